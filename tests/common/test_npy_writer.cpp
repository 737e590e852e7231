// NPY recording: the header numpy expects, patched frame count, and (when python3 with numpy is
// installed) numpy.load reading back exactly what was written.
#include "npy_writer.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace ocean;

TEST_CASE("NpyWriter writes a v1.0 header with the final shape and the data after it") {
  const auto dir = std::filesystem::temp_directory_path() / ("ocean_npy_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "frames.npy").string();
  const int rows = 3, cols = 5, frames = 7;
  {
    NpyWriter w(path, rows, cols);
    for (int f = 0; f < frames; ++f) {
      std::vector<float> v(rows * cols);
      for (int i = 0; i < rows * cols; ++i) v[i] = f * 100.0f + i + 0.25f;
      w.append(v);
    }
    CHECK(w.frames() == frames);
    CHECK_THROWS(w.append(std::vector<float>(4)));
    w.close();
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() == NpyWriter::kHeaderBytes + std::size_t(frames) * rows * cols * 4);
  CHECK(bytes.compare(0, 6, "\x93NUMPY") == 0);
  CHECK(bytes[6] == 1);
  CHECK(bytes[7] == 0);
  const std::size_t hlen = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
  CHECK((10 + hlen) % 64 == 0);
  const std::string header = bytes.substr(10, hlen);
  CHECK(header.find("'shape': (7, 3, 5)") != std::string::npos);
  CHECK(header.find("'descr': '<f4'") != std::string::npos);
  CHECK(header.back() == '\n');
  float first;
  std::memcpy(&first, bytes.data() + NpyWriter::kHeaderBytes, 4);
  CHECK(first == 0.25f);

  if (std::system("/usr/bin/python3 -c 'import numpy' >/dev/null 2>&1") == 0) {
    const std::string cmd = "/usr/bin/python3 -c \"import numpy as np; a = np.load('" + path +
                            "'); assert a.shape == (7, 3, 5) and a.dtype == np.float32; "
                            "assert float(a[6, 2, 4]) == 6 * 100 + 14 + 0.25; assert float(a[0, 0, 0]) == 0.25\"";
    CHECK(std::system(cmd.c_str()) == 0);
  } else {
    WARN("python3 with numpy not found: numpy.load check skipped");
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("NpyWriter names the path when it cannot open it") {
  try {
    NpyWriter w("/nonexistent-dir/x.npy", 2, 2);
    FAIL("expected an exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("/nonexistent-dir/x.npy") != std::string::npos);
  }
}
