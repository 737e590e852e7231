// HullRecord: the viewer's hull poses, one CSV line per vessel and rendered frame (--record-hulls),
// beside the decoded surface under each hull, so a test checks from the viewer's own output that
// the hulls ride the water it shows.
#pragma once

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "hull_motion.hpp"

namespace ocean::viewer {

class HullRecord {
 public:
  // False when the file cannot be written (the reason in error).
  bool open(const std::string& path, std::string& error) {
    file_.reset(std::fopen(path.c_str(), "w"));
    if (!file_) {
      error = "--record-hulls '" + path + "': cannot open it for writing";
      return false;
    }
    std::fprintf(file_.get(), "frame,t_s,id,x_m,z_m,heading_deg,speed_mps,heave_m,pitch_deg,roll_deg,draft_m,"
                              "surface_bow_m,surface_stern_m,surface_port_m,surface_starboard_m,surface_mid_m,keel_above_m\n");
    return true;
  }
  bool active() const { return file_ != nullptr; }
  void write(std::uint64_t frame, double t_s, const std::vector<client::HullState>& hulls) {
    if (!file_) return;
    constexpr double kDeg = 180.0 / 3.14159265358979;
    for (const client::HullState& h : hulls) {
      std::fprintf(file_.get(), "%llu,%.4f,%u,%.3f,%.3f,%.2f,%.3f,%.5f,%.4f,%.4f,%.3f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f\n",
                   static_cast<unsigned long long>(frame), t_s, h.id, h.x_m, h.z_m, std::atan2(h.dir_z, h.dir_x) * kDeg,
                   h.speed_mps, h.heave_m, h.pitch_rad * kDeg, h.roll_rad * kDeg, h.hull.draft_m, h.surface_m[0],
                   h.surface_m[1], h.surface_m[2], h.surface_m[3], h.surface_m[4], h.keel_above_m);
    }
  }

 private:
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
};

}  // namespace ocean::viewer
