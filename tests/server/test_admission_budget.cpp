// AdmissionBudget: far from its target the door is open; nearer, it admits what the present cost
// per session says would load the thread to the target, with waiting for a CPU counted thrice;
// one slow second moves that a little, and a handful of sessions never closes it.
#include "admission_budget.hpp"

#include <catch2/catch.hpp>

using ocean::server::AdmissionBudget;
using ocean::server::LoadPeriod;

namespace {

void steady(AdmissionBudget& budget, double ran_s, double waited_s, double sessions, int seconds = 20) {
  for (int i = 0; i < seconds; ++i) budget.observe(LoadPeriod{ran_s, waited_s, 1.0, sessions});
}

}  // namespace

TEST_CASE("admission: open while the load is under half the target", "[admission]") {
  AdmissionBudget budget(0.8);
  steady(budget, 0.35, 0.0, 800);
  CHECK(budget.capacity() == AdmissionBudget::kUnlimited);
  CHECK(budget.admits(100000));
  CHECK(!budget.over_target());
}

TEST_CASE("admission: nearer the target, the capacity is the sessions that would reach it", "[admission]") {
  AdmissionBudget budget(0.8);
  steady(budget, 0.6, 0.0, 1500);
  // 0.6 for 1500 sessions: 0.8 for 2000.
  CHECK(budget.capacity() >= 1995);
  CHECK(budget.capacity() <= 2000);
  CHECK(budget.admits(1990));
  CHECK(!budget.admits(2000));
  CHECK(!budget.over_target());
}

TEST_CASE("admission: past the target the door closes below the sessions served, ending none", "[admission]") {
  AdmissionBudget budget(0.8);
  steady(budget, 1.0, 0.0, 1200);
  CHECK(budget.over_target());
  CHECK(budget.capacity() < 1200);  // no new session; the 1200 keep theirs (nothing here ends one)
  CHECK(budget.capacity() >= 900);
}

TEST_CASE("admission: waiting for a CPU counts three times", "[admission]") {
  AdmissionBudget alone(0.8);
  AdmissionBudget crowded(0.8);
  steady(alone, 0.6, 0.0, 1000);
  steady(crowded, 0.3, 0.3, 1000);  // the same share of wall time, half of it spent waiting
  CHECK(alone.busy_share() == Approx(crowded.busy_share()));
  CHECK(crowded.wait_share() == Approx(0.3).margin(0.001));
  CHECK(crowded.capacity() < alone.capacity());
  CHECK(crowded.load() == Approx(1.2).margin(0.002));  // 0.3 running + 3 x 0.3 waiting
  CHECK(crowded.over_target());
  CHECK(crowded.capacity() >= 660);  // 1000 x 0.8 / 1.2
  CHECK(crowded.capacity() <= 667);
}

TEST_CASE("admission: one slow second moves the capacity a little, a lasting load all the way", "[admission]") {
  AdmissionBudget budget(0.8);
  steady(budget, 0.3, 0.0, 500);
  budget.observe(LoadPeriod{0.95, 0.0, 1.0, 500});
  CHECK(budget.admits(600));  // smoothed 0.56: room for about 700
  steady(budget, 0.95, 0.0, 500);
  CHECK(!budget.admits(500));
}

TEST_CASE("admission: a handful of sessions never closes the door", "[admission]") {
  AdmissionBudget budget(0.8, 32);
  steady(budget, 1.0, 0.0, 5);  // a slow or shared machine with five viewers
  CHECK(budget.capacity() == 32);
  CHECK(budget.admits(31));
}

TEST_CASE("admission: the door opens again as the load falls", "[admission]") {
  AdmissionBudget budget(0.8);
  steady(budget, 1.0, 0.0, 1000);
  REQUIRE(!budget.admits(1000));
  steady(budget, 0.2, 0.0, 1000);
  CHECK(budget.admits(100000));
}

TEST_CASE("admission: work for connections that never said Hello does not close the door", "[admission]") {
  // 100 sessions cost 10 % of the thread; strangers churning connections take 70 % more and make it
  // wait 10 % for a CPU. Counted as session cost (main) that is a load of 1.1: no room at all.
  AdmissionBudget churned(0.85);
  for (int i = 0; i < 20; ++i) churned.observe(LoadPeriod{0.8, 0.1, 1.0, 100, 0.1});
  CHECK(churned.load() == Approx(1.1).margin(0.002));
  CHECK(churned.session_load() == Approx(1.1 / 8).margin(0.002));  // the waits shared out alike
  CHECK(churned.admits(110));
  CHECK(churned.capacity() == AdmissionBudget::kUnlimited);  // 0.14: far from the target
  // The same sessions costing the whole 80 % themselves close it as before.
  AdmissionBudget loaded(0.85);
  for (int i = 0; i < 20; ++i) loaded.observe(LoadPeriod{0.8, 0.1, 1.0, 100, 0.8});
  CHECK(!loaded.admits(100));
  CHECK(loaded.capacity() >= 75);  // 100 x 0.85 / 1.1
  CHECK(loaded.capacity() <= 78);
}
