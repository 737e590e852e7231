// The admin token check of ParamChange: constant time whatever the two lengths, and never true
// when the server has no token (--admin-token-file unset disables the admin interface).
#pragma once

#include <string_view>

namespace ocean::server {

bool same_token(std::string_view given, std::string_view expected);

}  // namespace ocean::server
