// run_until: runs an io_context in short slices until a condition holds or a deadline passes, so
// a test waits on its own loop's handlers instead of sleeping a guessed time.
#pragma once

#include <asio/io_context.hpp>

#include <chrono>

namespace ocean::test {

template <typename Done>
bool run_until(asio::io_context& io, Done done, double seconds = 5.0) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done() && std::chrono::steady_clock::now() < until) io.run_for(std::chrono::milliseconds(5));
  return done();
}

}  // namespace ocean::test
