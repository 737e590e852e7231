// The framer's state machine: prefix (4 bytes) -> limit checks -> body -> good.
#include "tcp_framer.hpp"

#include <algorithm>

#include "ocean_generated.h"

namespace ocean::protocol {

TcpFramer::TcpFramer(std::size_t max_message_bytes) : max_message_bytes_(max_message_bytes) {}

void TcpFramer::set_max_message_bytes(std::size_t max_message_bytes) {
  max_message_bytes_ = max_message_bytes;
}

std::size_t TcpFramer::buffered_bytes() const { return complete_ ? 0 : buffer_.size(); }

std::span<const std::uint8_t> TcpFramer::message() const {
  return complete_ ? std::span<const std::uint8_t>(buffer_) : std::span<const std::uint8_t>();
}

void TcpFramer::reset() {
  buffer_.clear();
  expected_ = 0;
  complete_ = false;
  failure_ = Reason::ok;
}

TcpFramer::Result TcpFramer::feed(std::span<const std::uint8_t> bytes) {
  if (failure_ != Reason::ok) return Result{Status::bad, failure_, 0};
  if (complete_) {
    buffer_.clear();
    expected_ = 0;
    complete_ = false;
  }
  std::size_t consumed = 0;
  auto take = [&](std::size_t wanted) {
    const std::size_t n = std::min(wanted, bytes.size() - consumed);
    buffer_.insert(buffer_.end(), bytes.begin() + consumed, bytes.begin() + consumed + n);
    consumed += n;
  };

  if (expected_ == 0) {
    take(kSizePrefixBytes - buffer_.size());
    if (buffer_.size() < kSizePrefixBytes) return Result{Status::need_more, Reason::ok, consumed};
    const std::size_t body = flatbuffers::ReadScalar<std::uint32_t>(buffer_.data());
    const std::size_t whole = kSizePrefixBytes + body;
    if (body == 0) failure_ = Reason::empty;
    else if (whole > max_message_bytes_) failure_ = Reason::oversized;
    else if (whole < kMinMessageBytes) failure_ = Reason::truncated;
    if (failure_ != Reason::ok) return Result{Status::bad, failure_, consumed};
    expected_ = whole;
    buffer_.reserve(whole);
  }

  take(expected_ - buffer_.size());
  if (buffer_.size() < expected_) return Result{Status::need_more, Reason::ok, consumed};
  complete_ = true;
  return Result{Status::good, Reason::ok, consumed};
}

}  // namespace ocean::protocol
