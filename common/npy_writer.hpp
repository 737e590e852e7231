// NpyWriter: records frames as a float32 array (frames x rows x cols) in NPY v1.0, appending as
// it goes and patching the frame count into the header on close, so numpy.load reads long runs.
#pragma once

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace ocean {

class NpyWriter {
 public:
  NpyWriter(const std::string& path, int rows, int cols);  // throws std::runtime_error naming the path
  ~NpyWriter();  // closes (errors on this path are swallowed: call close() to see them)
  NpyWriter(const NpyWriter&) = delete;
  NpyWriter& operator=(const NpyWriter&) = delete;

  void append(std::span<const float> frame);  // rows * cols values, row-major
  void close();                               // rewrites the header with the final shape
  std::uint64_t frames() const { return frames_; }
  int cols() const { return cols_; }

  static constexpr std::size_t kHeaderBytes = 128;  // fixed, so the shape can be patched in place

 private:
  void write_header();
  std::string path_;
  int rows_, cols_;
  std::uint64_t frames_ = 0;
  std::FILE* file_ = nullptr;
};

// Writes (or rewrites, at offset 0) the fixed-size NPY v1.0 header of an array of `descr` (e.g.
// "<f4", "<i8") and `shape` (e.g. "(12, 64, 64)"); throws std::runtime_error naming the path.
void write_npy_header(std::FILE* file, const std::string& path, const char* descr, const std::string& shape);

// Writes a whole recording at once: frames.size() / (rows * cols) frames.
void write_npy(const std::string& path, int rows, int cols, std::span<const float> frames);

}  // namespace ocean
