// test_contacts.cpp: circle-triangle overlap area against closed forms and Monte Carlo; a
// flat surface pushes the same however it is triangulated; Hertz impacts against the closed
// form; restitution; sticking and sliding friction; the neighbour search against brute force.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "io/mesh_file.h"
#include "scenes/block_on_floor.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/contacts/contacts.h"
#include "swarf/core/errors.h"
#include "swarf/geometry/overlap_area.h"
#include "swarf/simulation.h"
#include "swarf/state/mesh.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// ---- overlap area -------------------------------------------------------------------------

// Closed forms are exact up to rounding of atan2 and square roots: 1e-12 relative.
constexpr double kAreaTol = 1e-12;

TEST(OverlapArea, CircleInsideTriangle) {
  const double r = 0.3;
  EXPECT_NEAR(circle_triangle_area(Vec2(-5, -5), Vec2(5, -5), Vec2(0, 5), r), M_PI * r * r, kAreaTol);
}

TEST(OverlapArea, TheWholeDiscShortcutJoinsTheWedgeSumAtAnEdge) {
  // A circle clear of every edge takes a shortcut (pi r^2, no wedges). Moved across the
  // line where it starts to touch an edge (distance r +- 1e-9 r), either winding, the area
  // is continuous: the wedge sum just inside the shortcut's limit differs from pi r^2 by the
  // cut segment, ~ (4 sqrt(2)/3) r^2 (1e-9)^1.5 < 1e-13 r^2, and rounding (1e-12 relative).
  const double r = 0.25;
  for (const double gap : {1e-9, -1e-9}) {
    const double y = -1.0 + r * (1.0 + gap);  // the centre's distance r (1 + gap) from the edge y = -1
    const Vec2 a(-4.0, -1.0 - y), b(4.0, -1.0 - y), c(0.0, 5.0 - y);
    for (const double area : {circle_triangle_area(a, b, c, r), circle_triangle_area(a, c, b, r)})
      EXPECT_NEAR(area, M_PI * r * r, 1e-12 * M_PI * r * r) << "gap " << gap;
  }
  // Outside the triangle, r away from an edge: no overlap (the shortcut must not take it).
  EXPECT_NEAR(circle_triangle_area(Vec2(-4, 1), Vec2(4, 1), Vec2(0, 7), 0.5), 0.0, kAreaTol);
  EXPECT_NEAR(circle_triangle_area(Vec2(-4, 1), Vec2(0, 7), Vec2(4, 1), 0.5), 0.0, kAreaTol);
}

TEST(OverlapArea, TriangleInsideCircle) {
  EXPECT_NEAR(circle_triangle_area(Vec2(0.1, 0.1), Vec2(0.5, 0.1), Vec2(0.1, 0.4), 1.0), 0.5 * 0.4 * 0.3, kAreaTol);
}

TEST(OverlapArea, CentreOnAnEdgeGivesHalfTheCircle) {
  EXPECT_NEAR(circle_triangle_area(Vec2(-5, 0), Vec2(5, 0), Vec2(0, 7), 0.5), 0.5 * M_PI * 0.25, kAreaTol);
}

TEST(OverlapArea, CentreOnARightAngledVertexGivesAQuarter) {
  EXPECT_NEAR(circle_triangle_area(Vec2(0, 0), Vec2(9, 0), Vec2(0, 9), 1.0), 0.25 * M_PI, kAreaTol);
}

TEST(OverlapArea, OneEdgeCutsACircularSegment) {
  // A huge triangle whose edge y = h cuts the circle: the part below the chord is inside.
  const double r = 1.0, h = 0.4;
  const double segment = r * r * std::acos(h / r) - h * std::sqrt(r * r - h * h);  // area above the chord
  EXPECT_NEAR(circle_triangle_area(Vec2(-50, h), Vec2(50, h), Vec2(0, -80), r), M_PI * r * r - segment, kAreaTol);
}

TEST(OverlapArea, VertexInsideWithTwoEdgesCutting) {
  // Wedge of 60 degrees with its apex at distance 0.5 from the centre on the x axis, opening
  // away from the centre: compare with a fine polar integration (1e-7 relative).
  const double r = 1.0;
  const Vec2 apex(0.5, 0.0);
  const Vec2 b = apex + 10.0 * Vec2(std::cos(M_PI / 6), std::sin(M_PI / 6));
  const Vec2 c = apex + 10.0 * Vec2(std::cos(-M_PI / 6), std::sin(-M_PI / 6));
  const double got = circle_triangle_area(apex, b, c, r);
  // Integrate over x: the wedge between the lines y = +-(x - 0.5) tan 30, inside the circle.
  const int n = 2000000;
  double sum = 0.0;
  const double t = std::tan(M_PI / 6);
  for (int k = 0; k < n; ++k) {
    const double x = 0.5 + (k + 0.5) * (0.5 / n);
    const double half = std::min((x - 0.5) * t, std::sqrt(std::max(0.0, r * r - x * x)));
    sum += 2.0 * half * (0.5 / n);
  }
  EXPECT_NEAR(got, sum, 1e-7 * sum);
}

