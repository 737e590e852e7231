// The text format of the codec test vectors in tests/codec/vectors (CODEC.md section 12): one event
// per line, a kind word then name=value fields; bytes as lowercase hex. Shared by the generator
// (make_codec_vectors.cpp) and the check (test_codec_vectors.cpp).
#pragma once

#include "common/cascade.hpp"
#include "frame_reconstruction.hpp"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace ocean::codec::vectors {

// The sequences the generator writes and the check reads: <name>.txt and, but for
// desktop_cascaded (three frames of 82k samples would be 3 MB of floats), <name>.f32.
inline constexpr const char* kSequences[] = {"lite_modeled", "lite_explicit", "mobile_choppy", "desktop_cascaded"};

// The channels of a frame's float block, in order: height, slope_x, slope_z, then for choppy
// streams disp_x, disp_z, disp_xx, disp_zz, disp_xz and jacobian (non-choppy sequences stay as
// in the layout codec version 2 wrote), each grid^2 little-endian float32.
inline std::vector<std::pair<const char*, const std::vector<float>*>> frame_channels(const ReconstructedFrame& f,
                                                                                     bool choppy) {
  std::vector<std::pair<const char*, const std::vector<float>*>> channels = {
      {"height", &f.height}, {"slope_x", &f.slope_x}, {"slope_z", &f.slope_z}};
  if (choppy)
    channels.insert(channels.end(), {{"disp_x", &f.disp_x},
                                     {"disp_z", &f.disp_z},
                                     {"disp_xx", &f.disp_xx},
                                     {"disp_zz", &f.disp_zz},
                                     {"disp_xz", &f.disp_xz},
                                     {"jacobian", &f.jacobian}});
  return channels;
}

// Sample positions whose values every frame line repeats in decimal, for a quick look: these,
// and in a cascaded stream the same offsets into each further lattice's samples plus its last.
inline constexpr std::uint32_t kSamplePositions[] = {0, 517, 1023};

inline std::string hex(std::span<const std::uint8_t> bytes) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  out.reserve(2 * bytes.size());
  for (std::uint8_t b : bytes) {
    out.push_back(digits[b >> 4]);
    out.push_back(digits[b & 15]);
  }
  return out;
}

inline std::vector<std::uint8_t> unhex(std::string_view text) {
  auto nibble = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    throw std::invalid_argument("not a lowercase hex digit");
  };
  if (text.size() % 2 != 0) throw std::invalid_argument("odd number of hex digits");
  std::vector<std::uint8_t> out(text.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<std::uint8_t>(nibble(text[2 * i]) << 4 | nibble(text[2 * i + 1]));
  return out;
}

// The `cascades` field of a stream line: each cascade as patch_scale:grid:min_cycles:max_cycles,
// comma-separated; empty for a stream without cascades.
inline std::string cascades_text(const std::vector<Cascade>& cascades) {
  std::ostringstream out;
  for (std::size_t i = 0; i < cascades.size(); ++i)
    out << (i == 0 ? "" : ",") << cascades[i].patch_scale << ":" << cascades[i].grid << ":"
        << cascades[i].band.min_cycles << ":" << cascades[i].band.max_cycles;
  return out.str();
}

// FNV-1a 64 with the standard offset basis (0xcbf29ce484222325) and prime 0x100000001b3.
inline std::uint64_t fnv1a64(std::span<const std::uint8_t> bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::uint8_t b : bytes) {
    h ^= b;
    h *= 0x100000001b3ull;
  }
  return h;
}

inline std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// 17 significant digits: reads back as the same double in any language.
inline std::string text_of(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
// 9 significant digits: reads back as the same float32 when parsed as float32.
inline std::string text_of(float v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  return buf;
}

struct Line {
  int number = 0;
  std::string kind;
  std::map<std::string, std::string> fields;

  const std::string& at(const std::string& name) const {
    auto it = fields.find(name);
    if (it == fields.end()) throw std::invalid_argument("line " + std::to_string(number) + ": no field " + name);
    return it->second;
  }
  std::uint64_t u64(const std::string& name) const { return std::stoull(at(name)); }
  double f64(const std::string& name) const { return std::strtod(at(name).c_str(), nullptr); }
  float f32(const std::string& name) const { return std::strtof(at(name).c_str(), nullptr); }
};

inline std::vector<Line> parse_lines(std::istream& in) {
  std::vector<Line> lines;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (text.empty() || text[0] == '#') continue;
    std::istringstream words(text);
    Line line;
    line.number = number;
    words >> line.kind;
    std::string word;
    while (words >> word) {
      const auto eq = word.find('=');
      if (eq == std::string::npos) throw std::invalid_argument("line " + std::to_string(number) + ": " + word);
      line.fields[word.substr(0, eq)] = word.substr(eq + 1);
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

// Comma-separated values of a field (sample lists).
inline std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

}  // namespace ocean::codec::vectors
