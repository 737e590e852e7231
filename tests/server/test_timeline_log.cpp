// The fleet's timeline log against a real etcd (Debian's etcd-server, started here on free
// ports): entries come back in the order they were appended, replicas appending at once each get
// their own place in one order, and a store that goes away is named in the error, then found again
// with nothing lost.
#include "timeline_log.hpp"

#include "etcd_process.hpp"

#include <asio/io_context.hpp>
#include <asio/ip/tcp.hpp>
#include <asio/write.hpp>
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <optional>
#include <cstdlib>
#include <set>
#include <string>
#include <thread>
#include <unistd.h>

using namespace ocean::server;
using ocean::test_support::EtcdProcess;

namespace {

TimelineLog log_at(const std::string& url) {
  std::string error;
  const auto address = parse_timeline_url(url, error);
  REQUIRE(address);
  return TimelineLog(*address, 2.0);
}

}  // namespace

TEST_CASE("a timeline URL names the store and the log's prefix", "[timeline]") {
  std::string error;
  const auto a = parse_timeline_url("etcd://store.example:2380/ocean/harbour-1/", error);
  REQUIRE(a);
  CHECK(a->store.host == "store.example");
  CHECK(a->store.port == 2380);
  CHECK(a->prefix == "/ocean/harbour-1");
  const auto b = parse_timeline_url("etcd://10.0.0.5/ocean/x", error);
  REQUIRE(b);
  CHECK(b->store.port == 2379);
  for (const char* bad : {"redis://h:1/p", "etcd://h:1", "etcd://h:1/", "etcd://h:0/p", "etcd://h:x/p", "etcd://:2379/p"}) {
    INFO(bad);
    error.clear();
    CHECK_FALSE(parse_timeline_url(bad, error));
    CHECK(error.find(bad) != std::string::npos);
  }
}

TEST_CASE("base64 as etcd's JSON gateway writes it", "[timeline]") {
  const std::string bytes("\0\x01\xff scene", 9);
  std::string back;
  CHECK(to_base64("foo") == "Zm9v");
  REQUIRE(from_base64(to_base64(bytes), back));
  CHECK(back == bytes);
  CHECK_FALSE(from_base64("not base64!", back));
}

TEST_CASE("entries come back in the order they were appended, bytes intact", "[timeline]") {
  EtcdProcess etcd;
  TimelineLog log = log_at(etcd.url("/ocean/harbour-1"));
  const std::string binary("\0wind\xff", 6);
  for (const std::string& bytes : {std::string("first"), binary, std::string("third")}) {
    const auto appended = log.append(bytes);
    REQUIRE(appended.error.empty());
  }
  const auto all = log.read_from(1, 100);
  REQUIRE(all.error.empty());
  REQUIRE(all.entries.size() == 3);
  CHECK(all.entries[0].index == 1);
  CHECK(all.entries[0].bytes == "first");
  CHECK(all.entries[1].bytes == binary);
  CHECK(all.entries[2].index == 3);
  CHECK(log.read_from(1, 0).entries.empty());  // etcd's limit 0 is "all": asking for none gets none
  const auto second = log.read_from(2, 1);
  REQUIRE(second.entries.size() == 1);
  CHECK(second.entries[0].bytes == binary);
  // Another fleet's log beside it is its own.
  TimelineLog other = log_at(etcd.url("/ocean/harbour-2"));
  CHECK(other.read_from(1, 100).entries.empty());
  CHECK(other.append("elsewhere").index == 1);
  CHECK(log.read_from(1, 100).entries.size() == 3);
}

TEST_CASE("replicas appending at once each get a place of their own, in one order", "[timeline]") {
  EtcdProcess etcd;
  constexpr int kReplicas = 3, kEach = 15;
  std::vector<std::thread> replicas;
  std::vector<std::string> errors(kReplicas);
  const TimelineLog fresh = log_at(etcd.url("/ocean/race"));  // parsed here: Catch's checks are not thread-safe
  for (int r = 0; r < kReplicas; ++r)
    replicas.emplace_back([&, r] {
      TimelineLog log = fresh;
      for (int i = 0; i < kEach; ++i)
        if (const auto a = log.append("replica " + std::to_string(r) + " change " + std::to_string(i)); !a.error.empty())
          errors[r] = a.error;
    });
  for (auto& t : replicas) t.join();
  for (const auto& e : errors) CHECK(e == "");
  const auto a = log_at(etcd.url("/ocean/race")).read_from(1, 1000);
  const auto b = log_at(etcd.url("/ocean/race")).read_from(1, 1000);
  REQUIRE(a.entries.size() == kReplicas * kEach);
  std::set<std::string> seen;
  for (std::size_t i = 0; i < a.entries.size(); ++i) {
    CHECK(a.entries[i].index == i + 1);  // no gap, no place taken twice
    CHECK(a.entries[i].bytes == b.entries[i].bytes);  // every reader, one order
    seen.insert(a.entries[i].bytes);
  }
  CHECK(seen.size() == kReplicas * kEach);  // each change exactly once
}

