// test_particle_flows.cpp: particles created and removed during a run (state/particle_flows.h):
// the inflow's count against its rate, no overlap at creation, the outflow's removals against
// the scheme's own trajectories, the energy balance with what the flows carry, and restart and
// thread-count bit identity across them.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>

#include "app/observers/energy_balance.h"
#include "case_errors.h"
#include "memory_archive.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/geometry/shapes.h"
#include "swarf/laws/hertz.h"
#include "swarf/simulation.h"

namespace swarf {
namespace {

// A stream: spheres of 0.4 to 0.6 mm created in a 10 x 10 x 2 mm box at 2e4 per second, moving
// down at 2 m/s; an outflow box below; gravity; Hertz contacts among them (a crowded box makes
// the placement work). 'contacts' off: they fly through each other.
World stream(bool contacts, bool gravity) {
  World w;
  w.rods.build_rows(0);
  Inflow f;
  f.box_min = Vec3(0.0, 0.0, 0.0);
  f.box_max = Vec3(10e-3, 10e-3, 2e-3);
  f.rate = 2e4;
  f.radius_min = 0.4e-3;
  f.radius_max = 0.6e-3;
  f.density = 2500;
  f.velocity = Vec3(0.1, 0.0, -2.0);
  f.seed = 7;
  f.overlap = 0.0;
  w.inflows.push_back(f);
  Outflow o;
  o.box_min = Vec3(-1.0, -1.0, -1.0);
  o.box_max = Vec3(1.0, 1.0, -10e-3);
  w.outflows.push_back(o);
  if (gravity) w.gravity = Vec3(0.0, 0.0, -9.81);
  w.contacts = contacts;
  w.contact.youngs_modulus = 1e8;
  w.contact.poisson_ratio = 0.3;
  w.contact.alpha = restitution_to_alpha(0.5);
  w.contact.skin = 0.1e-3;
  return w;
}

StepSettings verlet(double dt) {
  StepSettings s;
  s.dt = dt;
  return s;
}

// The inflow owes rate x h each step and creates what it owes unless a place cannot be found:
// created + missed = floor(rate t) exactly (a step's share is added before the count is
// taken; the fractional rest carries over). Every particle created in a step overlaps no other
// particle then. Some are missed in the crowded box, not all.
TEST(Flows, TheInflowCreatesAtItsRateAndNeverOverlaps) {
  World w = stream(true, false);
  const double h = 1e-6;
  Simulation sim(w, verlet(h));
  std::int64_t last_id = -1;
  for (int k = 0; k < 1000; ++k) {
    sim.step();
    const auto& p = w.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.id[i] <= last_id) continue;  // created in this step: check against everything
      for (std::size_t j = 0; j < p.size(); ++j)
        if (j != i) {
          const double d = (p.position[i] - p.position[j]).norm(), s = p.radius[i] + p.radius[j];
          ASSERT_GE(d, s * (1 - 1e-12)) << "particle " << p.id[i] << " created overlapping " << p.id[j];
        }
    }
    for (auto id : p.id) last_id = std::max(last_id, id);
  }
  const Inflow& f = w.inflows[0];
  // (1000 steps of 1e-6 s at 2e4 /s: 20 due; the owed sum is exact in binary to 1e-12)
  EXPECT_EQ(f.created + f.missed, static_cast<std::int64_t>(std::floor(2e4 * 1000 * h + 1e-9)));
  EXPECT_GT(f.created, 10);
  EXPECT_EQ(static_cast<std::int64_t>(w.particles.size()) + w.outflows[0].removed, f.created);
}

// Without contacts or gravity each particle moves by the scheme's x+ = x + h v: the outflow
// removes exactly the particles whose recurrence puts their centre in its box at a step's end,
// and no other.
// The stream without contacts falls at constant velocity; each particle's track by the scheme's
// own recurrence x+ = x + h v says when it enters the outflow region, and the particles the
// outflow removed must be exactly those (by id), whatever the region's form.
void expect_outflow_removes_what_enters(World w, const std::function<bool(const Vec3&)>& region) {
  w.inflows[0].rate = 5e4;
  w.inflows[0].velocity = Vec3(0.1, 0.0, -4.0);
  const double h = 1e-6;
  Simulation sim(w, verlet(h));
  struct Track {
    Vec3 x, v;
    bool gone = false;
  };
  std::map<std::int64_t, Track> tracks;  // by id: the test's own recurrence
  std::set<std::int64_t> expected_gone;
  for (int k = 0; k < 6000; ++k) {
    sim.step();
    for (auto& [id, t] : tracks)
      if (!t.gone) {
        t.x = t.x + h * t.v;
        if (region(t.x)) {
          t.gone = true;
          expected_gone.insert(id);
        }
      }
    const auto& p = w.particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!tracks.count(p.id[i])) tracks[p.id[i]] = Track{p.position[i], p.velocity[i]};
  }
  std::set<std::int64_t> present(w.particles.id.begin(), w.particles.id.end());
  std::int64_t gone = 0;
  for (const auto& [id, t] : tracks) {
    EXPECT_EQ(present.count(id) == 0, t.gone) << "particle " << id;
    gone += t.gone;
  }
  EXPECT_GT(gone, 50);  // (6 ms at 4 m/s: the first ones fell 24 mm)
  EXPECT_EQ(w.outflows[0].removed, gone);
}

