#include "datagram_port.hpp"

#include <netinet/in.h>
#include <sys/epoll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <system_error>

namespace ocean::server {

namespace {

// Don't fragment, and don't learn path MTUs either (what QUIC stacks do): every datagram is at
// most protocol::kMaxDatagram, below any path's MTU, and with the DF bit set the kernel gives it
// IP id 0 instead of drawing one from its shared, hashed id generator for each send (1.7 % of the
// server's time at 1000 viewers). A socket of the other family refuses the option it lacks.
void set_no_fragments(int fd) {
  const int probe = IP_PMTUDISC_PROBE;
  ::setsockopt(fd, IPPROTO_IP, IP_MTU_DISCOVER, &probe, sizeof probe);
  const int probe6 = IPV6_PMTUDISC_PROBE;
  ::setsockopt(fd, IPPROTO_IPV6, IPV6_MTU_DISCOVER, &probe6, sizeof probe6);
}

int new_epoll() {
  const int fd = ::epoll_create1(EPOLL_CLOEXEC);
  if (fd < 0) throw std::system_error(errno, std::generic_category(), "epoll_create1 for the UDP socket");
  return fd;
}

}  // namespace

DatagramPort::DatagramPort(asio::io_context& context, asio::ip::udp::socket socket, Handler handler)
    : ready_(context, new_epoll()), pause_(context), handler_(std::move(handler)), buffers_(kBatch) {
  fd_ = socket.release();
  set_no_fragments(fd_);
  epoll_event event{};
  event.events = EPOLLIN | EPOLLONESHOT;
  event.data.fd = fd_;
  if (::epoll_ctl(ready_.native_handle(), EPOLL_CTL_ADD, fd_, &event) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    throw std::system_error(error, std::generic_category(), "epoll_ctl for the UDP socket");
  }
}

DatagramPort::~DatagramPort() { close(); }

void DatagramPort::start() { arm(); }

void DatagramPort::close() {
  if (fd_ < 0) return;
  std::error_code ignored;
  pause_.cancel();
  ready_.close(ignored);
  ::close(fd_);
  fd_ = -1;
}

void DatagramPort::arm() {
  if (fd_ < 0) return;
  // One-shot: re-enabled here, reported once, then silent however many datagrams arrive.
  epoll_event event{};
  event.events = EPOLLIN | EPOLLONESHOT;
  event.data.fd = fd_;
  ::epoll_ctl(ready_.native_handle(), EPOLL_CTL_MOD, fd_, &event);
  ready_.async_wait(asio::posix::stream_descriptor::wait_read, [this](std::error_code error) {
    if (fd_ < 0 || error == asio::error::operation_aborted) return;
    ++wakes_;
    epoll_event taken{};
    ::epoll_wait(ready_.native_handle(), &taken, 1, 0);  // takes the event: the socket stays quiet
    if (drain() == 0) return arm();
    pause_.expires_after(kPause);
    pause_.async_wait([this](std::error_code e) {
      if (!e) arm();
    });
  });
}

std::size_t DatagramPort::drain() {
  std::array<mmsghdr, kBatch> headers{};
  std::array<iovec, kBatch> vectors{};
  std::size_t total = 0;
  while (total < kMaxPerWake && fd_ >= 0) {
    for (std::size_t i = 0; i < kBatch; ++i) {
      vectors[i] = iovec{buffers_[i].data(), kBufferBytes};
      headers[i] = mmsghdr{};
      headers[i].msg_hdr.msg_iov = &vectors[i];
      headers[i].msg_hdr.msg_iovlen = 1;
      headers[i].msg_hdr.msg_name = senders_[i].data();
      headers[i].msg_hdr.msg_namelen = static_cast<socklen_t>(senders_[i].capacity());
    }
    const int got = ::recvmmsg(fd_, headers.data(), kBatch, MSG_DONTWAIT, nullptr);
    if (got <= 0) break;  // drained; an error (ICMP unreachable from a send) is taken by the call
    for (int i = 0; i < got && fd_ >= 0; ++i) {
      senders_[i].resize(headers[i].msg_hdr.msg_namelen);
      handler_(std::span<const std::uint8_t>(buffers_[i].data(), headers[i].msg_len), senders_[i]);
    }
    total += static_cast<std::size_t>(got);
    if (static_cast<std::size_t>(got) < kBatch) break;
  }
  return total;
}

}  // namespace ocean::server
