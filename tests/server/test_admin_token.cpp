// same_token: the ParamChange gate.
#include "admin_token.hpp"

#include <catch2/catch.hpp>

using ocean::server::same_token;

TEST_CASE("the admin token matches only itself, and never when none is configured") {
  CHECK(same_token("s3cret", "s3cret"));
  CHECK(!same_token("s3creT", "s3cret"));
  CHECK(!same_token("s3cret-and-more", "s3cret"));  // a longer guess sharing the prefix
  CHECK(!same_token("", "s3cret"));
  CHECK(!same_token("", ""));  // no --admin-token-file: the admin interface is off
}
