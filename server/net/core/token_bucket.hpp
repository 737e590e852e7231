// TokenBucket: a session's downstream budget in bytes. Tokens accrue at the client's announced
// rate up to a small burst; a send takes its bytes. Time is an argument (seconds, any origin).
#pragma once

#include <algorithm>
#include <cstddef>

namespace ocean::server {

class TokenBucket {
 public:
  // bytes_per_s 0 = unlimited.
  TokenBucket(double bytes_per_s, double burst_bytes, double now_s)
      : rate_(bytes_per_s), burst_(burst_bytes), tokens_(burst_bytes), last_s_(now_s) {}

  bool unlimited() const { return rate_ <= 0.0; }
  double rate() const { return rate_; }

  void refill(double now_s) {
    if (now_s > last_s_) tokens_ = std::min(burst_, tokens_ + (now_s - last_s_) * rate_);
    last_s_ = std::max(last_s_, now_s);
  }
  double burst() const { return burst_; }

  // Takes `bytes` if that many tokens are there; else takes nothing.
  bool try_take(std::size_t bytes, double now_s) { return try_take_leaving(static_cast<double>(bytes), 0.0, now_s); }
  // Takes `amount` only if `reserve` tokens are left after it (work that can wait leaves room
  // for work that cannot); else takes nothing.
  bool try_take_leaving(double amount, double reserve, double now_s) {
    if (unlimited()) return true;
    refill(now_s);
    if (tokens_ < amount + reserve) return false;
    tokens_ -= amount;
    return true;
  }
  // Seconds until `bytes` tokens are there (0 when they are now); bytes above the burst wait for
  // the burst (a caller paces a large message as soon as the bucket is full).
  double wait_s(std::size_t bytes, double now_s) {
    if (unlimited()) return 0.0;
    refill(now_s);
    const double need = std::min(static_cast<double>(bytes), burst_) - tokens_;
    return need <= 0.0 ? 0.0 : need / rate_;
  }
  // Takes `bytes` regardless, possibly going below zero (a message larger than the burst).
  void take(std::size_t bytes, double now_s) {
    if (unlimited()) return;
    refill(now_s);
    tokens_ -= static_cast<double>(bytes);
  }

 private:
  double rate_;
  double burst_;
  double tokens_;
  double last_s_;
};

}  // namespace ocean::server
