// `ocean-loadtest --list-scenarios`: the scenario table for people, or with --json one JSON array
// for scripts (local_server.py starts a server with each scenario's ServerNeeds from it).
#pragma once

#include <ostream>
#include <string>

namespace ocean::loadtest {

void print_scenarios(std::ostream& out);
std::string scenarios_json();  // one line, no trailing newline

}  // namespace ocean::loadtest