TEST_CASE("the first decision on an entry stands for every replica, and a member's acknowledgement goes with its lease",
          "[timeline]") {
  EtcdProcess etcd;
  const TimelineLog log = log_at(etcd.url("/ocean/decisions"));
  TimelineLog::Decision first;
  REQUIRE(log.decide({3, false, "too late"}, first).empty());
  CHECK_FALSE(first.commit);
  TimelineLog::Decision second;  // another replica, deciding the same entry otherwise
  REQUIRE(log.decide({3, true, {}}, second).empty());
  CHECK_FALSE(second.commit);
  CHECK(second.reason == "too late");
  REQUIRE(log.decide({5, true, {}}, second).empty());
  const TimelineLog::Decisions read = log.decisions_from(4, 10);
  REQUIRE(read.error.empty());
  REQUIRE(read.decided.size() == 1);
  CHECK(read.decided[0].index == 5);
  CHECK(read.decided[0].commit);
  CHECK(log_at(etcd.url("/ocean/other")).decisions_from(1, 10).decided.empty());

  // Two members; one lease lapses (etcd's shortest, 2 s) and its acknowledgement is gone with it.
  EtcdGateway store = log.store();
  const EtcdResult kept = store.lease_grant(30), lapsing = store.lease_grant(2);
  REQUIRE(kept.error.empty());
  REQUIRE(lapsing.error.empty());
  CHECK(lapsing.ttl_s == 2);
  REQUIRE(log.acknowledge(0xA, 7, kept.lease).error.empty());
  REQUIRE(log.acknowledge(0xC, 6, lapsing.lease).error.empty());
  TimelineLog::Acks acks = log.acks();
  REQUIRE(acks.error.empty());
  REQUIRE(acks.read.size() == 2);
  CHECK(acks.read[0] == std::pair<std::uint64_t, std::uint64_t>{0xA, 7});
  CHECK(acks.read[1] == std::pair<std::uint64_t, std::uint64_t>{0xC, 6});
  CHECK(store.lease_keepalive(lapsing.lease).ttl_s == 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(3500));
  CHECK(store.lease_keepalive(lapsing.lease).ttl_s == 0);
  acks = log.acks();
  REQUIRE(acks.read.size() == 1);
  CHECK(acks.read[0].first == 0xA);
}

TEST_CASE("a store that is down is named in the error, and once back it has lost nothing", "[timeline]") {
  EtcdProcess etcd;
  TimelineLog log = log_at(etcd.url("/ocean/faults"));
  REQUIRE(log.append("before").error.empty());
  etcd.stop();
  const auto refused = log.append("while down");
  CHECK(refused.error.find("unreachable") != std::string::npos);
  CHECK(refused.error.find("unknown") == std::string::npos);  // refused before it was sent: known not written
  CHECK(log.read_from(1, 10).error.find("127.0.0.1") != std::string::npos);
  etcd.start();
  const auto after = log.append("after");
  REQUIRE(after.error.empty());
  CHECK(after.index == 2);
  const auto all = log.read_from(1, 10);
  REQUIRE(all.entries.size() == 2);
  CHECK(all.entries[0].bytes == "before");
  CHECK(all.entries[1].bytes == "after");
}

namespace {

// A one-connection HTTP server on loopback that answers with `reply` (or, empty, never answers).
struct FakeStore {
  asio::io_context io;
  asio::ip::tcp::acceptor acceptor{io, {asio::ip::make_address("127.0.0.1"), 0}};
  std::thread thread;
  explicit FakeStore(std::string reply) {
    thread = std::thread([this, reply] {
      asio::ip::tcp::socket socket(io);
      acceptor.accept(socket);
      char request[4096];
      std::error_code ignored;
      socket.read_some(asio::buffer(request), ignored);
      if (reply.empty()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(800));
        return;
      }
      asio::write(socket, asio::buffer(reply), ignored);
    });
  }
  ~FakeStore() { thread.join(); }
  EtcdGateway gateway(double timeout_s) const { return EtcdGateway({"127.0.0.1", acceptor.local_endpoint().port()}, timeout_s); }
};

}  // namespace

TEST_CASE("a store that takes the request and never answers is a timeout, its outcome unknown", "[timeline]") {
  FakeStore silent("");
  const EtcdResult result = silent.gateway(0.3).put_if_absent("k", "v");
  CHECK(result.error.find("did not answer within") != std::string::npos);
  CHECK(result.maybe_applied);
}

TEST_CASE("a chunked reply is read; a malformed one is named", "[timeline]") {
  {
    FakeStore chunked("HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\n"
                      "d\r\n{\"header\":{\"r\r\ne\r\nevision\":\"7\"}}\r\n0\r\n\r\n");
    const EtcdResult result = chunked.gateway(2.0).range("a", "b", 1);
    CHECK(result.error == "");
    CHECK(result.revision == 7);
  }
  {
    FakeStore broken("HTTP/1.1 200 OK\r\nTransfer-Encoding: chunked\r\n\r\nffffffffffffffff\r\nshort\r\n");
    CHECK(broken.gateway(2.0).range("a", "b", 1).error.find("malformed chunked body") != std::string::npos);
  }
  {
    FakeStore not_etcd("HTTP/1.1 503 Service Unavailable\r\nContent-Length: 4\r\n\r\nbusy");
    CHECK(not_etcd.gateway(2.0).range("a", "b", 1).error.find("answered 503") != std::string::npos);
  }
}