TEST(OverlapArea, MatchesMonteCarloOnRandomTriangles) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng));
    const double r = 1.0;
    const double exact = circle_triangle_area(a, b, c, r);
    // Monte Carlo over the circle's bounding square: the standard error is
    // sqrt(p (1-p) / N) * 4 r^2; 200000 samples give at most 4.5e-3; allow 5 sigma.
    const int N = 200000;
    int hits = 0;
    auto side = [](const Vec2& p, const Vec2& q, const Vec2& x) {
      return (q[0] - p[0]) * (x[1] - p[1]) - (q[1] - p[1]) * (x[0] - p[0]);
    };
    std::uniform_real_distribution<double> s(-r, r);
    for (int k = 0; k < N; ++k) {
      const Vec2 x(s(rng), s(rng));
      if (x.squaredNorm() > r * r) continue;
      const double d1 = side(a, b, x), d2 = side(b, c, x), d3 = side(c, a, x);
      if ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0)) ++hits;
    }
    const double p = double(hits) / N, mc = 4.0 * r * r * p;
    const double sigma = 4.0 * r * r * std::sqrt(std::max(p * (1 - p), 1e-12) / N);
    EXPECT_NEAR(exact, mc, 5 * sigma + 1e-12) << "trial " << trial;
  }
}

// ---- flat surfaces, however triangulated --------------------------------------------------

// A square [-L, L]^2 in z = 0 made of 2 triangles, or of an irregular triangulation: a grid
// whose interior vertices are jittered in the plane.
TriangleMesh square(int n, double jitter, unsigned seed) {
  TriangleMesh m;
  m.name = "square";
  const double L = 0.01;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int b = 0; b <= n; ++b)
    for (int a = 0; a <= n; ++a) {
      double x = -L + 2 * L * a / n, y = -L + 2 * L * b / n;
      if (a > 0 && a < n && b > 0 && b < n) {
        x += u(rng) * 2 * L / n;
        y += u(rng) * 2 * L / n;
      }
      m.vertices.emplace_back(x, y, 0.0);
    }
  auto id = [&](int a, int b) { return b * (n + 1) + a; };
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      // Alternate the diagonal so the triangulation is irregular in shape too.
      if ((a + b) % 2) {
        m.triangles.push_back({id(a, b), id(a + 1, b), id(a + 1, b + 1)});
        m.triangles.push_back({id(a, b), id(a + 1, b + 1), id(a, b + 1)});
      } else {
        m.triangles.push_back({id(a, b), id(a + 1, b), id(a, b + 1)});
        m.triangles.push_back({id(a + 1, b), id(a + 1, b + 1), id(a, b + 1)});
      }
    }
  m.validate("square");
  return m;
}

// The force on one sphere (radius 1 mm) at 'centre' pressed into the mesh, with a velocity.
Vec3 force_on_sphere(const TriangleMesh& mesh, const Vec3& centre, const Vec3& velocity,
                     const StickingRule& sticking = {}, double temperature = 0.0,
                     const SpeedFriction& tool_friction = {}) {
  Particles p;
  p.resize(1);
  p.temperature[0] = temperature;
  p.position[0] = centre;
  p.velocity[0] = velocity;
  p.radius[0] = 1e-3;
  p.mass[0] = 3e-5;
  p.inv_mass[0] = 1.0 / p.mass[0];
  Rods rods;
  rods.build_rows(1);
  std::vector<MeshBody> meshes(1);
  meshes[0].name = "square";
  meshes[0].mesh = mesh;
  meshes[0].youngs_modulus = kInf;
  meshes[0].poisson_ratio = 0.3;
  ContactParams prm;
  prm.youngs_modulus = 70e9;
  prm.poisson_ratio = 0.3;
  prm.alpha = restitution_to_alpha(0.7);
  prm.friction = 0.3;
  prm.law = FrictionLaw::Spring;
  prm.skin = 2e-4;
  prm.sticking = sticking;
  prm.tool_friction = tool_friction;
  ContactSystem cs;
  cs.setup(prm, 1, &meshes);
  cs.update_lists(p, rods, true);
  cs.evaluate(p, 1e-7);
  Vec3 f = Vec3::Zero(), tau = Vec3::Zero();
  cs.add_to_particle(0, p.radius[0], f, tau);
  return f;
}

