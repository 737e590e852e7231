// The LoadSummary fields by how a merge treats them, in one table each, so the JSON writer, the
// JSON reader and the merge cannot disagree about a field.
#pragma once

#include <cstdint>
#include <string_view>

#include "load_summary.hpp"

namespace ocean::loadtest {

template <typename T>
struct SummaryField {
  std::string_view name;
  T LoadSummary::*member;
};

// Summed.
inline constexpr SummaryField<std::uint64_t> kSummedCounts[] = {
    {"frames_expected", &LoadSummary::frames_expected},
    {"frames_expected_welcomed", &LoadSummary::frames_expected_welcomed},
    {"frames_received", &LoadSummary::frames_received},
    {"frames_ok", &LoadSummary::frames_ok},
    {"frames_late", &LoadSummary::frames_late},
    {"frames_lost", &LoadSummary::frames_lost},
    {"frames_bad", &LoadSummary::frames_bad},
    {"stalls", &LoadSummary::stalls},
    {"keyframes", &LoadSummary::keyframes},
    {"reconnects", &LoadSummary::reconnects},
    {"truth_evaluations", &LoadSummary::truth_evaluations},
    {"decodes_run", &LoadSummary::decodes_run},
    {"decodes_shared", &LoadSummary::decodes_shared},
    {"truth_checks", &LoadSummary::truth_checks},
    {"keyframe_requests", &LoadSummary::keyframe_requests},
    {"chunks_rejected_by_codec", &LoadSummary::chunks_rejected_by_codec},
    {"messages_rejected", &LoadSummary::messages_rejected},
    {"transport_fallbacks", &LoadSummary::transport_fallbacks},
    {"frames_recovered", &LoadSummary::frames_recovered},
};
inline constexpr SummaryField<int> kSummedInts[] = {
    {"clients", &LoadSummary::clients},
    {"clients_connected", &LoadSummary::clients_connected},
    {"clients_welcomed", &LoadSummary::clients_welcomed},
    {"threads", &LoadSummary::threads},
    {"processes", &LoadSummary::processes},
};
// Each process's own CPU adds up to what the load generation cost.
inline constexpr SummaryField<double> kSummedDoubles[] = {
    {"loadtest_cpu_pct", &LoadSummary::loadtest_cpu_pct},
};
// The largest of the parts: extremes, the longest run, the most scenes any part saw.
inline constexpr SummaryField<double> kLargestDoubles[] = {
    {"max_err_m", &LoadSummary::max_err_m},
    {"interpolation_delay_max_ms", &LoadSummary::interpolation_delay_max_ms},
    {"duration_s", &LoadSummary::duration_s},
};
// What the run was: every part must agree, or the merge is refused.
inline constexpr SummaryField<double> kSameDoubles[] = {
    {"error_bound_m", &LoadSummary::error_bound_m},
    {"interpolation_delay_ms", &LoadSummary::interpolation_delay_ms},
};
// Counts by name, summed name by name.
inline constexpr SummaryField<std::map<std::string, std::uint64_t>> kSummedMaps[] = {
    {"codec_rejections", &LoadSummary::codec_rejections},
    {"refusals", &LoadSummary::refusals},
    {"not_welcomed", &LoadSummary::not_welcomed},
};
inline constexpr SummaryField<std::string> kSameTexts[] = {
    {"profile", &LoadSummary::profile},
    {"transport", &LoadSummary::transport},
    {"link", &LoadSummary::link},
    {"scenario", &LoadSummary::scenario},
};

}  // namespace ocean::loadtest
