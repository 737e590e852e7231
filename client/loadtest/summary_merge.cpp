#include "summary_merge.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "json_value.hpp"
#include "summary_fields.hpp"

namespace ocean::loadtest {
namespace {

std::string differs(std::string_view field, const std::string& a, const std::string& b) {
  return "the summaries ran different streams: " + std::string(field) + " '" + a + "' and '" + b + "'";
}

std::string check_same_run(const LoadSummary& total, const LoadSummary& part) {
  if (total.processes == 0) return {};
  for (const auto& f : kSameTexts)
    if (total.*f.member != part.*f.member) return differs(f.name, total.*f.member, part.*f.member);
  if (total.bandwidth_bps != part.bandwidth_bps)
    return differs("bandwidth_bps", std::to_string(total.bandwidth_bps), std::to_string(part.bandwidth_bps));
  return {};
}

}  // namespace

std::string merge_into(LoadSummary& total, const LoadSummary& part) {
  if (std::string why = check_same_run(total, part); !why.empty()) return why;
  if (total.processes == 0) {
    for (const auto& f : kSameTexts) total.*f.member = part.*f.member;
    total.bandwidth_bps = part.bandwidth_bps;
    total.threads = 0;
  }
  for (const auto& f : kSummedCounts) total.*f.member += part.*f.member;
  for (const auto& f : kSummedInts) total.*f.member += part.*f.member;
  for (const auto& f : kSummedDoubles) total.*f.member += part.*f.member;
  for (const auto& f : kLargestDoubles) total.*f.member = std::max(total.*f.member, part.*f.member);
  // A part whose clients never got a Welcome knows no bound (0): the others' stands.
  for (const auto& f : kSameDoubles)
    if (part.*f.member != 0.0) total.*f.member = part.*f.member;
  for (const auto& f : kSummedMaps)
    for (const auto& [name, n] : part.*f.member) (total.*f.member)[name] += n;
  total.scenes = std::max(total.scenes, part.scenes);
  // Every part measured the same server over (nearly) the same time: the largest reading stands.
  if (part.server_cpu_pct) total.server_cpu_pct = std::max(total.server_cpu_pct.value_or(0.0), *part.server_cpu_pct);
  total.latency_s.merge(part.latency_s);
  total.connection.merge(part.connection);
  total.bytes_received += part.bytes_received;
  total.udp_datagrams += part.udp_datagrams;
  total.client_seconds += part.client_seconds;
  finalize(total);
  return {};
}

namespace {

bool read_histogram(const JsonValue* j, SparseHistogram& out, std::string& error) {
  const JsonValue* bin = j ? j->find("bin") : nullptr;
  const JsonValue* max = j ? j->find("max") : nullptr;
  const JsonValue* bins = j ? j->find("bins") : nullptr;
  if (!bin || !max || !bins || bins->kind != JsonValue::Kind::array) return error = "a histogram needs bin, max and bins", false;
  if (bin->number != out.bin_width()) return error = "histogram bin width " + bin->text + " is not this version's", false;
  for (const JsonValue& pair : bins->items) {
    const auto index = pair.items.size() == 2 ? pair.items[0].as_uint() : std::nullopt;
    const auto count = pair.items.size() == 2 ? pair.items[1].as_uint() : std::nullopt;
    if (!index || !count) return error = "a histogram bin is not [index, count]", false;
    out.add_bin(*index, *count);
  }
  out.note_max(max->number);
  return true;
}

bool read_parts(const JsonValue& j, LoadSummary& s, std::string& error) {
  const JsonValue* parts = j.find("parts");
  if (!parts) return error = "no \"parts\" (written by an ocean-loadtest without --merge support?)", false;
  if (!read_histogram(parts->find("latency_s"), s.latency_s, error) ||
      !read_histogram(parts->find("ttff_s"), s.connection.ttff_s, error) ||
      !read_histogram(parts->find("peak_kbps"), s.connection.peak_kbps, error) ||
      !read_histogram(parts->find("calm_kbps"), s.connection.calm_kbps, error))
    return false;
  const JsonValue* startup = parts->find("startup_peak_kbps");
  const JsonValue* without = parts->find("clients_without_frame");
  const JsonValue* bytes = parts->find("bytes_received");
  const JsonValue* datagrams = parts->find("udp_datagrams");
  const JsonValue* seconds = parts->find("client_seconds");
  if (!startup || !without || !bytes || !datagrams || !seconds || !bytes->as_uint() || !datagrams->as_uint())
    return error = "\"parts\" lacks a traffic or connection count", false;
  s.connection.startup_peak_kbps = startup->number;
  s.connection.clients_without_frame = static_cast<int>(without->number);
  s.bytes_received = *bytes->as_uint();
  s.udp_datagrams = *datagrams->as_uint();
  s.client_seconds = seconds->number;
  return true;
}

bool read_fields(const JsonValue& j, LoadSummary& s, std::string& error) {
  auto missing = [&](std::string_view name) { return error = "no \"" + std::string(name) + "\"", false; };
  for (const auto& f : kSummedCounts) {
    const JsonValue* v = j.find(std::string(f.name));
    if (!v || !v->as_uint()) return missing(f.name);
    s.*f.member = *v->as_uint();
  }
  auto read_number = [&](std::string_view name, auto& member) {
    const JsonValue* v = j.find(std::string(name));
    if (!v || v->kind != JsonValue::Kind::number) return false;
    member = static_cast<std::remove_reference_t<decltype(member)>>(v->number);
    return true;
  };
  for (const auto& f : kSummedInts)
    if (!read_number(f.name, s.*f.member)) return missing(f.name);
  using Doubles = std::span<const SummaryField<double>>;
  for (const Doubles group : {Doubles(kSummedDoubles), Doubles(kLargestDoubles), Doubles(kSameDoubles)})
    for (const auto& f : group)
      if (!read_number(f.name, s.*f.member)) return missing(f.name);
  for (const auto& f : kSameTexts) {
    const JsonValue* v = j.find(std::string(f.name));
    if (!v || v->kind != JsonValue::Kind::string) return missing(f.name);
    s.*f.member = v->text;
  }
  if (!read_number("scenes", s.scenes) || !read_number("bandwidth_bps", s.bandwidth_bps)) return missing("scenes or bandwidth_bps");
  if (const JsonValue* cpu = j.find("server_cpu_pct"); cpu && cpu->kind == JsonValue::Kind::number) s.server_cpu_pct = cpu->number;
  for (const auto& f : kSummedMaps)
    if (const JsonValue* counts = j.find(std::string(f.name)))
      for (const auto& [name, n] : counts->fields) (s.*f.member)[name] = n.as_uint().value_or(0);
  return true;
}

}  // namespace

std::optional<LoadSummary> summary_from_json(const std::string& text, std::string& error) {
  const std::optional<JsonValue> j = parse_json(text, error);
  if (!j) return std::nullopt;
  if (j->kind != JsonValue::Kind::object) return error = "not a JSON object", std::nullopt;
  LoadSummary s;
  if (!read_fields(*j, s, error) || !read_parts(*j, s, error)) return std::nullopt;
  finalize(s);
  return s;
}

std::optional<LoadSummary> merge_summary_files(std::span<const std::string> paths, std::string& error) {
  LoadSummary total;
  total.processes = 0;
  for (const std::string& path : paths) {
    std::ifstream in(path);
    if (!in) return error = path + ": cannot be read", std::nullopt;
    // The summary is the last line a --json run printed; progress or a table may come before it.
    std::string line, last;
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    std::string why;
    const std::optional<LoadSummary> part = summary_from_json(last, why);
    if (!part) return error = path + ": not an ocean-loadtest --json summary: " + why, std::nullopt;
    if (why = merge_into(total, *part); !why.empty()) return error = path + ": " + why, std::nullopt;
  }
  return total;
}

}  // namespace ocean::loadtest