// The sticking cap (laws/sticking.h): a sphere sliding fast over a face (the spring law
// saturated) passes Coulomb's mu fn, or the cap 4 R^2 k0 Theta(T) where that is smaller, with
// Theta = 1 - T*^m (floored at 1e-3). Here k0 is set so that the cap is 1/3 of mu fn cold;
// the force's direction stays against the slip. Tolerance: round-off (1e-12).
TEST(Sticking, TheCapTakesOverWhereMuTimesThePressureExceedsTheShearStrength) {
  const TriangleMesh m = square(4, 0.0, 1);
  const Vec3 centre(2.5e-3, 2.5e-3, 1e-3 - 2e-6), slide(50.0, 0.0, 0.0);  // (on a diagonal: two triangles share it)
  const Vec3 free = force_on_sphere(m, centre, slide);
  const double fn = free.z(), ft = std::hypot(free.x(), free.y());
  ASSERT_GT(fn, 0.0);
  EXPECT_NEAR(ft, 0.3 * fn, 1e-12 * fn);  // (saturated: Coulomb)
  const double R = 1e-3;
  StickingRule s{.shear_strength = 0.1 * fn / (4.0 * R * R),
                 .softening_exponent = 2.0,
                 .melt_temperature = 1693.15,
                 .reference_temperature = 293.15};
  for (const auto& [T, theta] : std::vector<std::pair<double, double>>{
           {0.0, 1.0}, {293.15, 1.0}, {993.15, 0.75}, {1693.15, 1e-3}, {2500.0, 1e-3}}) {
    const Vec3 f = force_on_sphere(m, centre, slide, s, T);
    EXPECT_NEAR(f.z(), fn, 1e-12 * fn) << T;
    EXPECT_NEAR(-f.x(), 0.1 * fn * theta, 1e-12 * fn) << T;
    EXPECT_NEAR(f.y(), 0.0, 1e-12 * fn) << T;
  }
  // Above Coulomb (a strong material, cold) the cap does not bind.
  s.shear_strength = 10.0 * fn / (4.0 * R * R);
  const Vec3 strong = force_on_sphere(m, centre, slide, s, 293.15);
  EXPECT_NEAR(-strong.x(), 0.3 * fn, 1e-12 * fn);
}

// The flow zone (sticking.h): the cap is read at the face's temperature T + b tau, b = f R v_s,
// so tau is the root of tau = k0 Theta(T + b tau). Checked against a value worked by hand for
// m = 1 (the closed form), against the defining equation for m = 1 and m = 0.8 (the bisection,
// to a relative 1e-12: round-off of a root of a monotone function), and at its limits: no slip
// or no rise gives the cold cap, a face at the melting point the floor, and the cap falls as the
// slip grows.
TEST(Sticking, TheFlowZoneSolvesTheCapAtTheFacesOwnTemperature) {
  StickingRule s{.shear_strength = 666.2e6, .softening_exponent = 1.0, .melt_temperature = 1733.0};
  // By hand: u = (800 - 293.15)/1439.85 = 0.3520158, k0 b/span = 666.2/1439.85 = 0.4626871,
  // tau = 666.2 MPa (1 - u)/(1 + 0.4626871) = 295.1329 MPa (to the 7 digits given: 1 kPa).
  EXPECT_NEAR(flow_zone_strength(s, 800.0, 1e-6), 295.1329e6, 1e3);
  for (double m : {1.0, 0.8}) {
    s.softening_exponent = m;
    for (double T : {250.0, 293.15, 600.0, 1200.0})
      for (double b : {1e-8, 1e-7, 1e-6, 1e-5}) {
        const double tau = flow_zone_strength(s, T, b);
        EXPECT_NEAR(tau, s.shear_strength * sticking_softening(s, T + b * tau), 1e-12 * s.shear_strength)
            << "m " << m << " T " << T << " b " << b;
        EXPECT_LE(tau, s.shear_strength * sticking_softening(s, T)) << "m " << m << " T " << T << " b " << b;
      }
    EXPECT_EQ(flow_zone_strength(s, 900.0, 0.0), s.shear_strength * sticking_softening(s, 900.0));
    EXPECT_NEAR(flow_zone_strength(s, 1733.0, 1e-6), 1e-3 * s.shear_strength, 1e-12 * s.shear_strength);
  }
  // Through the contact: a sphere (R = 1 mm) sliding at 50 m/s over a face at 900 K, the cap well
  // below Coulomb's mu fn: its friction is 4 R^2 tau at the face's temperature, with f chosen so
  // that the rise is large (b k0 = half the span to melting: tau = k0 (1 - u)/1.5, two thirds of
  // the cold cap); the same sphere without the flow zone passes the cap at the particle's
  // temperature.
  const TriangleMesh mesh = square(4, 0.0, 1);
  const Vec3 centre(2.5e-3, 2.5e-3, 1e-3 - 2e-6), slide(50.0, 0.0, 0.0);
  const Vec3 free = force_on_sphere(mesh, centre, slide);
  const double R = 1e-3, fn = free.z();
  StickingRule c{.shear_strength = 0.1 * fn / (4.0 * R * R), .softening_exponent = 1.0, .melt_temperature = 1733.0};
  const Vec3 cold = force_on_sphere(mesh, centre, slide, c, 900.0);
  EXPECT_NEAR(-cold.x(), 4.0 * R * R * c.shear_strength * sticking_softening(c, 900.0), 1e-12 * fn);
  c.flow_zone = 0.5 * (c.melt_temperature - c.reference_temperature) / c.shear_strength / (R * 50.0);
  const double b = c.flow_zone * R * 50.0;
  const Vec3 hot = force_on_sphere(mesh, centre, slide, c, 900.0);
  EXPECT_NEAR(-hot.x(), 4.0 * R * R * flow_zone_strength(c, 900.0, b), 1e-12 * fn);
  EXPECT_NEAR(-hot.x(), -cold.x() / 1.5, 1e-12 * fn);
  EXPECT_NEAR(hot.z(), fn, 1e-12 * fn);
  // Standing still on the face the flow zone is not heated: the cold cap (the spring law's force
  // is then below it; checked on the cap itself).
  EXPECT_EQ(sticking_cap(c, R, 900.0, 0.0), 4.0 * R * R * c.shear_strength * sticking_softening(c, 900.0));
  EXPECT_LT(sticking_cap(c, R, 900.0, 100.0), sticking_cap(c, R, 900.0, 50.0));
}

