#include "session_table.hpp"

#include <stdexcept>

namespace ocean::server {

Session* SessionTable::find(std::uint64_t id) const {
  const auto found = index_.find(id);
  return found == index_.end() ? nullptr : all_[found->second].get();
}

void SessionTable::insert(std::shared_ptr<Session> session) {
  if (!index_.emplace(session->id, all_.size()).second)
    throw std::invalid_argument("SessionTable::insert: session id already present");
  all_.push_back(std::move(session));
}

void SessionTable::erase(std::uint64_t id) {
  const auto found = index_.find(id);
  if (found == index_.end()) return;
  const std::size_t at = found->second;
  index_.erase(found);
  if (at + 1 != all_.size()) {
    all_[at] = std::move(all_.back());
    index_[all_[at]->id] = at;
  }
  all_.pop_back();
}

}  // namespace ocean::server
