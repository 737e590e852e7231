// EtcdGateway: the calls the fleet's timeline makes to etcd, through etcd's own v3 API as its
// JSON gateway serves it (POST /v3/kv/range and /v3/kv/txn, keys and values in base64) - no client
// protocol of our own. Blocking, one short HTTP/1.1 request per call, each within a deadline (a
// host name's lookup excepted: give the store as an address where that matters): the timeline
// calls it from a thread of its own, never from the tick loop or the network thread.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ocean::server {

struct EtcdEndpoint {
  std::string host;
  std::uint16_t port = 2379;
};

struct EtcdKeyValue {
  std::string key, value;
  std::int64_t mod_revision = 0;
};

struct EtcdResult {
  std::string error;           // empty: the call was answered; else why not (unreachable, timed out, refused)
  std::int64_t revision = 0;   // the store's revision when it answered
  bool succeeded = false;      // a transaction's comparison held (put_if_absent wrote)
  std::vector<EtcdKeyValue> kvs;  // a range's keys and values, in key order
  bool more = false;           // a range stopped at its limit
  bool maybe_applied = false;  // an error after the request was sent: the store may have done it
  std::int64_t lease = 0;      // lease_grant: the lease's id
  std::int64_t ttl_s = 0;      // lease_grant, lease_keepalive: its time to live (0: it has lapsed)
};

class EtcdGateway {
 public:
  EtcdGateway(EtcdEndpoint endpoint, double timeout_s) : endpoint_(std::move(endpoint)), timeout_s_(timeout_s) {}

  // Writes key = value only if the key has never been written (a transaction comparing its
  // create_revision with 0): two writers of one key, one wins.
  EtcdResult put_if_absent(const std::string& key, const std::string& value) const;
  // key = value, bound to `lease` (0: none): the store deletes it when the lease lapses.
  EtcdResult put(const std::string& key, const std::string& value, std::int64_t lease = 0) const;
  // A lease the store keeps for ttl_s seconds past its grant or last keepalive (etcd grants at
  // least its own minimum, 2 s by default; the answer's ttl_s says what it granted).
  EtcdResult lease_grant(std::int64_t ttl_s) const;
  // Renews `lease`; the answer's ttl_s is 0 once it has lapsed (its keys are gone).
  EtcdResult lease_keepalive(std::int64_t lease) const;
  // Ends `lease` now, its keys with it.
  EtcdResult lease_revoke(std::int64_t lease) const;
  // The keys in [from, to) in key order (the last first when descending), at most limit of them.
  EtcdResult range(const std::string& from, const std::string& to, std::int64_t limit, bool descending = false) const;

  const EtcdEndpoint& endpoint() const { return endpoint_; }

 private:
  EtcdResult call(const std::string& path, const std::string& body) const;

  EtcdEndpoint endpoint_;
  double timeout_s_;
};

// Base64 (RFC 4648, padded), as the JSON gateway writes bytes.
std::string to_base64(const std::string& bytes);
// false when `text` is not padded base64.
bool from_base64(const std::string& text, std::string& bytes);

}  // namespace ocean::server
