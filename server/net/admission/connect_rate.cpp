#include "connect_rate.hpp"

#include <algorithm>

namespace ocean::server {

ConnectRate::Range ConnectRate::range_of(const asio::ip::address& address) {
  Range range{};
  if (address.is_v4() || (address.is_v6() && address.to_v6().is_v4_mapped())) {
    const auto bytes = address.is_v4() ? address.to_v4().to_bytes()
                                       : asio::ip::make_address_v4(asio::ip::v4_mapped, address.to_v6()).to_bytes();
    range[0] = 4;
    std::copy_n(bytes.begin(), 3, range.begin() + 1);  // the /24
  } else {
    const auto bytes = address.to_v6().to_bytes();
    range[0] = 6;
    std::copy_n(bytes.begin(), 8, range.begin() + 1);  // the /64
  }
  return range;
}

bool ConnectRate::allow(const asio::ip::address& address, double now_s) {
  if (per_s_ <= 0.0) return true;
  const Range range = range_of(address);
  auto it = ranges_.find(range);
  if (it == ranges_.end()) {
    make_room(now_s);
    it = ranges_.emplace(range, Entry{TokenBucket(per_s_, burst_, now_s), now_s}).first;
  }
  it->second.last_s = now_s;
  return it->second.bucket.try_take(1, now_s);
}

// Ranges whose bucket has filled again are at rest: forgetting them changes nothing. If every
// range is busy, the table is full of churners, and the one heard from longest ago goes.
void ConnectRate::make_room(double now_s) {
  if (ranges_.size() < max_ranges_) return;
  const double refill_s = burst_ / per_s_;
  std::erase_if(ranges_, [&](const auto& entry) { return now_s - entry.second.last_s >= refill_s; });
  if (ranges_.size() < max_ranges_) return;
  ranges_.erase(std::min_element(ranges_.begin(), ranges_.end(), [](const auto& a, const auto& b) {
    return a.second.last_s < b.second.last_s;
  }));
}

}  // namespace ocean::server
