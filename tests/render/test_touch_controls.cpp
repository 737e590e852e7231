// The web viewer's touch gestures: one finger looks, two fingers move, a finger added or lifted
// never jumps the view.
#include "client/render/touch_controls.hpp"

#include <catch2/catch.hpp>

#include <vector>

using namespace ocean::render;

TEST_CASE("one finger drags the view like the mouse, and a new finger starts a new gesture") {
  TouchGesture g;
  Camera c;
  c.position = {0.0, 10.0, 0.0};
  CHECK(g.update(std::vector<TouchPoint>{{7, 100, 100}}).look_dx_px == 0.0);  // touch down: nothing yet
  const TouchMotion m = g.update(std::vector<TouchPoint>{{7, 160, 90}});
  CHECK(m.look_dx_px == 60.0);
  CHECK(m.look_dy_px == -10.0);
  apply_touch_motion(c, m);
  CHECK(c.forward().x > 0.0f);  // dragged right: turned right, as with the mouse
  CHECK(c.position.x == 0.0);   // one finger does not move the eye
  // Lifted and put down elsewhere (a new id): no jump from the old position.
  g.update({});
  g.update(std::vector<TouchPoint>{{8, 900, 500}});
  const TouchMotion again = g.update(std::vector<TouchPoint>{{8, 905, 500}});
  CHECK(again.look_dx_px == 5.0);
}

TEST_CASE("spreading two fingers moves forward over the water, pinching moves back, dragging slides") {
  TouchGesture g;
  Camera c;
  c.position = {0.0, 10.0, 0.0};
  c.pitch_rad = -0.5f;  // looking down at the water: forward still moves level
  g.update(std::vector<TouchPoint>{{1, 100, 300}});
  CHECK(g.update(std::vector<TouchPoint>{{1, 100, 300}, {2, 200, 300}}).forward_m == 0.0);  // second finger down
  const TouchMotion spread = g.update(std::vector<TouchPoint>{{1, 50, 300}, {2, 250, 300}}, TouchSettings{0.5, 0.25});
  CHECK(spread.forward_m == Approx(50.0));  // 100 px wider at 0.5 m/px; the midpoint stayed
  CHECK(spread.right_m == Approx(0.0));
  CHECK(spread.look_dx_px == 0.0);
  apply_touch_motion(c, spread);
  CHECK(c.position.z == Approx(-50.0));  // yaw 0 looks along -z
  CHECK(c.position.y == Approx(10.0));
  const TouchMotion pinch = g.update(std::vector<TouchPoint>{{1, 100, 300}, {2, 200, 300}}, TouchSettings{0.5, 0.25});
  CHECK(pinch.forward_m == Approx(-50.0));
  const TouchMotion slide = g.update(std::vector<TouchPoint>{{1, 140, 300}, {2, 240, 300}}, TouchSettings{0.5, 0.25});
  CHECK(slide.right_m == Approx(-10.0));  // both fingers 40 px right: the water moves right, the eye left
  apply_touch_motion(c, slide);
  CHECK(c.position.x == Approx(-10.0));
}

TEST_CASE("two quick taps in one place are a double tap; a drag, a slow press or a pinch is not") {
  using ocean::render::DoubleTap;
  using ocean::render::TouchPoint;
  const std::vector<TouchPoint> none, finger{{1, 100.0, 200.0}}, moved{{1, 160.0, 200.0}};
  const std::vector<TouchPoint> two{{1, 100.0, 200.0}, {2, 300.0, 200.0}};
  const auto tap = [&](DoubleTap& d, double at, const std::vector<TouchPoint>& where) {
    d.update(where, at);
    return d.update(none, at + 0.1);
  };
  DoubleTap d;
  CHECK(!tap(d, 1.0, finger));
  CHECK(tap(d, 1.3, finger));   // the second tap 0.3 s later
  CHECK(!tap(d, 1.6, finger));  // a third starts a new pair
  CHECK(!tap(d, 3.0, finger));
  CHECK(!tap(d, 3.9, finger));  // too long after the first
  DoubleTap slow;
  CHECK(!tap(slow, 1.0, finger));
  slow.update(finger, 1.3);
  CHECK(!slow.update(none, 1.8));  // held half a second: a press, not a tap
  DoubleTap drag;
  CHECK(!tap(drag, 1.0, finger));
  drag.update(finger, 1.2);
  drag.update(moved, 1.25);
  CHECK(!drag.update(none, 1.3));  // the finger moved 60 px: it turned the view
  DoubleTap pinch;
  CHECK(!tap(pinch, 1.0, finger));
  pinch.update(two, 1.2);
  pinch.update(finger, 1.25);
  CHECK(!pinch.update(none, 1.3));
}
