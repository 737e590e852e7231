// FrameRecorder: --record FILE.npy (viewer, load test) - everything a client decoded, frame by
// frame, so a recording can be compared with the sim tick by tick or measured offline (CODEC.md
// section 10 is the format): FILE.npy the first lattice's heights (frames x grid x grid float32),
// FILE.ticks.npy each frame's tick and FILE.baselines.npy the tick of the state it was decoded
// from (a key's own tick) (int64), FILE.lattices.npy the stream's lattice sizes (int64), and
// FILE.<channel>.npy every channel the stream carries over all its lattices (frames x 1 x samples
// float32, the lattices one after the other, each row-major z * n + x).
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <string>

#include "frame_reconstruction.hpp"
#include "message_types.hpp"
#include "npy_writer.hpp"

#include <memory>
#include <vector>

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

// The lattice sizes of a stream's frames in order: its cascades' grids, or its one grid.
std::vector<int> stream_lattices(const protocol::StreamParams& stream);

class FrameRecorder {
 public:
  explicit FrameRecorder(std::string heights_path);
  ~FrameRecorder();
  // Opens the files on the first frame (its layout is the recording's); false, writing nothing,
  // for a frame of another layout (a new stream after a reconnection). Throws std::runtime_error.
  bool append(std::int64_t tick, std::span<const int> lattices, const codec::ReconstructedFrame& frame);
  void close();

 private:
  struct Channel;
  void open(std::span<const int> lattices, const codec::ReconstructedFrame& frame);

  std::string path_;
  std::vector<int> lattices_;
  std::optional<NpyWriter> heights_;
  std::optional<TickNpyWriter> ticks_, baselines_;
  std::vector<std::unique_ptr<Channel>> channels_;
};

}  // namespace ocean::client