// The tool's friction against the sliding speed (speed_friction.h): the table's value by linear
// interpolation between its points and constant outside, checked at worked values; through the
// contact, a sphere sliding over a face (the spring law saturated at every speed used) passes
// mu(|v_t|) fn against its slip, whatever mu the sphere-sphere contacts have (0.3 here), and
// the normal force does not change. Tolerance: round-off (1e-12 relative).
TEST(Friction, TheToolsCoefficientFollowsItsTableOfSlidingSpeeds) {
  SpeedFriction c;
  EXPECT_EQ(friction_at_speed(c, 0.3, 40.0), 0.3);  // (no table: the constant)
  c.points = 3;
  c.speed = {20.0, 60.0, 80.0};
  c.mu = {0.6, 0.2, 0.1};
  for (const auto& [s, mu] : std::vector<std::pair<double, double>>{
           {0.0, 0.6}, {10.0, 0.6}, {20.0, 0.6}, {40.0, 0.4}, {50.0, 0.3}, {60.0, 0.2}, {70.0, 0.15}, {1e3, 0.1}})
    EXPECT_NEAR(friction_at_speed(c, 0.3, s), mu, 1e-15) << s;
  const TriangleMesh m = square(4, 0.0, 1);
  const Vec3 centre(2.5e-3, 2.5e-3, 1e-3 - 2e-6);
  const double fn = force_on_sphere(m, centre, Vec3(50.0, 0.0, 0.0)).z();
  ASSERT_GT(fn, 0.0);
  for (double s : {10.0, 40.0, 50.0, 100.0}) {
    const Vec3 f = force_on_sphere(m, centre, Vec3(s, 0.0, 0.0), {}, 0.0, c);
    EXPECT_NEAR(f.z(), fn, 1e-12 * fn) << s;
    EXPECT_NEAR(-f.x(), friction_at_speed(c, 0.3, s) * fn, 1e-12 * fn) << s;
    EXPECT_NEAR(f.y(), 0.0, 1e-12 * fn) << s;
  }
}

