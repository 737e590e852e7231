#include "query_flags.hpp"

#include <cmath>

#include "number_list.hpp"
#include "profile.hpp"
#include "wire_limits.hpp"

namespace ocean::admin {

CLI::App* QueryFlags::add_to(CLI::App& app) {
  CLI::App* query = app.add_subcommand(
      "query", "print the sea (height, normal, vertical velocity) the server streams at world points, at its newest tick, "
               "as JSON (admin token needed)");
  query->fallthrough();  // --server, --token-file, --timeout may follow it
  query->add_option("--at", at, "X,Z: a world point in metres; repeat for more");
  query->add_option("--grid", grid, "X0,Z0,X1,Z1,NX,NZ: NX x NZ points spanning the rectangle (corners included)");
  query->add_option("--profile", profile, "the stream asked (default: the server's first offered profile)");
  query->add_option("--repeat", repeat, "ask this many times, printing a summary of the answers' latency, [1, 100000]")
      ->check(CLI::Range(1, 100000));
  query->add_option("--rate", rate_hz, "queries a second with --repeat, [0.1, 1000] (ocean-server answers 60 a second "
                                       "per connection, a burst of 30: beyond that it refuses, exit 3)")
      ->check(CLI::Range(0.1, 1000.0));
  return query;
}

bool QueryFlags::read(AdminOptions& options, std::string& error) const {
  protocol::HeightQuery q;
  std::vector<double> xs;
  for (const std::string& point : at) {
    if (!parse_numbers(point, 2, xs)) {
      error = "--at '" + point + "': give X,Z in metres, e.g. 40,-60";
      return false;
    }
    q.points.emplace_back(xs[0], xs[1]);
  }
  if (!grid.empty()) {
    if (!parse_numbers(grid, 6, xs) || xs[4] < 1 || xs[5] < 1 || xs[4] != std::floor(xs[4]) || xs[5] != std::floor(xs[5]) ||
        xs[4] * xs[5] > static_cast<double>(protocol::kMaxQueryPoints)) {
      error = "--grid '" + grid + "': give X0,Z0,X1,Z1,NX,NZ (finite) with whole NX, NZ >= 1 and NX * NZ <= 2048";
      return false;
    }
    const int nx = static_cast<int>(xs[4]), nz = static_cast<int>(xs[5]);
    for (int j = 0; j < nz; ++j)
      for (int i = 0; i < nx; ++i)
        q.points.emplace_back(xs[0] + (nx > 1 ? (xs[2] - xs[0]) * i / (nx - 1) : 0.0),
                              xs[1] + (nz > 1 ? (xs[3] - xs[1]) * j / (nz - 1) : 0.0));
  }
  if (q.points.empty() || q.points.size() > protocol::kMaxQueryPoints) {
    error = "query: give 1 to 2048 points with --at X,Z or --grid (" + std::to_string(q.points.size()) + " given)";
    return false;
  }
  if (!profile.empty()) {
    const Profile* p = find_profile(std::string_view(profile));
    if (!p) {
      error = "--profile '" + profile + "': not a profile; one of";
      for (const Profile& known : all_profiles()) error += " " + std::string(known.name);
      return false;
    }
    q.profile_id = p->id;
  }
  options.query = std::move(q);
  options.query_repeat = repeat;
  options.query_rate_hz = rate_hz;
  return true;
}

}  // namespace ocean::admin
