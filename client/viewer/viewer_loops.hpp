// The viewers' two frame loops over any FrameSource: headless (EGL, a fixed number of frames
// into an off-screen target, an optional screenshot) and the GLFW window (fly camera, HUD toggle,
// until closed or a frame count). Each returns the process exit code: 0, or 1 with the reason in
// error. The source's GL objects are released before the context goes.
#pragma once

#include <string>

#include "client/viewer/frame_source.hpp"

namespace ocean::viewer {

struct LoopSettings {
  std::string program;  // window title, and the prefix of what the window loop prints
  int width = 1280, height = 720;
  int frames = 0;          // headless: how many; window: 0 = until closed
  std::string screenshot;  // PNG of the last frame (window: only with frames > 0)
  bool hud = false;        // headless only; the window toggles it with H
};

struct LoopResult {
  int frames = 0;  // rendered
  double seconds = 0.0;
  double process_cpu_ms = 0.0;  // the whole process over the loop (all llvmpipe threads)
  bool screenshot_written = false;
  std::string gl;  // headless: EGL vendor and GL renderer
};

int run_headless_loop(FrameSource& source, const LoopSettings& settings, LoopResult& result, std::string& error);
int run_window_loop(FrameSource& source, const LoopSettings& settings, LoopResult& result, std::string& error);

}  // namespace ocean::viewer