TEST(Flows, TheOutflowRemovesExactlyWhatEntersIt) {
  expect_outflow_removes_what_enters(stream(false, false), [](const Vec3& x) { return x.z() <= -10e-3; });
}

// A plane outflow (a tilted floor, its normal of length 2: only the direction counts) removes
// what crosses it, wherever it crosses.
TEST(Flows, APlaneOutflowRemovesExactlyWhatCrossesIt) {
  World w = stream(false, false);
  const Vec3 point(0.0, 0.0, -8e-3), normal = 2.0 * Vec3(0.2, 0.0, -1.0).normalized();
  w.outflows[0].plane_point = point;
  w.outflows[0].plane_normal = normal;
  expect_outflow_removes_what_enters(w, [&](const Vec3& x) { return (x - point).dot(normal) > 0.0; });
}

// Falling spheres in and out: with no contacts and constant gravity velocity Verlet is exact,
// so the balance 0 = kinetic + potential - initial + flow_energy closes to rounding (1e-12 of
// the energy brought in); with contacts the contact work joins it, and the balance closes to
// the scheme's error (1e-4 of the energy that went through).
TEST(Flows, TheEnergyBalanceClosesWithWhatTheFlowsCarry) {
  for (const bool contacts : {false, true}) {
    World w = stream(contacts, true);
    Simulation sim(w, verlet(1e-6));
    double through = 0.0;  // J: the largest of the energy terms
    for (int k = 0; k < 12000; ++k) {
      sim.step();
      through = std::max({through, std::abs(sim.ledger().flow_energy), sim.kinetic_energy()});
    }
    ASSERT_GT(w.outflows[0].removed, 50);
    const EnergyLedger& L = sim.ledger();
    const double error = sim.kinetic_energy() + sim.potential_energy() + L.contact_work + L.flow_energy;
    EXPECT_NEAR(error, 0.0, (contacts ? 1e-4 : 1e-12) * through) << "contacts " << contacts;
  }
}

// Runs 'sim' for 'steps' steps with the run's energy check after each (as every series row
// does); returns the balance's error at the end, J, and in 'refused_before' the number of
// steps the check as it was before issue 37 (blind to what crossed the flows) would have
// stopped at. Throws the check's SimulationError.
double checked_error(Simulation& sim, int steps, int& refused_before, const std::function<void(int)>& before = {}) {
  EnergyBalance balance;
  balance.begin(sim);
  refused_before = 0;
  for (int k = 0; k < steps; ++k) {
    if (before) before(k);
    sim.step();
    EnergyBalanceNow b = balance.measure(sim);
    check_energy_balance(b, sim.time());
    b.flow_through = 0.0;
    try {
      check_energy_balance(b, sim.time());
    } catch (const SimulationError&) {
      ++refused_before;
    }
  }
  return balance.measure(sim).error;
}

// Issue 37 D: an outflow half-space that holds the inflow's box removes every new particle one
// step after it is created (the outflow runs first). At most rows nothing is held, and the
// error is the round-off of flow_energy's terms (1e-22 J), which the check compared with 0 J
// and stopped the run ("energy balance lost"). The ledger was right: in - out cancels to
// rounding (checked here to 1e-12 of what went through); the check now counts what crossed.
// With gravity (the terms do not cancel bit for bit), both schemes, with and without contacts.
TEST(Flows, AnOutflowHoldingTheInflowBoxIsNotABlowUp) {
  for (const bool newmark : {false, true})
    for (const bool contacts : {false, true}) {
      World w = stream(contacts, true);
      w.inflows[0].rate = 2e3;  // (one particle every 500 steps: most rows hold none)
      w.outflows[0].plane_point = Vec3(0.0, 0.0, 1.0);
      w.outflows[0].plane_normal = Vec3(0.0, 0.0, -1.0);  // (z < 1 m: the whole box)
      StepSettings set = verlet(1e-6);
      if (newmark) {
        set.scheme = Scheme::Newmark;
        set.dt_min = 1e-9;
        set.dt_max = 1e-6;
      }
      Simulation sim(w, set);
      double error = 0.0;
      int refused_before = 0;
      ASSERT_NO_THROW(error = checked_error(sim, 3000, refused_before))
          << "newmark " << newmark << " contacts " << contacts;
      EXPECT_GT(refused_before, 0) << "the case no longer shows the false blow-up";
      EXPECT_GE(w.inflows[0].created, 5);
      EXPECT_LE(w.inflows[0].created - w.outflows[0].removed, 1);  // (the last step's, if any)
      EXPECT_GT(sim.ledger().flow_through, 0.0);
      EXPECT_NEAR(error, 0.0, 1e-12 * sim.ledger().flow_through) << "newmark " << newmark << " contacts " << contacts;
    }
}

