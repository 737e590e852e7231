// Merging load-test summaries: the clients of one run spread over threads (--threads) or over
// processes on several machines (--merge A.json B.json ...) add up to one summary. Counts are
// summed, extremes kept, and percentiles recomputed from the merged histograms, so they are the
// percentiles of every part's samples together, never averages of the parts' percentiles.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "load_summary.hpp"

namespace ocean::loadtest {

// Adds `part` into `total` (an empty LoadSummary{} with processes = 0 starts a merge) and
// finalizes it. Refuses (returns why, total unchanged) when the two ran different streams: another
// profile, transport, link, scenario or announced bandwidth.
std::string merge_into(LoadSummary& total, const LoadSummary& part);

// One summary as to_json wrote it (the --json line, with its "parts"); nullopt with `error` set
// when the text is not such a summary.
std::optional<LoadSummary> summary_from_json(const std::string& text, std::string& error);

// ocean-loadtest --merge: reads each file's last non-empty line as a summary and merges them all;
// nullopt with `error` naming the file that could not be read or merged.
std::optional<LoadSummary> merge_summary_files(std::span<const std::string> paths, std::string& error);

}  // namespace ocean::loadtest
