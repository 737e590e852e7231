// `ocean-admin query`: sends the HeightQuery and prints its answer as JSON, or, with --repeat,
// asks at --rate and prints how long the answers took (what a game server's buoyancy loop sees).
#pragma once

#include "admin_link.hpp"
#include "admin_options.hpp"

namespace ocean::admin {

// An exit code (admin_options.hpp); failures are told on stderr.
int run_query(AdminLink& link, const AdminOptions& options);

}  // namespace ocean::admin