// Issue 37 item 4: an outflow that removes everything. A stream with contacts falls into the
// outflow; the inflow stops, and when the last particle has left nothing is held and no work
// was done: the error left is the scheme's (the contacts' collisions), which the check
// compared with 0 J (round-off here: it closes to 1e-16 J). Now it stays within what crossed
// the boundaries, and the run goes on.
TEST(Flows, AnOutflowThatRemovesEverythingIsNotABlowUp) {
  World w = stream(true, true);
  Simulation sim(w, verlet(1e-6));
  double error = 0.0;
  int refused_before = 0;
  ASSERT_NO_THROW(error = checked_error(sim, 14000, refused_before, [&](int k) {
                    if (k == 3000) w.inflows[0].rate = 0.0;
                  }));
  EXPECT_EQ(w.particles.size(), 0u);
  EXPECT_GT(w.outflows[0].removed, 30);
  EXPECT_EQ(w.outflows[0].removed, w.inflows[0].created);
  EXPECT_GT(refused_before, 0) << "the case no longer shows the false blow-up";
  // (within the scheme's error with contacts, as in TheEnergyBalanceClosesWithWhatTheFlowsCarry)
  EXPECT_LT(std::abs(error), 1e-4 * sim.ledger().flow_through);
}

// A checkpoint taken while particles come and go, loaded into a simulation of the World as it
// started (no particles), continues to the same bits; and the same on 1 and 2 threads.
TEST(Flows, RestartAndThreadsGiveTheSameBitsAcrossTheFlows) {
  const StepSettings set = verlet(1e-6);
  World a = stream(true, true);
  Simulation one(a, set);
  for (int k = 0; k < 7000; ++k) one.step();
  ASSERT_GT(a.outflows[0].removed, 0);
  test::MemoryArchive ar;
  one.visit_state(ar);
  for (int k = 0; k < 3000; ++k) one.step();
  World b = stream(true, true);
  Simulation two(b, set);
  ar.set_loading(true);
  two.visit_state(ar);
  for (int k = 0; k < 3000; ++k) two.step();
  EXPECT_EQ(one.state_hash(), two.state_hash());
  EXPECT_EQ(a.inflows[0].created, b.inflows[0].created);
  EXPECT_EQ(a.particles.id, b.particles.id);

  const int saved = omp_get_max_threads();
  std::uint64_t hash[2];
  for (int t = 1; t <= 2; ++t) {
    omp_set_num_threads(t);
    World w = stream(true, true);
    Simulation sim(w, set);
    for (int k = 0; k < 10000; ++k) sim.step();
    hash[t - 1] = sim.state_hash();
  }
  omp_set_num_threads(saved);
  EXPECT_EQ(hash[0], hash[1]);
  EXPECT_EQ(hash[0], one.state_hash());
}

TEST(Flows, BadRegionsAreRefused) {
  const auto refused = [](auto change) {
    World w = stream(false, false);
    change(w);
    EXPECT_THROW(Simulation(w, verlet(1e-6)), InputError);
  };
  refused([](World& w) { w.inflows[0].rate = -1.0; });
  refused([](World& w) { w.inflows[0].radius_min = 0.0; });
  refused([](World& w) { w.inflows[0].radius_max = 0.1e-3; });  // below radius_min
  refused([](World& w) { w.inflows[0].density = NAN; });
  refused([](World& w) { w.inflows[0].overlap = 1.0; });
  refused([](World& w) { w.inflows[0].box_max = Vec3(-1.0, 1.0, 1.0); });
  refused([](World& w) { w.outflows[0].box_min = Vec3(HUGE_VAL, 0.0, 0.0); });
  refused([](World& w) {
    w.outflows[0].plane_normal = Vec3(0.0, 0.0, -1.0);
    w.outflows[0].plane_point = Vec3(NAN, 0.0, 0.0);
  });
}

