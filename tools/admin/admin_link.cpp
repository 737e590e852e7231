#include "admin_link.hpp"

#include <asio/connect.hpp>
#include <asio/write.hpp>

#include "message_readers.hpp"
#include "verify_message.hpp"

namespace ocean::admin {

AdminLink::AdminLink(double timeout_s)
    : socket_(io_),
      deadline_(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s))),
      max_message_bytes_(protocol::kDefaultMaxMessageBytes) {}

bool AdminLink::run_until(const bool& done, Clock::time_point until) {
  while (!done && Clock::now() < until) {
    io_.run_one_for(until - Clock::now());
    if (io_.stopped()) io_.restart();
  }
  if (done) return true;
  timed_out_ = true;
  asio::error_code ignored;
  socket_.close(ignored);  // completes the pending operation with operation_aborted
  io_.restart();
  io_.run();
  return false;
}

bool AdminLink::connect(const client::ServerEndpoint& server, std::string& error) {
  const std::string name = server.host + ":" + server.port;
  asio::ip::tcp::resolver resolver(io_);
  asio::error_code ec;
  const auto endpoints = resolver.resolve(server.host, server.port, ec);
  if (ec) {
    error = "cannot resolve " + name + ": " + ec.message();
    return false;
  }
  bool done = false;
  asio::async_connect(socket_, endpoints, [&](const asio::error_code& e, const asio::ip::tcp::endpoint&) {
    ec = e;
    done = true;
  });
  if (!run_until(done, deadline_)) {
    error = "no connection to " + name + " within the timeout";
    return false;
  }
  if (ec) {
    error = "cannot connect to " + name + ": " + ec.message();
    return false;
  }
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);  // a repeated query must not wait for Nagle
  return true;
}

bool AdminLink::send(const protocol::Bytes& bytes, std::string& error) {
  bool done = false;
  asio::error_code ec;
  asio::async_write(socket_, asio::buffer(bytes), [&](const asio::error_code& e, std::size_t) {
    ec = e;
    done = true;
  });
  if (!run_until(done, deadline_)) {
    error = "sending to the server timed out";
    return false;
  }
  if (ec) error = "sending to the server failed: " + ec.message();
  return !ec;
}

std::optional<protocol::AnyMessage> AdminLink::receive(std::string& error, std::optional<Clock::time_point> until) {
  const Clock::time_point limit = until ? std::min(*until, deadline_) : deadline_;
  std::vector<std::uint8_t> chunk(16 * 1024);
  while (true) {
    const auto fed = framer_.feed(pending_);
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(fed.consumed));
    if (fed.status == protocol::TcpFramer::Status::bad) {
      error = "the server sent an unframeable stream: " + std::string(protocol::to_string(fed.reason));
      return std::nullopt;
    }
    if (fed.status == protocol::TcpFramer::Status::good) {
      const protocol::Verified v = protocol::verify_message(
          framer_.message(), {protocol::Sender::server, wire::Transport::tcp, max_message_bytes_});
      if (!v.ok) {
        error = "the server sent a bad message: " + protocol::describe(v);
        return std::nullopt;
      }
      return protocol::decode(*v.message);
    }
    bool done = false;
    asio::error_code ec;
    std::size_t n = 0;
    socket_.async_read_some(asio::buffer(chunk), [&](const asio::error_code& e, std::size_t got) {
      ec = e;
      n = got;
      done = true;
    });
    if (!run_until(done, limit)) {
      error = "no answer from the server within the timeout";
      return std::nullopt;
    }
    if (ec) {
      error = ec == asio::error::eof ? "the server closed the connection" : "receiving failed: " + ec.message();
      return std::nullopt;
    }
    pending_.insert(pending_.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
  }
}

void AdminLink::set_max_message_bytes(std::size_t bytes) {
  max_message_bytes_ = bytes;
  framer_.set_max_message_bytes(bytes);
}

}  // namespace ocean::admin
