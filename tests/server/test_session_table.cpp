// SessionTable (find by id, dense walk, swap-remove) and the core's walks over it while
// sessions close under them: a link that closes at once erases its session in the middle of a
// walk, and every session must still get its goodbye.
#include <catch2/catch.hpp>

#include "core_rig.hpp"
#include "memory_links.hpp"
#include "message_builders.hpp"
#include "session_table.hpp"
#include "verify_message.hpp"

#include <algorithm>
#include <set>

using namespace ocean;
using namespace ocean::server;
using ocean::test::CoreRig;
using ocean::test::MemoryDatagrams;
using ocean::test::MemoryLink;
namespace proto = ocean::protocol;

namespace {

std::shared_ptr<Session> session_with_id(std::uint64_t id) {
  auto session = std::make_shared<Session>();
  session->id = id;
  return session;
}

std::set<std::uint64_t> walked_ids(const SessionTable& table) {
  std::set<std::uint64_t> ids;
  for (const auto& session : table) ids.insert(session->id);
  return ids;
}

}  // namespace

TEST_CASE("the session table finds every session by id and walks each exactly once") {
  SessionTable table;
  for (std::uint64_t id : {11u, 22u, 33u, 44u, 55u}) table.insert(session_with_id(id));
  CHECK(table.size() == 5);
  CHECK(walked_ids(table) == std::set<std::uint64_t>{11, 22, 33, 44, 55});
  REQUIRE(table.find(33) != nullptr);
  CHECK(table.find(33)->id == 33);
  CHECK(table.find(66) == nullptr);
  CHECK_THROWS_AS(table.insert(session_with_id(22)), std::invalid_argument);

  table.erase(22);  // the middle: the last one moves into its place
  CHECK(table.find(22) == nullptr);
  CHECK(!table.contains(22));
  CHECK(walked_ids(table) == std::set<std::uint64_t>{11, 33, 44, 55});
  for (std::uint64_t id : {11u, 33u, 44u, 55u}) {
    REQUIRE(table.find(id) != nullptr);
    CHECK(table.find(id)->id == id);
  }
  table.erase(55);  // then the one that moved
  table.erase(99);  // unknown: nothing happens
  CHECK(walked_ids(table) == std::set<std::uint64_t>{11, 33, 44});
  for (std::size_t i = 0; i < table.size(); ++i) CHECK(table.find(table[i]->id) == table[i].get());
  table.erase(11);
  table.erase(33);
  table.erase(44);
  CHECK(table.empty());
  table.insert(session_with_id(22));  // an erased id may come back
  CHECK(table.find(22) != nullptr);
}

TEST_CASE("stop says goodbye to every session even when each link closes at once") {
  MemoryDatagrams datagrams;
  CoreRig rig(ocean::test::core_test_config(), ocean::test::core_test_options(), datagrams, 7701, 0);
  std::vector<std::shared_ptr<MemoryLink>> links;
  for (int i = 0; i < 7; ++i) {
    links.push_back(std::make_shared<MemoryLink>("127.0.0.1:" + std::to_string(41000 + i)));
    rig.core().open(links.back(), CoreRig::at(0.0));
    links.back()->deliver(proto::encode(proto::Hello{1, 0, wire::Transport::tcp, "t"}), CoreRig::at(0.0));
  }
  REQUIRE(rig.core().session_count() == links.size());
  for (auto& link : links) link->take();
  rig.core().stop();  // MemoryLink closes inside close_after_flush: each Bye erases its session
  CHECK(rig.core().session_count() == 0);
  for (auto& link : links) {
    CHECK(link->close_reason == "closed_after_flush");
    bool bye = false;
    for (const proto::Bytes& message : link->take()) {
      const auto verified = proto::verify_message(message, {proto::Sender::server, wire::Transport::tcp});
      bye = bye || (verified && verified.message->body_type() == wire::Body::Bye);
    }
    CHECK(bye);
  }
}