// [[inflow]] and [[outflow]] in a case: an inflow alone is a case; its keys reach the World
// (the density is the material's); the step and the skin take its radii into account; bad
// keys are refused by name.
TEST(FlowCase, InflowAndOutflowTablesBuildTheWorldsRegions) {
  const std::string text =
      "[material]\ndensity = 2500.0\n[contact]\nyoungs_modulus = 1e8\n"
      "[[inflow]]\nbox_min = [0.0, 0.0, 0.0]\nbox_max = [0.01, 0.01, 0.002]\nrate = 2e4\nradius_min = 0.4e-3\n"
      "radius_max = 0.6e-3\nvelocity = [0.0, 0.0, -2.0]\nseed = 7\n"
      "[[outflow]]\nbox_min = [-1.0, -1.0, -1.0]\nbox_max = [1.0, 1.0, -0.01]\n"
      "[integrator]\nscheme = \"verlet\"\nend_time = 1e-3\n";
  const Model m = build_model(parse_case(text, "flows.toml", {}));
  ASSERT_EQ(m.inflows.size(), 1u);
  ASSERT_EQ(m.outflows.size(), 1u);
  EXPECT_EQ(m.particles.size(), 0u);
  EXPECT_EQ(m.inflows[0].density, 2500.0);
  EXPECT_EQ(m.inflows[0].radius_max, 0.6e-3);
  EXPECT_EQ(m.inflows[0].seed, 7u);
  EXPECT_EQ(m.outflows[0].box_max, Vec3(1.0, 1.0, -0.01));
  EXPECT_EQ(m.derived.radius, 0.4e-3);  // (the stable step's radius: the inflow's smallest)
  EXPECT_GT(m.contact.skin, 0.0);       // (from the inflow's largest radius: no particle at the start)
  const auto refused = [&](const std::vector<std::string>& set, std::initializer_list<std::string> words) {
    test::expect_mentions(test::case_error(text, set, "flows.toml"), words);
  };
  refused({"inflow.0.radius_max=0.3e-3"}, {"inflow.radius_max", ">= radius_min"});
  refused({"inflow.0.box_max=[0.01, -0.01, 0.002]"}, {"inflow.box_max", ">= box_min"});
  refused({"inflow.0.rate=-1.0"}, {"inflow.rate"});
  refused({"outflow.0.box_max=[1.0, -2.0, 1.0]"}, {"outflow.box_max"});
  refused({"inflow.0.overlap=1.0"}, {"inflow.overlap"});
  refused({"inflow.0.mass_rate=0.1"}, {"inflow.rate", "mass_rate both given"});
  refused({"outflow.0.plane_normal=[0.0, 0.0, -1.0]"}, {"outflow.box_min", "not with a plane"});

  // A mass rate: rate = mass_rate / (4/3 pi rho E[R^3]), E[R^3] = (b^4 - a^4) / (4 (b - a)) for radii
  // uniform in [a, b] (to rounding, 1e-14).
  std::string by_mass = text;
  by_mass.replace(by_mass.find("rate = 2e4"), 10, "mass_rate = 0.05");
  const std::string box = "box_min = [-1.0, -1.0, -1.0]\nbox_max = [1.0, 1.0, -0.01]";
  by_mass.replace(by_mass.find(box), box.size(), "plane_point = [0.0, 0.0, -0.01]\nplane_normal = [0.0, 0.0, -3.0]");
  const Model mm = build_model(parse_case(by_mass, "flows.toml", {}));
  const double a = 0.4e-3, b = 0.6e-3, r3 = (std::pow(b, 4) - std::pow(a, 4)) / (4 * (b - a));
  EXPECT_NEAR(mm.inflows[0].rate / (0.05 / (4.0 / 3.0 * std::numbers::pi * 2500 * r3)), 1.0, 1e-14);
  EXPECT_EQ(mm.outflows[0].plane_normal, Vec3(0.0, 0.0, -1.0));  // (normalised)
  EXPECT_EQ(mm.outflows[0].plane_point, Vec3(0.0, 0.0, -0.01));
  EXPECT_FALSE(mm.outflows[0].contains(Vec3(5.0, 5.0, -0.0099)));
  EXPECT_TRUE(mm.outflows[0].contains(Vec3(5.0, 5.0, -0.0101)));
  const auto refused_by_mass = [&](const std::vector<std::string>& set, std::initializer_list<std::string> words) {
    test::expect_mentions(test::case_error(by_mass, set, "flows.toml"), words);
  };
  refused_by_mass({"outflow.0.plane_normal=[0.0, 0.0, 0.0]"}, {"outflow.plane_normal", "not be zero"});
  refused_by_mass({"inflow.0.mass_rate=-1.0"}, {"inflow.mass_rate"});
  // A cut's analysis takes the workpiece as the first particles: removals are refused there.
  test::expect_mentions(test::case_error(std::string(kDefaultCutTableToml) +
                                             "[[outflow]]\nbox_min = [-1.0, -1.0, -1.0]\nbox_max = [1.0, 1.0, -0.5]\n",
                                         {}, "cut.toml"),
                        {"cut.toml", "[[outflow]]", "cutting run"});
}

}  // namespace
}  // namespace swarf
