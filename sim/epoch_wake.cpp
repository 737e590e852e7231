#include "epoch_wake.hpp"

#include "sea_model.hpp"

namespace ocean::sim {

EpochWake::EpochWake(const WakeRegion& region, double origin_x_m, double origin_z_m,
                     std::vector<model::VesselTrack> tracks, int rate_hz, std::int64_t epoch_ticks)
    : region_(region),
      origin_x_m_(origin_x_m),
      origin_z_m_(origin_z_m),
      tracks_(std::move(tracks)),
      rate_hz_(rate_hz),
      epoch_ticks_(epoch_ticks) {
  if (rate_hz < 1) throw ParamError(bad_param("wake rate_hz", rate_hz, ">= 1"));
  if (epoch_ticks < 1) throw ParamError(bad_param("wake epoch_ticks", static_cast<double>(epoch_ticks), ">= 1"));
}

EpochWake::Part EpochWake::fresh(std::int64_t start) const { return Part{start, start, WakeField(region_)}; }

void EpochWake::step(Part& part) {
  const std::int64_t t = part.reached;
  poses_.clear();
  // Forced only during its own epoch; afterwards its waves ring down freely.
  if (t < part.start + epoch_ticks_) {
    const double mid_s = (static_cast<double>(t) + 0.5) / rate_hz_;
    for (const model::VesselTrack& v : tracks_) {
      if (!model::present_at(v.presence, mid_s)) continue;  // a dropped object between splashes
      HullPose pose = model::pose_at(v, mid_s);
      pose.x_m -= origin_x_m_;
      pose.z_m -= origin_z_m_;
      poses_.push_back(pose);
    }
  }
  // The depth in force at t (the region's before every change).
  auto depth = depths_.upper_bound(t);
  part.field.set_depth(depth == depths_.begin() ? region_.depth_m : std::prev(depth)->second);
  part.field.step(1.0 / rate_hz_, poses_);
  ++part.reached;
}

void EpochWake::advance_to(std::int64_t tick) {
  if (tick < 0) throw ParamError(bad_param("wake tick", static_cast<double>(tick), ">= 0"));
  const std::int64_t epoch = tick / epoch_ticks_;
  const std::int64_t first = std::max<std::int64_t>(0, epoch - 1);
  // Keep the parts of epochs `first` and `epoch` that can still step forward to `tick`.
  std::vector<Part> kept;
  for (std::int64_t e = first; e <= epoch; ++e) {
    const std::int64_t start = e * epoch_ticks_;
    Part* found = nullptr;
    for (Part& p : parts_)
      if (p.start == start && p.reached <= tick) found = &p;
    kept.push_back(found ? std::move(*found) : fresh(start));
  }
  parts_ = std::move(kept);
  for (Part& p : parts_)
    while (p.reached < tick) step(p);
  tick_ = tick;
}

void EpochWake::set_depth(double depth_m, std::int64_t from) {
  if (auto it = depths_.find(from); it != depths_.end() && it->second == depth_m) return;
  depths_[from] = depth_m;
  restart_after(from);
}

void EpochWake::set_tracks(std::vector<model::VesselTrack> tracks, std::int64_t from) {
  tracks_ = std::move(tracks);
  restart_after(from);
}

void EpochWake::restart_after(std::int64_t from) {
  for (Part& p : parts_)
    if (p.reached > from) p = fresh(p.start);
  if (tick_ > from) {  // the wake at tick_ must be stepped again with the new tracks
    const std::int64_t tick = tick_;
    tick_ = -1;
    advance_to(tick);
  }
}

std::vector<const WakeField*> EpochWake::fields() const {
  std::vector<const WakeField*> out;
  for (const Part& p : parts_) out.push_back(&p.field);
  return out;
}

}  // namespace ocean::sim