TEST(FlatSurface, SameForceHoweverTriangulated) {
  const TriangleMesh two = square(1, 0.0, 1), many = square(16, 0.3, 5);
  ASSERT_EQ(two.triangles.size(), 2u);
  ASSERT_EQ(many.triangles.size(), 512u);
  const double delta = 2e-6;         // m
  const Vec3 v(0.02, -0.01, -0.05);  // m/s: normal damping and tangential slip both act
  // Over the middle of a face, over the 2-triangle diagonal, over a vertex and an edge of the
  // irregular mesh (its vertex nearest the centre), and a general point.
  std::vector<Vec2> spots{{0.0031, -0.0042}, {0.0, 0.0}, {0.0021, 0.0021}, {-0.0057, 0.0013}};
  double nearest = 1e9;
  Vec2 vertex(0, 0);
  for (const auto& x : many.vertices)
    if (Vec2(x[0], x[1]).norm() < nearest && std::abs(x[0]) < 0.009 && x[0] != 0.0) {
      nearest = Vec2(x[0], x[1]).norm();
      vertex = Vec2(x[0], x[1]);
    }
  spots.push_back(vertex);
  const auto& tri = many.triangles[100];
  const Vec3 mid = 0.5 * (many.vertices[tri[0]] + many.vertices[tri[1]]);
  spots.emplace_back(mid[0], mid[1]);
  for (const auto& s : spots) {
    const Vec3 c(s[0], s[1], 1e-3 - delta);
    const Vec3 f2 = force_on_sphere(two, c, v), fn = force_on_sphere(many, c, v);
    ASSERT_GT(f2[2], 0.0);
    EXPECT_LT((f2 - fn).norm(), 1e-9 * f2.norm())
        << "at " << s.transpose() << ": " << f2.transpose() << " vs " << fn.transpose();
  }
}

TEST(FlatSurface, NormalForceIsHertzOnARigidPlane) {
  // At rest: F = 4/3 E/(1 - nu^2) sqrt(R) delta^(3/2) (rigid wall, the convention of hertz.h).
  const double delta = 2e-6;
  const Vec3 f = force_on_sphere(square(4, 0.2, 3), Vec3(0.001, 0.002, 1e-3 - delta), Vec3::Zero());
  const double want = 4.0 / 3.0 * 70e9 / (1 - 0.09) * std::sqrt(1e-3) * std::pow(delta, 1.5);
  EXPECT_NEAR(f[2], want, 1e-9 * want);
  EXPECT_NEAR(f[0], 0.0, 1e-12 * want);
}

// ---- impacts ------------------------------------------------------------------------------

std::string two_spheres(double v, double restitution, double dt) {
  return fmt::format(R"([material]
density = 2800.0
[[particle]]
position = [0.0, 0.0, 0.0]
velocity = [{v}, 0.0, 0.0]
radius = 0.01
[[particle]]
position = [0.0201, 0.0, 0.0]
velocity = [-{v}, 0.0, 0.0]
radius = 0.01
[contact]
youngs_modulus = 48e9
poisson_ratio = 0.2
restitution = {e}
friction = 0.0
[integrator]
scheme = "verlet"
dt = {dt:.17g}
end_time = 1e-4
)",
                     fmt::arg("v", v), fmt::arg("e", restitution), fmt::arg("dt", dt));
}

TEST(Impact, TwoSpheresMatchTheHertzClosedForm) {
  // Chung and Ooi test 1 (glass): R = 0.01 m, E = 48 GPa, nu = 0.2, rho = 2800, 10 m/s each.
  const double v = 10.0;
  const std::string text = two_spheres(v, 1.0, 2e-8);
  Model m = build_model(parse_case(text, "impact", {}));
  Simulation sim(m, m.step);
  const double R = 0.01, E = 48e9, nu = 0.2, mass = m.particles.mass[0];
  const double Es = E / (2 * (1 - nu * nu)), Rs = R / 2, ms = mass / 2, vr = 2 * v;
  const double dmax = std::pow(15 * ms * vr * vr / (16 * Es * std::sqrt(Rs)), 0.4);
  const double fmax = 4.0 / 3.0 * Es * std::sqrt(Rs) * std::pow(dmax, 1.5);
  const double tc = 2.868 * std::pow(ms * ms / (Es * Es * Rs * vr), 0.2);
  double peak_f = 0, peak_d = 0, t_on = -1, t_off = -1;
  for (int k = 0; k < 5000 && t_off < 0; ++k) {
    sim.step();
    const double d = 2 * R - (m.particles.position[1] - m.particles.position[0]).norm();
    if (d > 0 && t_on < 0) t_on = sim.time();
    if (d <= 0 && t_on >= 0) t_off = sim.time();
    peak_d = std::max(peak_d, d);
    peak_f = std::max(peak_f, m.particles.force[1][0]);
  }
  // Step 20 ns against a contact time near 50 us: discretisation errors well below 0.5 %.
  EXPECT_NEAR(peak_d, dmax, 5e-3 * dmax);
  EXPECT_NEAR(peak_f, fmax, 5e-3 * fmax);
  EXPECT_NEAR(t_off - t_on, tc, 5e-3 * tc);
  // Elastic: the spheres leave with the speed they came with.
  EXPECT_NEAR(m.particles.velocity[1][0], v, 1e-3 * v);
}

