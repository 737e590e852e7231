// NPY v1.0: magic, version 1.0, uint16 header length, a Python dict literal padded with spaces
// and ending in '\n' so that magic + length + header is a multiple of 64 bytes.
#include "npy_writer.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace ocean {

NpyWriter::NpyWriter(const std::string& path, int rows, int cols) : path_(path), rows_(rows), cols_(cols) {
  if (rows <= 0 || cols <= 0) throw std::runtime_error("NpyWriter: rows and cols must be positive for " + path);
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) throw std::runtime_error("NpyWriter: cannot open " + path + " for writing");
  write_header();
}

NpyWriter::~NpyWriter() {
  try {
    close();
  } catch (...) {
  }
}

void write_npy_header(std::FILE* file, const std::string& path, const char* descr, const std::string& shape) {
  constexpr std::size_t kHeaderBytes = NpyWriter::kHeaderBytes;
  char dict[kHeaderBytes];
  const int len = std::snprintf(dict, sizeof dict, "{'descr': '%s', 'fortran_order': False, 'shape': %s, }", descr,
                                shape.c_str());
  const std::size_t dict_room = kHeaderBytes - 10;  // magic(6) + version(2) + length(2)
  if (len < 0 || static_cast<std::size_t>(len) + 1 > dict_room) throw std::runtime_error("NPY header too long for " + path);
  std::vector<char> h(kHeaderBytes, ' ');
  const char magic[] = "\x93NUMPY";
  std::memcpy(h.data(), magic, 6);
  h[6] = 1;
  h[7] = 0;
  h[8] = static_cast<char>(dict_room & 0xFF);
  h[9] = static_cast<char>(dict_room >> 8);
  std::memcpy(h.data() + 10, dict, static_cast<std::size_t>(len));
  h[kHeaderBytes - 1] = '\n';
  if (std::fseek(file, 0, SEEK_SET) != 0 || std::fwrite(h.data(), 1, h.size(), file) != h.size())
    throw std::runtime_error("cannot write the NPY header of " + path);
}

void NpyWriter::write_header() {
  // Appended piecewise: g++ 12 warns falsely (-Wrestrict) on "(" + std::string once inlined.
  std::string shape = "(";
  shape += std::to_string(frames_) + ", " + std::to_string(rows_) + ", " + std::to_string(cols_) + ")";
  write_npy_header(file_, path_, "<f4", shape);
}

void NpyWriter::append(std::span<const float> frame) {
  if (!file_) throw std::runtime_error("NpyWriter: " + path_ + " is closed");
  if (frame.size() != static_cast<std::size_t>(rows_) * cols_)
    throw std::runtime_error("NpyWriter: frame has " + std::to_string(frame.size()) + " values, " + path_ +
                             " records " + std::to_string(rows_) + " x " + std::to_string(cols_));
  if (std::fseek(file_, 0, SEEK_END) != 0) throw std::runtime_error("NpyWriter: cannot seek in " + path_);
  if constexpr (std::endian::native == std::endian::little) {
    if (std::fwrite(frame.data(), sizeof(float), frame.size(), file_) != frame.size())
      throw std::runtime_error("NpyWriter: write failed on " + path_);
  } else {
    std::vector<std::uint8_t> le(frame.size() * 4);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const auto u = std::bit_cast<std::uint32_t>(frame[i]);
      for (int b = 0; b < 4; ++b) le[4 * i + b] = static_cast<std::uint8_t>(u >> (8 * b));
    }
    if (std::fwrite(le.data(), 1, le.size(), file_) != le.size())
      throw std::runtime_error("NpyWriter: write failed on " + path_);
  }
  ++frames_;
}

void NpyWriter::close() {
  if (!file_) return;
  std::FILE* f = file_;
  write_header();
  file_ = nullptr;
  if (std::fclose(f) != 0) throw std::runtime_error("NpyWriter: closing " + path_ + " failed");
}

void write_npy(const std::string& path, int rows, int cols, std::span<const float> frames) {
  NpyWriter w(path, rows, cols);
  const std::size_t per = static_cast<std::size_t>(rows) * cols;
  for (std::size_t i = 0; i + per <= frames.size(); i += per) w.append(frames.subspan(i, per));
  w.close();
}

}  // namespace ocean
