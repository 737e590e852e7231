// TimelineLog: the fleet's scene timeline as an ordered log in etcd, the one source every replica
// follows. Entry N lives under <prefix>/log/<N as 20 digits>, written only where nothing ever was
// (EtcdGateway::put_if_absent), so replicas appending at once take distinct places and every
// reader sees one order; etcd's Raft commit makes an acknowledged entry survive a member's loss.
// The entries are opaque bytes here: what they say (a scene change, a vessel command, each with its
// effective tick) is the server's.
//
// An entry takes effect only once decided: <prefix>/decided/<N> holds "commit" or "abort <why>",
// written where nothing was (first decision wins, every replica reads the same one). The replica
// that appended commits once every member has acknowledged reading it; a member is a replica
// holding an etcd lease, and <prefix>/acks/<origin> (bound to that lease) holds how far it has
// read - so a replica cut off from the store either acknowledges, holds the change back (it aborts
// at its tick), or has lost its lease, and knows it (TimelineFollower).
#pragma once

#include "etcd_gateway.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ocean::server {

struct TimelineAddress {
  EtcdEndpoint store;
  std::string prefix;  // "/ocean/harbour-1": the log's keys start with it
};

// "etcd://HOST:PORT/PREFIX" (PORT defaults to 2379); nullopt with `error` naming what is wrong.
std::optional<TimelineAddress> parse_timeline_url(std::string_view url, std::string& error);

struct TimelineEntry {
  std::uint64_t index = 0;  // 1, 2, ...: the log's order
  std::string bytes;
};

class TimelineLog {
 public:
  TimelineLog(TimelineAddress address, double timeout_s) : address_(std::move(address)), store_(address_.store, timeout_s) {}

  struct Appended {
    std::string error;  // empty: written at `index`
    std::uint64_t index = 0;
  };
  // Appends after the last entry written, whoever wrote it. An error after the write was sent
  // (the store went away, or timed out) leaves its outcome unknown, and says so: a caller that
  // would retry puts an id of its own in the entry and looks for it first.
  Appended append(const std::string& bytes);

  struct Read {
    std::string error;  // empty: `entries` are every entry from `from` on, up to `max`, in order
    std::vector<TimelineEntry> entries;
  };
  Read read_from(std::uint64_t from, std::size_t max) const;

  // This replica has read every entry up to `index`; bound to `lease`, so it goes when that lapses.
  EtcdResult acknowledge(std::uint64_t origin, std::uint64_t index, std::int64_t lease) const;
  struct Acks {
    std::string error;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> read;  // (origin, entries read) of every member
  };
  Acks acks() const;

  struct Decision {
    std::uint64_t index = 0;
    bool commit = false;
    std::string reason;  // an abort's
  };
  // Writes the decision on `index` unless one was written; `decided` is whichever stands.
  std::string decide(const Decision& decision, Decision& decided) const;
  struct Decisions {
    std::string error;
    std::vector<Decision> decided;  // in index order, from `from` on
  };
  Decisions decisions_from(std::uint64_t from, std::size_t max) const;

  std::string key(std::uint64_t index) const;  // <prefix>/log/<index, 20 digits>
  const EtcdGateway& store() const { return store_; }
  const TimelineAddress& address() const { return address_; }

 private:
  TimelineAddress address_;
  EtcdGateway store_;
  std::uint64_t next_ = 1;  // where the next append tries first
};

}  // namespace ocean::server