TEST(Impact, RestitutionIsTheSameAtEverySpeed) {
  for (double e : {0.3, 0.8}) {
    for (double v : {0.5, 5.0}) {
      const std::string text = two_spheres(v, e, 5e-8);
      Model m = build_model(parse_case(text, "e", {}));
      Simulation sim(m, m.step);
      // The gap of 0.1 mm closes at 2 v; the contact lasts below 0.2 ms at these speeds.
      while (sim.time() < 1e-4 / (2 * v) + 3e-4) sim.step();
      const double rebound = (m.particles.velocity[1][0] - m.particles.velocity[0][0]) / (2 * v);
      // alpha(e) is solved to 1e-15 by bisection on an RK4 solution of the dimensionless
      // impact; the simulation's own discretisation adds < 0.5 %.
      EXPECT_NEAR(rebound, e, 5e-3) << "e " << e << " v " << v;
    }
  }
}

// ---- friction: a block on a tilted floor ---------------------------------------------------

// A bonded block (2 x 2 x 1 cells, 16 particles) on a floor, gravity tilted by 'angle'
// (tests/scenes/block_on_floor.h), stepped explicitly.
Model block_on_floor(double angle, double mu, const std::string& law) {
  test::BlockOnFloor b;
  b.angle = angle;
  b.mu = mu;
  b.law = law;
  b.integrator = "scheme = \"verlet\"\nend_time = 1";
  return build_model(parse_case(test::block_on_floor_case(b), "block", {}));
}

double mean_x(const Model& m) { return test::mean_x(m.particles.position); }

TEST(Friction, SpringHoldsBelowTheFrictionAngleAndSlidesAbove) {
  const double mu = 0.4, g = 9.81, T = 0.02;
  for (const double ratio : {0.5, 1.6}) {
    const double angle = std::atan(ratio * mu);
    Model m = block_on_floor(angle, mu, "spring");
    Simulation sim(m, m.step);
    const double x0 = mean_x(m);
    while (sim.time() < T) sim.step();
    const double moved = mean_x(m) - x0;
    if (ratio < 1) {
      // Sticking: only the elastic tangential springs give (micrometres at most).
      EXPECT_LT(std::abs(moved), 2e-6) << "moved " << moved;
    } else {
      // Sliding: x = a t^2 / 2 with a = g (sin - mu cos); the block settles onto the floor in
      // the first milliseconds, so allow 10 %.
      const double a = g * (std::sin(angle) - mu * std::cos(angle));
      EXPECT_NEAR(moved, 0.5 * a * T * T, 0.1 * 0.5 * a * T * T);
    }
  }
}

TEST(Friction, RegularizedLawSlidesAboveTheFrictionAngle) {
  const double mu = 0.4, g = 9.81, T = 0.02, angle = std::atan(1.6 * mu);
  Model m = block_on_floor(angle, mu, "regularized");
  Simulation sim(m, m.step);
  const double x0 = mean_x(m);
  while (sim.time() < T) sim.step();
  const double a = g * (std::sin(angle) - mu * std::cos(angle));
  EXPECT_NEAR(mean_x(m) - x0, 0.5 * a * T * T, 0.1 * 0.5 * a * T * T);
}

// A tool's force by strip of its edge (the oblique cut's force away from the sides): the bands
// split the floor's contacts, so two bands that meet carry the whole force (to rounding: the
// two partial sums are added in another order than the whole, hence 1e-12 relative) and a band
// holding every contact is the whole force in the same order, bit for bit. The block (4 x 4 x 1
// cells) rests on the floor after 5 ms, each half of it on contacts of its own.
TEST(MeshForce, BandsSplitTheMeshForceByWhereItsContactsAct) {
  test::BlockOnFloor b;
  b.cells = {4, 4, 1};
  b.integrator = "scheme = \"verlet\"\nend_time = 1";
  Model m = build_model(parse_case(test::block_on_floor_case(b), "block", {}));
  Simulation sim(m, m.step);
  while (sim.time() < 5e-3) sim.step();
  const Vec3 whole = sim.mesh_force(0);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Vec3& x : m.particles.position) lo = std::min(lo, x[1]), hi = std::max(hi, x[1]);
  const double mid = 0.5 * (lo + hi) + 1e-4;  // (between two lattice planes)
  const Vec3 left = sim.contacts().mesh_force_in_band(0, 1, -HUGE_VAL, mid);
  const Vec3 right = sim.contacts().mesh_force_in_band(0, 1, mid, HUGE_VAL);
  ASSERT_GT(whole.norm(), 0.0);
  EXPECT_GT(left.norm(), 0.2 * whole.norm());
  EXPECT_GT(right.norm(), 0.2 * whole.norm());
  EXPECT_LE((left + right - whole).norm(), 1e-12 * whole.norm());
  EXPECT_EQ(sim.contacts().mesh_force_in_band(0, 1, -HUGE_VAL, HUGE_VAL), whole);
  EXPECT_EQ(sim.contacts().mesh_force_in_band(0, 1, hi + 1.0, HUGE_VAL), Vec3::Zero());
}

