#include "raw_peers.hpp"

#include <arpa/inet.h>
#include <cerrno>
#include <chrono>
#include <utility>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "message_builders.hpp"
#include "message_readers.hpp"
#include "verify_message.hpp"

namespace ocean::faults {

ParamChangeAnswer send_param_change(RawTcp& admin, const protocol::ParamChange& change, double timeout_s) {
  if (!admin.send(protocol::encode(change))) return {};
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < until) {
    const auto message = admin.read_message(0.2);
    if (!message) continue;
    if (const auto* update = std::get_if<protocol::SceneUpdate>(&*message); update && update->request_id == change.request_id)
      return {true, std::nullopt};
    if (const auto* error = std::get_if<protocol::Error>(&*message)) return {false, error->code};
  }
  return {};
}

namespace {

sockaddr_in loopback(std::uint16_t port, const char* ip = "127.0.0.1") {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  ::inet_pton(AF_INET, ip, &address.sin_addr);
  return address;
}

}  // namespace

RawTcp::RawTcp(std::uint16_t port, int receive_buffer_bytes, const char* local_ip) {
  fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd_ < 0) return;
  if (local_ip) {
    const sockaddr_in local = loopback(0, local_ip);
    if (::bind(fd_, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0) return;
  }
  if (receive_buffer_bytes > 0) ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receive_buffer_bytes, sizeof receive_buffer_bytes);
  timeval tv{1, 0};
  ::setsockopt(fd_, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
  const int one = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  const sockaddr_in address = loopback(port);
  connected_ = ::connect(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0;
}

RawTcp::~RawTcp() { close(); }

RawTcp::RawTcp(RawTcp&& other) noexcept
    : fd_(other.fd_), connected_(other.connected_), framer_(std::move(other.framer_)), pending_(std::move(other.pending_)) {
  other.fd_ = -1;
  other.connected_ = false;
}

bool RawTcp::send(std::span<const std::uint8_t> bytes) {
  while (!bytes.empty() && fd_ >= 0) {
    const ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n <= 0) return false;
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return bytes.empty() && fd_ >= 0;
}

std::optional<protocol::AnyMessage> RawTcp::read_message(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (fd_ >= 0) {
    while (!pending_.empty()) {
      const auto result = framer_.feed(pending_);
      pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(result.consumed));
      if (result.status == protocol::TcpFramer::Status::bad) return std::nullopt;
      if (result.status != protocol::TcpFramer::Status::good) continue;
      const protocol::Verified verified = protocol::verify_message(
          framer_.message(), {protocol::Sender::server, wire::Transport::tcp, protocol::kDefaultMaxMessageBytes});
      if (!verified) return std::nullopt;
      return protocol::decode(*verified.message);
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
    std::uint8_t buffer[16384];
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n <= 0) {
      connected_ = false;
      return std::nullopt;
    }
    pending_.insert(pending_.end(), buffer, buffer + n);
  }
  return std::nullopt;
}

std::vector<std::uint8_t> RawTcp::read_raw(double timeout_s) {
  std::vector<std::uint8_t> bytes = std::exchange(pending_, {});
  if (!bytes.empty() || fd_ < 0) return bytes;
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, static_cast<int>(timeout_s * 1000.0)) <= 0) return bytes;
  std::uint8_t buffer[16384];
  const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
  if (n <= 0) {
    connected_ = false;
    return bytes;
  }
  return std::vector<std::uint8_t>(buffer, buffer + n);
}

std::optional<protocol::Welcome> RawTcp::handshake(const protocol::Hello& hello, double timeout_s) {
  if (!send(protocol::encode(hello))) return std::nullopt;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    auto message = read_message(left);
    if (!message) return std::nullopt;
    if (auto* welcome = std::get_if<protocol::Welcome>(&*message)) return *welcome;
    if (std::holds_alternative<protocol::Error>(*message)) return std::nullopt;
  }
  return std::nullopt;
}

RawTcp::Ending RawTcp::wait_closed(double timeout_s) {
  Ending ending;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (fd_ >= 0 && std::chrono::steady_clock::now() < deadline) {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    auto message = read_message(left);
    if (message) {
      if (auto* e = std::get_if<protocol::Error>(&*message)) ending.error = *e;
      if (auto* b = std::get_if<protocol::Bye>(&*message)) ending.bye = *b;
      continue;
    }
    if (!connected_) {
      ending.closed = true;
      break;
    }
  }
  return ending;
}

void RawTcp::close_with_reset() {
  if (fd_ < 0) return;
  const linger hard{1, 0};
  ::setsockopt(fd_, SOL_SOCKET, SO_LINGER, &hard, sizeof hard);
  close();
}

void RawTcp::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  connected_ = false;
}

RawUdp::RawUdp(const std::string& local_ip) {
  fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
  const sockaddr_in local = loopback(0, local_ip.c_str());
  ::bind(fd_, reinterpret_cast<const sockaddr*>(&local), sizeof local);
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
}

RawUdp::~RawUdp() {
  if (fd_ >= 0) ::close(fd_);
}

void RawUdp::send_to(std::uint16_t port, std::span<const std::uint8_t> bytes) {
  const sockaddr_in to = loopback(port);
  const ssize_t n = ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to);
  if (n >= 0) {
    bytes_out_ += bytes.size();
    ++datagrams_out_;
  }
}

void RawUdp::drain() {
  std::uint8_t buffer[65536];
  ssize_t n;
  while ((n = ::recv(fd_, buffer, sizeof buffer, 0)) >= 0) bytes_in_ += static_cast<std::uint64_t>(n);
}

void lower_thread_priority() {
  ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10);
}

}  // namespace ocean::faults
