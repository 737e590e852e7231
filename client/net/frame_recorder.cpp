// The tick file has NpyWriter's layout: a fixed 128-byte header, so the length can be patched.
#include "frame_recorder.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace ocean::client {
TickNpyWriter::TickNpyWriter(const std::string& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot open " + path + " for writing");
  write_header();
}

TickNpyWriter::~TickNpyWriter() {
  try {
    close();
  } catch (...) {
  }
}

void TickNpyWriter::write_header() { write_npy_header(file_, path_, "<i8", "(" + std::to_string(count_) + ",)"); }

void TickNpyWriter::append(std::int64_t value) {
  if (!file_) throw std::runtime_error(path_ + " is closed");
  std::uint8_t le[8];
  const auto u = std::bit_cast<std::uint64_t>(value);
  for (int b = 0; b < 8; ++b) le[b] = static_cast<std::uint8_t>(u >> (8 * b));
  if (std::fseek(file_, 0, SEEK_END) != 0 || std::fwrite(le, 1, 8, file_) != 8)
    throw std::runtime_error("write failed on " + path_);
  ++count_;
}

void TickNpyWriter::close() {
  if (!file_) return;
  std::FILE* f = file_;
  write_header();
  file_ = nullptr;
  if (std::fclose(f) != 0) throw std::runtime_error("closing " + path_ + " failed");
}

std::string ticks_path_for(const std::string& heights_path) {
  const std::string ext = ".npy";
  if (heights_path.size() > ext.size() && heights_path.compare(heights_path.size() - ext.size(), ext.size(), ext) == 0)
    return heights_path.substr(0, heights_path.size() - ext.size()) + ".ticks.npy";
  return heights_path + ".ticks.npy";
}

void FrameRecorder::append(std::int64_t tick, int grid, std::span<const float> heights) {
  if (!heights_) {
    heights_.emplace(path_, grid, grid);
    ticks_.emplace(ticks_path_for(path_));
  }
  heights_->append(heights);
  ticks_->append(tick);
}

void FrameRecorder::close() {
  if (heights_) heights_->close();
  if (ticks_) ticks_->close();
}

}  // namespace ocean::client