// ---- neighbour search ---------------------------------------------------------------------

// Frictionless, undamped contacts with a 0.1 mm skin, for the neighbour-search tests.
ContactParams frictionless_params() {
  ContactParams prm;
  prm.youngs_modulus = 1e9;
  prm.poisson_ratio = 0.3;
  prm.skin = 1e-4;
  return prm;
}

TEST(NeighbourSearch, FindsExactlyTheOverlappingPairsOfBruteForce) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 0.02), ur(0.4e-3, 0.9e-3);
  Particles p;
  const std::size_t n = 3000;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = Vec3(u(rng), u(rng), 0.5 * u(rng));
    p.radius[i] = ur(rng);
    p.mass[i] = 1e-6;
    p.inv_mass[i] = 1e6;
  }
  Rods rods;
  rods.build_rows(n);
  std::vector<MeshBody> meshes;
  const ContactParams prm = frictionless_params();
  ContactSystem cs;
  cs.setup(prm, n, &meshes);
  cs.update_lists(p, rods, true);
  cs.evaluate(p, 1e-7);
  std::size_t brute = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if ((p.position[i] - p.position[j]).norm() < p.radius[i] + p.radius[j]) ++brute;
  EXPECT_GT(brute, 100u);
  EXPECT_EQ(cs.touching(), brute);
  // Move every particle by less than half the skin: no rebuild, still exact.
  std::uniform_real_distribution<double> small(-0.28e-4, 0.28e-4);
  for (auto& x : p.position) x += Vec3(small(rng), small(rng), small(rng));
  const std::size_t builds = cs.list_builds();
  cs.update_lists(p, rods, false);
  EXPECT_EQ(cs.list_builds(), builds);
  cs.evaluate(p, 1e-7);
  brute = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if ((p.position[i] - p.position[j]).norm() < p.radius[i] + p.radius[j]) ++brute;
  EXPECT_EQ(cs.touching(), brute);
}

TEST(NeighbourSearch, BondedPairsAreNotContactsUntilTheRodBreaks) {
  // A compressed bonded pair: the rod acts, not the contact; once the rod is broken the
  // contact takes over.
  Particles p;
  p.resize(2);
  p.position[1] = Vec3(1.9e-3, 0, 0);
  p.radius = {1e-3, 1e-3};
  p.mass = {1e-5, 1e-5};
  p.inv_mass = {1e5, 1e5};
  Rods rods;
  rods.ends = {{0, 1}};
  rods.rest_length = {2e-3};
  rods.reset_state();
  rods.build_rows(2);
  std::vector<MeshBody> meshes;
  const ContactParams prm = frictionless_params();
  ContactSystem cs;
  cs.setup(prm, 2, &meshes);
  cs.update_lists(p, rods, true);
  cs.evaluate(p, 1e-7);
  EXPECT_EQ(cs.touching(), 0u);
  rods.intact[0] = 0;
  cs.update_lists(p, rods, true);
  cs.evaluate(p, 1e-7);
  EXPECT_EQ(cs.touching(), 1u);
}

TEST(NeighbourSearch, ABrokenRodsPairMergedIntoTheListsActsAsAfterARebuild) {
  // Three particles in a row, both neighbours bonded to the middle one and overlapping it.
  // The left rod breaks: the simulation merges its pair into the lists (add_pairs) instead
  // of rebuilding them; the contact force must be exactly that of a rebuilt list, and the
  // lists must not be rebuilt for it.
  Particles p;
  p.resize(3);
  p.position[0] = Vec3(-1.9e-3, 0, 0);
  p.position[2] = Vec3(1.95e-3, 0, 0);
  p.radius = {1e-3, 1e-3, 1e-3};
  p.mass = {1e-5, 1e-5, 1e-5};
  p.inv_mass = {1e5, 1e5, 1e5};
  Rods rods;
  rods.ends = {{0, 1}, {1, 2}};
  rods.rest_length = {2e-3, 2e-3};
  rods.reset_state();
  rods.build_rows(3);
  std::vector<MeshBody> meshes;
  const ContactParams prm = frictionless_params();
  ContactSystem merged, rebuilt;
  merged.setup(prm, 3, &meshes);
  merged.update_lists(p, rods, true);
  merged.evaluate(p, 1e-7);
  ASSERT_EQ(merged.touching(), 0u);
  rods.intact[0] = 0;
  merged.add_pairs(p, {{1, 0}});  // either order of the ends
  merged.update_lists(p, rods, false);
  EXPECT_EQ(merged.list_builds(), 1u);
  merged.evaluate(p, 1e-7);
  rebuilt.setup(prm, 3, &meshes);
  rebuilt.update_lists(p, rods, true);
  rebuilt.evaluate(p, 1e-7);
  EXPECT_EQ(merged.touching(), 1u);
  for (std::size_t i = 0; i < 3; ++i) {
    Vec3 fm = Vec3::Zero(), tm = Vec3::Zero(), fr = Vec3::Zero(), tr = Vec3::Zero();
    merged.add_to_particle(i, p.radius[i], fm, tm);
    rebuilt.add_to_particle(i, p.radius[i], fr, tr);
    EXPECT_EQ(fm, fr) << i;
  }
  Vec3 f0 = Vec3::Zero(), t0 = Vec3::Zero();
  merged.add_to_particle(0, p.radius[0], f0, t0);
  EXPECT_LT(f0[0], 0.0);  // pushed away from the middle particle
  // Merging a pair that is already listed changes nothing.
  merged.add_pairs(p, {{0, 1}});
  merged.evaluate(p, 1e-7);
  EXPECT_EQ(merged.touching(), 1u);
}

