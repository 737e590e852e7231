// The server's own tables as JSON (ocean-server --help-json), for tools that must follow the
// server rather than a copy of it: deploy/check-manifests.py reads the option names and which may
// be scheduled, tests/deploy checks the web page and PROTOCOL.md against the profiles.
#pragma once

#include <string>

namespace ocean::server {

// {"options": [{"name", "value_name", "help", "kind", "schedulable", "default"}...],
//  "profiles": [{"id", "name", "grid", "rate_hz", "normals", "choppy"}...]}, one line.
std::string options_json();

}  // namespace ocean::server
