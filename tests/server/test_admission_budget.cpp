// AdmissionBudget: the door closes at the sessions served once the thread stays busier than the
// target, not for one slow second, and opens again once the load falls well below it.
#include "admission_budget.hpp"

#include <catch2/catch.hpp>

using ocean::server::AdmissionBudget;

TEST_CASE("admission: open while the thread is under its target", "[admission]") {
  AdmissionBudget budget(0.7);
  for (int i = 0; i < 10; ++i) budget.observe(0.5, 1.0, 800);
  CHECK(budget.admits(100000));
  CHECK(!budget.over_target());
}

TEST_CASE("admission: one slow second does not close the door, a lasting load does", "[admission]") {
  AdmissionBudget budget(0.7);
  for (int i = 0; i < 10; ++i) budget.observe(0.3, 1.0, 500);
  budget.observe(0.95, 1.0, 500);
  CHECK(budget.admits(100000));
  budget.observe(0.95, 1.0, 1200);
  budget.observe(0.95, 1.0, 1300);
  CHECK(budget.over_target());
  CHECK(budget.capacity() == 1200);  // the sessions served when it closed: none is dropped
  CHECK(!budget.admits(1200));
  CHECK(budget.admits(1199));
  budget.observe(0.95, 1.0, 1200);
  CHECK(budget.capacity() == 1200);  // a later, larger count does not reopen it
}

TEST_CASE("admission: the door opens again below 80 % of the target", "[admission]") {
  AdmissionBudget budget(0.7);
  for (int i = 0; i < 5; ++i) budget.observe(0.95, 1.0, 1000);
  REQUIRE(!budget.admits(1000));
  budget.observe(0.6, 1.0, 1000);  // smoothed still above 0.56
  CHECK(!budget.admits(1000));
  for (int i = 0; i < 5; ++i) budget.observe(0.3, 1.0, 1000);
  CHECK(budget.admits(100000));
}