// ---- meshes -------------------------------------------------------------------------------

TEST(Meshes, StlAndObjRoundTripAndBadMeshesAreRejected) {
  test::TempDir dir("meshes");
  const TriangleMesh sq = square(3, 0.2, 9);
  write_stl(dir / "sq.stl", sq);
  const TriangleMesh back = read_mesh(dir / "sq.stl");
  EXPECT_EQ(back.triangles.size(), sq.triangles.size());
  EXPECT_EQ(back.vertices.size(), sq.vertices.size());  // welded
  test::write_file(dir / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 3\n");
  EXPECT_EQ(read_mesh(dir / "t.obj").triangles.size(), 2u);
  test::write_file(dir / "a.stl",
                   "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                   "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n");
  EXPECT_EQ(read_mesh(dir / "a.stl", 1e-3).vertices[1][0], 1e-3);
  // Degenerate, empty, non-finite, missing, unknown format.
  test::write_file(dir / "deg.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  test::write_file(dir / "empty.obj", "v 0 0 0\n");
  test::write_file(dir / "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  test::write_file(dir / "x.ply", "ply\n");
  for (const char* f : {"deg.obj", "empty.obj", "nan.obj", "missing.stl", "x.ply"}) {
    try {
      read_mesh(dir / f);
      ADD_FAILURE() << f << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

TEST(MovingMesh, ItsWorkIsInTheEnergyLedger) {
  // A rigid plane moving at v hits a free sphere (no friction). Elastic: the sphere leaves at
  // 2 v and the plane's work equals its kinetic energy 2 m v^2, the contacts keep nothing.
  // Damped (e = 0.5): the sphere leaves at (1 + e) v and the contacts take up the rest.
  for (const double e : {1.0, 0.5}) {
    const double v = 0.5, R = 1e-3;
    const std::string text = fmt::format(R"([material]
density = 2500.0
[[particle]]
position = [0.0, 0.0, 0.0]
radius = {R}
[contact]
youngs_modulus = 1e9
restitution = {e}
[[mesh]]
name = "pusher"
origin = [-0.0011, -0.01, -0.01]
edge1 = [0.0, 0.02, 0.0]
edge2 = [0.0, 0.0, 0.02]
motion = "velocity"
velocity = [{v}, 0.0, 0.0]
[integrator]
scheme = "verlet"
dt = 2e-8
end_time = 1
)",
                                         fmt::arg("R", R), fmt::arg("v", v), fmt::arg("e", e));
    Model m = build_model(parse_case(text, "pusher", {}));
    Simulation sim(m, m.step);
    // The 0.1 mm gap closes in 0.2 ms; the contact lasts about 0.03 ms.
    while (sim.time() < 4e-4) sim.step();
    const double mass = m.particles.mass[0];
    EXPECT_NEAR(m.particles.velocity[0][0], (1 + e) * v, 2e-3 * v);
    const double ke = sim.kinetic_energy();
    EXPECT_NEAR(ke, 0.5 * mass * (1 + e) * (1 + e) * v * v, 4e-3 * ke);
    // Trapezoidal work and power over steps of 1/1000 of the contact: balance to 1e-3 of the energy.
    const auto& L = sim.ledger();
    EXPECT_NEAR(L.external_work, ke + L.contact_work, 1e-3 * ke) << "e " << e;
    if (e == 1.0)
      EXPECT_NEAR(L.contact_work, 0.0, 1e-3 * ke);
    else
      EXPECT_GT(L.contact_work, 0.1 * ke);
  }
}

}  // namespace
}  // namespace swarf
