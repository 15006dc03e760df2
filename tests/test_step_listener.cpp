// test_step_listener.cpp: the engine's hook around each step (swarf/step_listener.h).
#include <gtest/gtest.h>

#include "scenes/pulled_bar.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// A bonded bar pulled at one end (Newmark: rejected tries happen inside a step, not between).
const std::string kBar = test::pulled_bar_case(
    {.cells = {8, 2, 2}, .velocity = 5.0, .integrator = "scheme = \"newmark\"\nend_time = 1"});

struct Recorder final : StepListener {
  std::vector<double> before, after;
  void before_step(Simulation& sim) override { before.push_back(sim.time()); }
  void after_step(Simulation& sim) override { after.push_back(sim.time()); }
};

TEST(StepListener, IsCalledOnceBeforeAndAfterEveryAcceptedStepWithTheStepsTimes) {
  Model m = build_model(parse_case(kBar, "bar", {}));
  Simulation sim(m, m.step);
  Recorder rec;
  sim.add_listener(&rec);
  std::vector<double> ends;
  for (int s = 0; s < 40; ++s) {
    sim.step();
    ends.push_back(sim.time());
  }
  ASSERT_EQ(rec.before.size(), 40u);
  ASSERT_EQ(rec.after.size(), 40u);
  EXPECT_EQ(rec.before[0], 0.0);
  for (std::size_t k = 0; k < 40; ++k) {
    EXPECT_EQ(rec.after[k], ends[k]);
    if (k > 0) {
      EXPECT_EQ(rec.before[k], ends[k - 1]);  // the time the step starts from
    }
  }
  sim.remove_listener(&rec);
  sim.step();
  EXPECT_EQ(rec.after.size(), 40u);
}

// A listener that does nothing leaves every bit of the state as it was without it.
TEST(StepListener, APassiveListenerChangesNoBit) {
  Model a = build_model(parse_case(kBar, "bar", {})), b = build_model(parse_case(kBar, "bar", {}));
  Simulation sa(a, a.step), sb(b, b.step);
  Recorder rec;
  sb.add_listener(&rec);
  for (int s = 0; s < 200; ++s) {
    sa.step();
    sb.step();
  }
  EXPECT_EQ(sa.state_hash(), sb.state_hash());
}

// Co-simulation in its simplest form: before each step a listener sets the pulled group's
// motion (a velocity chosen from outside); the bar then follows that motion, not the case's.
TEST(StepListener, BeforeStepCanSetAGroupsMotionForTheNextStep) {
  Model m = build_model(parse_case(kBar, "bar", {}));
  Simulation sim(m, m.step);
  const std::size_t right = 1;
  ASSERT_EQ(m.groups[right].name, "right");
  struct Driver final : StepListener {
    World* w;
    std::size_t g;
    void before_step(Simulation& sim) override {
      // Hold the end where it is from t = 0 on: a Fixed motion displaces nothing.
      w->groups[g].motion = Motion{};
    }
  } driver;
  driver.w = &m;
  driver.g = right;
  sim.add_listener(&driver);
  for (int s = 0; s < 50; ++s) sim.step();
  const auto i = m.groups[right].members.front();
  EXPECT_EQ(m.particles.position[i][0], m.particles.initial_position[i][0]);
}

}  // namespace
}  // namespace swarf
