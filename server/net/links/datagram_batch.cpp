#include "datagram_batch.hpp"

#include <sys/socket.h>

#include <array>
#include <cerrno>

namespace ocean::server {

void DatagramBatch::add(SharedBytes bytes, const asio::ip::udp::endpoint& to, int fd) {
  pending_.push_back(Pending{std::move(bytes), to});
  if (pending_.size() >= kMaxBatch) flush(fd);
}

void DatagramBatch::flush(int fd) {
  std::size_t next = 0;
  while (next < pending_.size()) {
    std::array<mmsghdr, kMaxBatch> headers{};
    std::array<iovec, kMaxBatch> vectors{};
    const std::size_t count = std::min(kMaxBatch, pending_.size() - next);
    for (std::size_t i = 0; i < count; ++i) {
      Pending& p = pending_[next + i];
      vectors[i] = iovec{const_cast<std::uint8_t*>(p.bytes->data()), p.bytes->size()};
      headers[i].msg_hdr.msg_name = p.to.data();
      headers[i].msg_hdr.msg_namelen = static_cast<socklen_t>(p.to.size());
      headers[i].msg_hdr.msg_iov = &vectors[i];
      headers[i].msg_hdr.msg_iovlen = 1;
    }
    ++calls_;
    const int n = ::sendmmsg(fd, headers.data(), static_cast<unsigned>(count), MSG_DONTWAIT);
    if (n > 0) {
      sent_ += static_cast<std::uint64_t>(n);
      next += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      dropped_ += pending_.size() - next;  // the socket buffer is full: this burst is lost
      break;
    }
    ++dropped_;  // this one datagram was refused (e.g. an unreachable address); the rest may go
    ++next;
  }
  pending_.clear();
}

}  // namespace ocean::server
