// The wake lattice's timeline (CODEC.md 7.9): advancing walks tick segments split at every change
// of scene (the recurrence changes) and at every epoch boundary (the wake of the epoch before last
// is dropped there, as the server's sim drops it); a model state's wake is the wake the last two
// epochs' forcing left. Each piece happens at a fixed tick, so advancing in parts gives the same
// integers.
#include "scene_timeline.hpp"

#include "fixed_point.hpp"

#include <algorithm>
#include <stdexcept>

namespace ocean::codec {
namespace {

ModalModel::WakeSpan span_of(WakeForcing::Part& p) {
  return {p.prev_re.data(), p.prev_im.data(), p.cur_re.data(), p.cur_im.data()};
}

// A part's pair added to (or, `take`, taken from) the state's wake modes, which start at `at`.
void fold_part(ModalState& state, std::size_t at, const WakeForcing::Part& p, bool take) {
  const auto op = [take](std::int64_t a, std::int64_t b) { return take ? wsub(a, b) : wadd(a, b); };
  for (std::size_t i = 0; i < p.cur_re.size(); ++i) {
    state.prev.re[at + i] = op(state.prev.re[at + i], p.prev_re[i]);
    state.prev.im[at + i] = op(state.prev.im[at + i], p.prev_im[i]);
    state.cur.re[at + i] = op(state.cur.re[at + i], p.cur_re[i]);
    state.cur.im[at + i] = op(state.cur.im[at + i], p.cur_im[i]);
  }
}

}  // namespace


void SceneTimeline::set_vessels(std::vector<model::VesselTrack> vessels) {
  if (!config_.has_wake()) throw std::invalid_argument("SceneTimeline::set_vessels: the stream has no wake lattice");
  if (vessels.empty())
    forcing_ = nullptr;
  else
    forcing_ = cache_ ? cache_->wake_forcing(config_, vessels) : std::make_shared<WakeForcing>(config_, std::move(vessels));
}

void SceneTimeline::set_vessels(std::vector<model::VesselTrack> vessels, Tick from) {
  if (!forcing_ || vessels.empty()) return set_vessels(std::move(vessels));
  if (!config_.has_wake()) throw std::invalid_argument("SceneTimeline::set_vessels: the stream has no wake lattice");
  if (vessels == forcing_->vessels()) return;
  forcing_ = cache_ ? cache_->wake_forcing(config_, vessels, *forcing_, from)
                    : std::make_shared<WakeForcing>(*forcing_, std::move(vessels), from);
}

const ModalModel& SceneTimeline::recurrence_near(Tick tick) const {
  // A tick before every scene still held (a decoder forgets old ones): the oldest held.
  return recurrence_of(held_at(std::max(tick, entries_.begin()->first)));
}

bool SceneTimeline::crosses_epoch(Tick from, Tick to) const {
  if (!forcing_) return false;
  const auto e = static_cast<Tick>(forcing_->epoch_ticks());
  return to / e != from / e;
}

const WakeForcing::Part& SceneTimeline::wake_part(std::int64_t epoch, Tick tick) const {
  WakeForcing::Part* p = &forcing_->part(epoch);
  if (p->at > tick) {  // asked for an earlier tick: again from rest
    p->at = static_cast<Tick>(epoch * forcing_->epoch_ticks());
    for (auto* v : {&p->prev_re, &p->prev_im, &p->cur_re, &p->cur_im}) std::fill(v->begin(), v->end(), 0);
  }
  const std::int64_t begin = epoch * forcing_->epoch_ticks(), end = begin + forcing_->epoch_ticks();
  while (p->at < tick) {
    Tick next = tick;
    if (auto it = entries_.upper_bound(p->at); it != entries_.end() && it->first < next) next = it->first;
    recurrence_near(p->at).step_wake(span_of(*p), next - p->at, p->at, forcing_.get(), begin, end);
    p->at = next;
  }
  return *p;
}

// The epochs alive at `tick` (its own and the one before) add the wake they left to `state`.
void SceneTimeline::add_wake_history(Tick tick, ModalState& state) const {
  if (!config_.has_wake() || !forcing_) return;
  const auto epoch = static_cast<std::int64_t>(tick / static_cast<Tick>(forcing_->epoch_ticks()));
  const std::size_t at = recurrence_near(tick).wake_modes_at();
  for (std::int64_t e = std::max<std::int64_t>(0, epoch - 1); e <= epoch; ++e) fold_part(state, at, wake_part(e, tick), false);
}

// From `from` to `to` without replacing the sea: the recurrence of each scene in force on the way,
// and at every epoch boundary B the wake of epoch B/E - 2 taken away.
void SceneTimeline::walk_wake(ModalState& state, Tick from, Tick to) const {
  Tick now = from;
  while (now < to) {
    Tick next = to;
    if (auto it = entries_.upper_bound(now); it != entries_.end() && it->first < next) next = it->first;
    if (forcing_) {
      const auto e = static_cast<Tick>(forcing_->epoch_ticks());
      next = std::min(next, (now / e + 1) * e);
    }
    recurrence_near(now).advance(state, state, next - now, {}, forcing_.get(), now);
    now = next;
    if (!forcing_) continue;
    const auto e = static_cast<Tick>(forcing_->epoch_ticks());
    const auto epoch = static_cast<std::int64_t>(now / e);
    if (now % e != 0 || epoch < 2) continue;
    fold_part(state, recurrence_near(now).wake_modes_at(), wake_part(epoch - 2, now), true);
  }
}

// The wake rides through a change of scene (walk_wake), while the sea's lattices take the new
// scene's model state at the last change in (from, to], then advance with its recurrence.
void SceneTimeline::advance_with_wake(ModalState& state, Tick from, Tick to) const {
  Tick now = from;
  const Tick start = start_of(to);
  if (start > from) {
    walk_wake(state, from, start);
    ModalState fresh;
    model_of(held_at(start)).state_at(start, fresh);  // the sea's model state (its wake modes are 0)
    const std::size_t wake_at = recurrence_of(held_at(start)).wake_modes_at();
    for (auto [to_s, from_s] : {std::pair{&state.prev, &fresh.prev}, std::pair{&state.cur, &fresh.cur}}) {
      std::copy(from_s->re.begin(), from_s->re.begin() + static_cast<std::ptrdiff_t>(wake_at), to_s->re.begin());
      std::copy(from_s->im.begin(), from_s->im.begin() + static_cast<std::ptrdiff_t>(wake_at), to_s->im.begin());
    }
    now = start;
  }
  walk_wake(state, now, to);
}

}  // namespace ocean::codec
