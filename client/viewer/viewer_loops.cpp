// The headless and window loops shared by ocean-viewer and ocean-viewer-local.
#include "client/viewer/viewer_loops.hpp"

#include <chrono>
#include <cstdio>

#include <GLES2/gl2.h>
#include <sys/resource.h>

#include "client/render/camera_controls.hpp"
#include "client/render/framebuffer_readback.hpp"
#include "client/render/offscreen_target.hpp"
#include "client/viewer/app_window.hpp"
#include "client/viewer/fps_meter.hpp"
#include "client/viewer/viewer_exit.hpp"
#include "client/viewer/headless_context.hpp"
#include "client/viewer/png_file.hpp"

namespace ocean::viewer {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// CPU time of the whole process (all llvmpipe threads included), milliseconds. On a shared
// machine this says what a frame costs even when the wall clock says how busy the machine was.
double process_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec / 1e3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

// Frees the source's GL objects on every way out of a loop, while its context is still current
// (declared after the context, so destroyed before it).
class ReleaseGlOnExit {
 public:
  explicit ReleaseGlOnExit(FrameSource& source) : source_(source) {}
  ~ReleaseGlOnExit() { source_.scene().release_gl(); }
  ReleaseGlOnExit(const ReleaseGlOnExit&) = delete;
  ReleaseGlOnExit& operator=(const ReleaseGlOnExit&) = delete;

 private:
  FrameSource& source_;
};

// Times the loop: wall clock and process CPU from construction to finish().
struct LoopClock {
  Clock::time_point start = Clock::now();
  double cpu_start_ms = process_cpu_ms();

  void finish(int frames, LoopResult& result) const {
    result.frames = frames;
    result.seconds = seconds_since(start);
    result.process_cpu_ms = process_cpu_ms() - cpu_start_ms;
  }
};

}  // namespace

int run_headless_loop(FrameSource& source, const LoopSettings& s, LoopResult& result, std::string& error) {
  HeadlessContext context;
  if (!context.create(error)) {
    error = "headless GL context: " + error;
    return 1;
  }
  render::OffscreenTarget target;
  const ReleaseGlOnExit release(source);
  if (!source.init(error) || !target.create(s.width, s.height, error)) return 1;
  result.gl = context.description();
  source.start();
  if (!source.wait_for_first_frame(error)) {
    source.stop();
    return kExitNoServer;
  }
  ViewScene& scene = source.scene();
  const LoopClock clock;
  for (int i = 0; i < s.frames; ++i) {
    const double t = source.frame_time_s(i, seconds_since(clock.start));
    if (!source.update(t, error)) {
      source.stop();
      return 1;
    }
    target.bind();
    scene.draw(s.width, s.height, t);
    if (s.hud) {
      const double elapsed = seconds_since(clock.start);
      scene.hud.draw(source.hud_stats(elapsed > 0 ? (i + 1) / elapsed : 0.0), s.width, s.height);
    }
    glFinish();  // count the rasterisation in the frame time, as a swap would
  }
  clock.finish(s.frames, result);
  source.stop();
  if (!s.screenshot.empty()) {
    if (!write_png(s.screenshot, s.width, s.height, render::read_framebuffer_rgba(s.width, s.height), error)) return 1;
    result.screenshot_written = true;
  }
  return 0;
}

int run_window_loop(FrameSource& source, const LoopSettings& s, LoopResult& result, std::string& error) {
  AppWindow window;
  if (!window.open({s.width, s.height, s.program.c_str(), true}, error)) return 1;
  const ReleaseGlOnExit release(source);
  if (!source.init(error)) return 1;
  source.start();
  ViewScene& scene = source.scene();
  const LoopClock clock;
  auto last = clock.start;
  FpsMeter fps_meter;
  int frame = 0;
  while (!window.should_close() && (s.frames <= 0 || frame < s.frames)) {
    const auto now = Clock::now();
    const double dt = std::chrono::duration<double>(now - last).count();
    const double elapsed = std::chrono::duration<double>(now - clock.start).count();
    last = now;
    const double fps = fps_meter.tick(elapsed);
    render::apply_fly_input(scene.camera, window.poll(), dt);
    for (int presses = window.take_follow_presses(); presses > 0; --presses) source.cycle_follow();
    const double t = source.frame_time_s(frame, elapsed);
    if (!source.update(t, error)) {
      source.stop();
      return 1;
    }
    int w = 0, h = 0;
    window.framebuffer_size(w, h);
    scene.draw(w, h, t);
    if (window.hud_visible()) scene.hud.draw(source.hud_stats(fps), w, h);
    ++frame;
    if (!s.screenshot.empty() && s.frames > 0 && frame == s.frames) {
      if (write_png(s.screenshot, w, h, render::read_framebuffer_rgba(w, h), error))
        result.screenshot_written = true;
      else
        std::fprintf(stderr, "%s: %s\n", s.program.c_str(), error.c_str());
    }
    window.swap();
  }
  clock.finish(frame, result);
  source.stop();
  return 0;
}

}  // namespace ocean::viewer
