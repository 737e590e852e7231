#include "tick_loop.hpp"

#include <asio/post.hpp>

#include <chrono>

namespace ocean::server {

std::int64_t system_unix_ns() {
  using namespace std::chrono;
  return duration_cast<nanoseconds>(system_clock::now().time_since_epoch()).count();
}

TickLoop::TickLoop(TickClock clock, TickHandler on_tick, WallClock now)
    : clock_(clock), on_tick_(std::move(on_tick)), now_(std::move(now)), timer_(context_) {}

TickLoop::~TickLoop() { stop(); }

void TickLoop::start() {
  if (thread_.joinable()) return;
  asio::post(context_, [this] { on_timer({}); });
  thread_ = std::thread([this] { context_.run(); });
}

void TickLoop::stop() {
  context_.stop();  // a tick in progress completes; no further handler runs
  if (thread_.joinable() && thread_.get_id() != std::this_thread::get_id()) thread_.join();
}

void TickLoop::do_wait() {
  // The wall-clock deadline becomes a steady-clock wait each time, tracking any clock adjustment.
  const std::int64_t next = last_tick_ ? *last_tick_ + 1 : clock_.tick_at(now_());
  const std::int64_t wait_ns = clock_.deadline_ns(next) - now_();
  timer_.expires_after(std::chrono::nanoseconds(wait_ns > 0 ? wait_ns : 0));
  timer_.async_wait([this](std::error_code error) { on_timer(error); });
}

void TickLoop::on_timer(std::error_code error) {
  if (error) return;  // cancelled: stopping
  if (const std::optional<TickDecision> decision = clock_.decide(now_(), last_tick_)) {
    last_tick_ = decision->tick;
    on_tick_(*decision);
  }
  do_wait();
}

}  // namespace ocean::server
