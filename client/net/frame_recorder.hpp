// FrameRecorder: --record FILE.npy (viewer, load test) - reconstructed heights (frames x grid x grid
// float32, NpyWriter) and, beside them in FILE.ticks.npy, the tick of every recorded frame
// (int64, one per frame), so a recording can be compared with the sim tick by tick.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <string>

#include "npy_writer.hpp"

namespace ocean::client {

// A 1-D int64 NPY v1.0 file, appended to as it goes, its length patched into the header on close.
class TickNpyWriter {
 public:
  explicit TickNpyWriter(const std::string& path);  // throws std::runtime_error naming the path
  ~TickNpyWriter();
  TickNpyWriter(const TickNpyWriter&) = delete;
  TickNpyWriter& operator=(const TickNpyWriter&) = delete;
  void append(std::int64_t value);
  void close();
  std::uint64_t size() const { return count_; }

 private:
  void write_header();
  std::string path_;
  std::uint64_t count_ = 0;
  std::FILE* file_ = nullptr;
};

// "run.npy" -> "run.ticks.npy"; a path without ".npy" gets ".ticks.npy" appended.
std::string ticks_path_for(const std::string& heights_path);

class FrameRecorder {
 public:
  explicit FrameRecorder(std::string heights_path) : path_(std::move(heights_path)) {}
  // Opens both files on the first frame (the grid is known then); throws std::runtime_error.
  void append(std::int64_t tick, int grid, std::span<const float> heights);
  void close();

 private:
  std::string path_;
  std::optional<NpyWriter> heights_;
  std::optional<TickNpyWriter> ticks_;
};

}  // namespace ocean::client
