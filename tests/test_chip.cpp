// test_chip.cpp: chip metrics on a synthetic particle set with a known chip, the
// shear-angle, friction-angle and Merchant relations against hand-worked values, the cut
// report's h_c as the median of the steady part's rows, and the intervals of its steady means.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "io/h5file.h"
#include "io/results_format.h"
#include "postprocess/chip.h"
#include "postprocess/cut_report.h"
#include "postprocess/steady_stats.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"

namespace swarf {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A cut with the uncut surface at z = 0 and the tool's tip at (0, 0, -h), no particles yet.
ChipInput cut_of(double radius, double h, double rake_deg) {
  ChipInput in;
  in.radius = radius;
  in.uncut_surface_z = 0.0;
  in.tool_tip = Vec3(0, 0, -h);
  in.rake_angle_deg = rake_deg;
  in.depth_of_cut = h;
  return in;
}
// Up the rake face, and its normal into the chip.
Vec3 face_up(double rake_deg) { return Vec3(-std::sin(rake_deg * kDeg), 0, std::cos(rake_deg * kDeg)); }
Vec3 face_normal(double rake_deg) { return Vec3(std::cos(rake_deg * kDeg), 0, std::sin(rake_deg * kDeg)); }

TEST(Chip, SyntheticChipOfKnownThickness) {
  // Workpiece below z = 0 (not chip), and a chip: a slab of thickness hc lying on a rake face
  // of 10 deg through the tip (0, 0, -h), filled with a square grid of particle centres a
  // radius inside both free surfaces.
  const double R = 1e-5, h = 2e-4, hc = 5e-4, gamma = 10.0;
  ChipInput in = cut_of(R, h, gamma);
  const Vec3 up = face_up(gamma), normal = face_normal(gamma);
  for (double x = -2e-3; x < 0; x += 2 * R)
    for (double z = -1e-3; z < -h; z += 2 * R) in.position.emplace_back(x, 0, z);  // workpiece, stays
  for (double s = 0; s < 3e-3; s += 2 * R)
    for (double t = R; t <= hc - R + 1e-12; t += (hc - 2 * R) / 20)
      in.position.push_back(in.tool_tip + s * up + t * normal);
  const ChipMetrics m = measure_chip(in);
  EXPECT_GT(m.chip_particles, 1000u);
  // Percentiles of a uniform spread of 21 layers: the 2nd-98th span loses 4 % of hc - 2R.
  EXPECT_NEAR(m.thickness, hc, 0.05 * hc);
  EXPECT_NEAR(m.compression_ratio, h / m.thickness, 1e-15);
  EXPECT_NEAR(m.shear_angle_deg, shear_angle_deg(h / m.thickness, gamma), 1e-12);
}

// A chip whose head still crosses the section (2 h to 3 h up the face) holds only part of its
// thickness there (a rounded head: here a slab whose outer layers end 2 h short of its inner
// ones, so the section sees the inner half of the chip until the head is 2 h past it); the measure
// waits until the head is h/2 past the section's end: 0 before, the chip's thickness after.
TEST(Chip, AChipWhoseHeadStillCrossesTheSectionIsNotMeasured) {
  const double R = 1e-5, h = 2e-4, hc = 5e-4, gamma = 10.0;
  const Vec3 up = face_up(gamma), normal = face_normal(gamma);
  auto chip_to = [&](double head) {
    ChipInput in = cut_of(R, h, gamma);
    for (double s = 0; s <= head + 1e-12; s += R)
      for (double t = R; t <= hc - R + 1e-12; t += (hc - 2 * R) / 20)
        if (t < 0.5 * hc || s <= head - 2 * h) in.position.push_back(in.tool_tip + s * up + t * normal);
    return in;
  };
  const ChipMetrics crossing = measure_chip(chip_to(3.4 * h));
  EXPECT_GT(crossing.measured_particles, 100u);
  EXPECT_NEAR(crossing.head, 3.4 * h, 1e-12);
  EXPECT_EQ(crossing.thickness, 0.0) << "the head is 0.4 h past the section";
  EXPECT_EQ(crossing.compression_ratio, 0.0);
  // (the inner half only: what the measure would have read)
  const ChipMetrics past = measure_chip(chip_to(3.6 * h));
  EXPECT_GT(past.thickness, 0.0) << "the head is 0.6 h past the section";
  EXPECT_LT(past.thickness, 0.8 * hc) << "still the inner part: the head's outer layers end 2 h behind it";
  const ChipMetrics whole = measure_chip(chip_to(5.1 * h));
  EXPECT_NEAR(whole.thickness, hc, 0.05 * hc);  // as the straight slab above
}

// A chip of thickness hc on the rake face of cut_of(R, h, gamma): a grid of centres a radius inside
// both free surfaces (21 layers across, R apart along the centre line), straight on the face for
// 'flat' from the tip, then curling away from it through 'arc' rad, its centre line on a circle of
// radius rc (centred rc + hc/2 from the face, on the chip's side). 'ys' are the layers along the width.
ChipInput curled_chip(double R, double h, double hc, double gamma, double flat, double rc, double arc,
                      std::vector<double> ys = {0.0}) {
  ChipInput in = cut_of(R, h, gamma);
  const Vec3 up = face_up(gamma), normal = face_normal(gamma);
  const Vec3 centre = in.tool_tip + flat * up + (rc + hc / 2) * normal;
  for (double y : ys)
    for (double s = 0; s < flat + rc * arc; s += R)
      for (double t = R; t <= hc - R + 1e-12; t += (hc - 2 * R) / 20) {
        if (s < flat) {
          in.position.push_back(in.tool_tip + s * up + t * normal + Vec3(0, y, 0));
        } else {
          const double phi = (s - flat) / rc, rad = rc + hc / 2 - t;
          in.position.push_back(centre + rad * (std::sin(phi) * up - std::cos(phi) * normal) + Vec3(0, y, 0));
        }
      }
  return in;
}

TEST(Chip, ACurledChipIsMeasuredWhereItLiesOnTheFace) {
  // The same slab on the face up to 3 h from the tip, then curling away through 90 degrees
  // (its centre line on a circle of radius 1 mm leaving the face): only the section on the
  // face counts, so the thickness is the slab's, not the slab's plus the curl's lift (1 mm at
  // the end: the old measure over the whole chip beyond 2 h gave about 1.5 mm).
  const double R = 1e-5, h = 2e-4, hc = 5e-4, gamma = 10.0, rc = 1e-3;
  ChipInput in = curled_chip(R, h, hc, gamma, 3 * h, rc, M_PI / 2);
  const ChipMetrics m = measure_chip(in);
  EXPECT_GT(m.measured_particles, 100u);
  EXPECT_NEAR(m.thickness, hc, 0.05 * hc);  // as the straight slab (see above)
  // The section ends at the face's end: half of it on a face 2.5 h long, none on one of 1.9 h.
  in.face_length = 2.5 * h;
  const ChipMetrics shorter = measure_chip(in);
  EXPECT_NEAR(double(shorter.measured_particles), 0.5 * double(m.measured_particles),
              0.05 * double(m.measured_particles));
  EXPECT_NEAR(shorter.thickness, hc, 0.05 * hc);
  in.face_length = 1.9 * h;
  EXPECT_EQ(measure_chip(in).thickness, 0.0);
}

// The chip's curl radius (measure_chip_curl): a chip of h_c = 0.3 mm on the face for 3 h, then
// curled through 120 deg about a centre line of radius 0.5 mm, two layers along the width (y is
// ignored). The centre line's points are midway between the 2nd and 98th percentiles of the
// particles across each slab; at 21 layers 14 um apart each percentile lies within one layer
// spacing of its surface layer, at worst half a spacing off the midpoint: 7 um, 1.4 % of R_u, the
// same for every point (the surfaces' layers are full at every angle): the radius within 2 %
// (0.2 % off as measured; 0.5 % for a 90 deg curl).
TEST(Chip, ACurledChipsRadiusIsRecovered) {
  const double R = 1e-5, h = 2e-4, hc = 3e-4, gamma = 10.0, ru = 5e-4, arc = 120 * kDeg;
  const ChipInput in = curled_chip(R, h, hc, gamma, 3 * h, ru, arc, {0.0, 2 * R});
  const ChipMetrics m = measure_chip(in);
  EXPECT_NEAR(m.thickness, hc, 0.05 * hc);  // h_c on the face as before (see above)
  const ChipCurl c = measure_chip_curl(in, m);
  ASSERT_TRUE(c.measured) << c.note;
  EXPECT_TRUE(c.note.empty());
  EXPECT_NEAR(c.radius, ru, 0.02 * ru);
  EXPECT_NEAR(c.start, 3 * h, 1e-12);  // past the thickness section (the contact ends there too)
  // The centre: rc + hc/2 off the face at 3 h, within the same 2 % of R_u.
  const Vec3 centre = in.tool_tip + 3 * h * face_up(gamma) + (ru + hc / 2) * face_normal(gamma);
  EXPECT_NEAR((c.centre - centre).norm(), 0.0, 0.02 * ru);
  EXPECT_LT(c.fit_rms, 0.01 * ru);
  // The points cover the arc up to its end, less the last slab (4 R: 5 deg of 0.5 mm) and the
  // part of the first slab on the face: 120 deg within 10 deg.
  EXPECT_NEAR(c.arc_deg, 120.0, 10.0);
  EXPECT_EQ(c.points, c.centreline.size());
  EXPECT_GE(c.points, 20u);  // 1.05 mm of arc in steps of 40 um: about 26
}

// The same chip with every particle moved by up to 1 % of R_u (5 um, half a radius) along x and z,
// uniformly, from a seeded mt19937_64 (the standard fixes its sequence; the doubles are made from
// its bits, as std::uniform_real_distribution is not portable). The jitter moves each surface's
// extreme percentiles outwards by about the same on both sides, so the midpoints stay unbiased;
// what is left is each point's scatter (a few um), averaged over 26 points by the fit: within 3 %
// (0.5 % off as measured).
TEST(Chip, AJitteredCurledChipsRadiusIsRecovered) {
  const double R = 1e-5, h = 2e-4, hc = 3e-4, gamma = 10.0, ru = 5e-4;
  ChipInput in = curled_chip(R, h, hc, gamma, 3 * h, ru, 120 * kDeg);
  std::mt19937_64 rng(20261206);
  const auto uniform = [&rng] { return double(rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0; };  // [-1, 1)
  for (Vec3& x : in.position) {
    x[0] += 0.01 * ru * uniform();
    x[2] += 0.01 * ru * uniform();
  }
  const ChipMetrics m = measure_chip(in);
  EXPECT_NEAR(m.thickness, hc, 0.05 * hc + 0.02 * ru);  // the jitter widens the spread by up to 2 x 5 um
  const ChipCurl c = measure_chip_curl(in, m);
  ASSERT_TRUE(c.measured) << c.note;
  EXPECT_NEAR(c.radius, ru, 0.03 * ru);
  EXPECT_LT(c.fit_rms, 0.02 * ru);
  EXPECT_GT(c.arc_deg, 100.0);
}

// The same chip with 20 stray particles 20 to 100 um off its surfaces (inside the slabs' window of
// one thickness about the centre line), at random angles along the curl: a slab of about 84
// particles puts its 98th percentile among the 4 of its surface layer, so one stray in a slab does
// not move its point; the radius within the 2 % of the clean chip (see above).
TEST(Chip, StrayParticlesDoNotMoveTheCurlRadius) {
  const double R = 1e-5, h = 2e-4, hc = 3e-4, gamma = 10.0, ru = 5e-4;
  ChipInput in = curled_chip(R, h, hc, gamma, 3 * h, ru, 120 * kDeg);
  const Vec3 up = face_up(gamma), normal = face_normal(gamma);
  const Vec3 centre = in.tool_tip + 3 * h * up + (ru + hc / 2) * normal;
  std::mt19937_64 rng(34);
  const auto unit = [&rng] { return double(rng() >> 11) * 0x1.0p-53; };  // [0, 1)
  for (int k = 0; k < 20; ++k) {
    const double phi = 120 * kDeg * unit(), off = 2e-5 + 8e-5 * unit();
    const double rad = k % 2 ? ru + hc / 2 + off : ru - hc / 2 - off;  // outside, inside
    in.position.push_back(centre + rad * (std::sin(phi) * up - std::cos(phi) * normal));
  }
  const ChipCurl c = measure_chip_curl(in, measure_chip(in));
  ASSERT_TRUE(c.measured) << c.note;
  EXPECT_NEAR(c.radius, ru, 0.02 * ru);
}

// A straight chip that runs on past the end of a 1 mm face: its centre line is a line, which
// no circle describes: not measured, and the note says it is a nearly straight chip.
TEST(Chip, AStraightChipHasNoCurlRadius) {
  const double R = 1e-5, h = 2e-4, hc = 3e-4, gamma = 10.0;
  ChipInput in = curled_chip(R, h, hc, gamma, 3e-3, 5e-4, 0.0);
  in.face_length = 1e-3;
  const ChipCurl c = measure_chip_curl(in, measure_chip(in));
  EXPECT_FALSE(c.measured);
  EXPECT_EQ(c.radius, 0.0);
  EXPECT_GE(c.points, 40u);  // 2 mm past the face's end in steps of 40 um
  EXPECT_LT(c.arc_deg, 1.0);
  EXPECT_NE(c.note.find("nearly straight chip"), std::string::npos) << c.note;
  // A slightly bent one (20 deg of a 2 mm radius past a face of 3 h) is not measured either.
  const ChipInput bent = curled_chip(R, h, hc, gamma, 3 * h, 2e-3, 20 * kDeg);
  const ChipCurl b = measure_chip_curl(bent, measure_chip(bent));
  EXPECT_FALSE(b.measured);
  EXPECT_NE(b.note.find("nearly straight chip"), std::string::npos) << b.note;
}

// The same curled chip mirrored about its mid-thickness plane: its centre line bends back towards
// the face (the centre on the tool's side), which is no up-curl: not measured, and the note says so.
// (The face ends at 3 h, where the bend starts: the bent part crosses the face's plane, which
// would otherwise count it as touching the face.)
TEST(Chip, AChipBendingTowardsTheFaceHasNoCurlRadius) {
  const double R = 1e-5, h = 2e-4, hc = 3e-4, gamma = 10.0;
  ChipInput in = curled_chip(R, h, hc, gamma, 3 * h, 5e-4, 90 * kDeg);
  const Vec3 normal = face_normal(gamma);
  for (Vec3& x : in.position) x -= 2 * ((x - in.tool_tip).dot(normal) - hc / 2) * normal;
  in.face_length = 3 * h;
  const ChipCurl c = measure_chip_curl(in, measure_chip(in));
  EXPECT_FALSE(c.measured);
  EXPECT_NE(c.note.find("bend towards the rake face (their circle, of 0.5"), std::string::npos) << c.note;
}

// Too few particles past the face: a curled chip that ends 30 um after leaving the face (less
// than one step of 4 R), and a chip of two particles.
TEST(Chip, TooFewParticlesGiveNoCurlRadius) {
  const double R = 1e-5, h = 2e-4, hc = 3e-4, gamma = 10.0;
  const ChipInput in = curled_chip(R, h, hc, gamma, 3 * h, 5e-4, 3e-5 / 5e-4);
  const ChipCurl c = measure_chip_curl(in, measure_chip(in));
  EXPECT_FALSE(c.measured);
  EXPECT_LT(c.points, 5u);
  EXPECT_NE(c.note.find("centreline points (at least 5 needed)"), std::string::npos) << c.note;
  ChipInput two = cut_of(R, h, gamma);
  two.position = {Vec3(0, 0, 1e-3), Vec3(0, 0, 2e-3)};
  const ChipCurl t = measure_chip_curl(two, measure_chip(two));
  EXPECT_FALSE(t.measured);
  EXPECT_FALSE(t.note.empty());
}

TEST(Chip, AnglesAgainstHandWorkedValues) {
  // r = 0.5, gamma = 0: tan(phi) = 0.5 -> phi = 26.565 deg.
  EXPECT_NEAR(shear_angle_deg(0.5, 0.0), std::atan(0.5) / kDeg, 1e-12);
  // r = 0.5, gamma = 10 deg: tan(phi) = 0.5 cos10 / (1 - 0.5 sin10) = 0.5383.
  EXPECT_NEAR(std::tan(shear_angle_deg(0.5, 10.0) * kDeg), 0.5 * std::cos(10 * kDeg) / (1 - 0.5 * std::sin(10 * kDeg)),
              1e-12);
  // Fc = Ft: the resultant is 45 deg from the cutting direction: beta = gamma + 45.
  EXPECT_NEAR(friction_angle_deg(100.0, 100.0, 5.0), 50.0, 1e-12);
  // Merchant: 45 + gamma/2 - beta/2.
  EXPECT_NEAR(merchant_shear_angle_deg(10.0, 30.0), 35.0, 1e-12);
}

TEST(Chip, TooFewParticlesGivesNoThickness) {
  ChipInput in;
  in.radius = 1e-5;
  in.depth_of_cut = 1e-4;
  in.position = {Vec3(0, 0, 1e-3), Vec3(0, 0, 2e-3)};
  const ChipMetrics m = measure_chip(in);
  EXPECT_EQ(m.chip_particles, 2u);
  EXPECT_EQ(m.thickness, 0.0);
}

// An oblique cut's chip, built in the inclined tool's own frame and turned into the world by
// lambda about the vertical through the tip (as the tool is, tool_geometry.h): a slab of thickness
// hc and width wc along the edge on the rake face, its particles moving at speed u up the face at
// eta off the edge's normal (plus the tool's speed along x). chip_input turns it back: h_c, the
// flow angle and the chip's width are recovered, h_c and the width to the percentile span's loss
// (21 layers across: 4 % of hc - 2R; 41 along the width: 4 % of wc - 2R), the angle to rounding.
TEST(Chip, AnObliqueChipsFlowAngleAndWidthAreRecovered) {
  const double R = 1e-5, h = 2e-4, hc = 4e-4, wc = 8e-4, gamma = 6.0, u = 2.0, v_tool = 3.0;
  for (const auto [lambda, eta] : {std::pair{0.0, 0.0}, std::pair{20.0, 17.0}, std::pair{-35.0, -31.0}}) {
    CutSetup s;
    s.rake_angle_deg = gamma;
    s.inclination_deg = lambda;
    s.uncut_surface_z = 0.0;
    s.radius = R;
    s.free_sides = true;
    const Vec3 tip(1e-3, 5e-4, -h);
    const Vec3 up = face_up(gamma), normal = face_normal(gamma);
    const Vec3 flow = u * (std::cos(eta * kDeg) * up + std::sin(eta * kDeg) * Vec3::UnitY());  // tool's frame
    const auto to_world = [&](const Vec3& a) { return to_tool_frame(a, -lambda); };
    std::vector<Vec3> x, vel;
    for (double y = -0.5 * wc + R; y <= 0.5 * wc - R + 1e-12; y += (wc - 2 * R) / 40)
      for (double a = 0; a < 4 * h; a += R)  // (the section: h to 3 h)
        for (double t = R; t <= hc - R + 1e-12; t += (hc - 2 * R) / 20) {
          x.push_back(tip + to_world(a * up + t * normal + y * Vec3::UnitY()));
          vel.push_back(to_world(flow) + Vec3(v_tool, 0, 0));
        }
    const ChipInput in = chip_input(s, x, tip);
    const ChipMetrics m = measure_chip(in);
    EXPECT_NEAR(m.thickness, hc, 0.05 * hc) << lambda;
    std::vector<Vec3> rel(vel.size());
    for (std::size_t i = 0; i < vel.size(); ++i) rel[i] = to_tool_frame(vel[i] - Vec3(v_tool, 0, 0), lambda);
    const ChipFlow f = measure_chip_flow(in, m, rel, wc);
    EXPECT_NEAR(f.flow_angle_deg, eta, 1e-9) << lambda;
    EXPECT_NEAR(f.width, wc, 0.05 * wc) << lambda;
    EXPECT_GT(f.particles, 1000u);
  }
}

// The side burr: over the machined part (not chip, behind the edge, not deep), the largest
// distance beyond the side faces' centres; a stray 5 h out and particles ahead of the edge or in
// the chip do not count. Hand-placed particles, h = 0.2 mm, faces at y = 0 and 1 mm, lambda 20 deg.
TEST(Chip, TheSideBurrIsTheMachinedPartsLargestStepOutOfTheSides) {
  const double h = 2e-4, R = 1e-5, lambda = 20.0;
  ChipInput in = cut_of(R, h, 10.0);
  in.tool_tip = Vec3(1e-3, 5e-4, -h);
  const auto behind = [&](double back, double y, double z) {  // 'back' behind the edge along its normal
    const Vec3 rel = to_tool_frame(Vec3(-back, y - 5e-4, 0.0), -lambda);
    return Vec3(in.tool_tip[0] + rel[0], y, z);
  };
  std::vector<Vec3> x{behind(2 * h, 1e-3 + 3e-5, -h - R),   // 30 um out at the +y side: the burr
                      behind(2 * h, -1e-5, -1.5 * h),       // 10 um out at the -y side
                      behind(2 * h, 1e-3 + 2e-3, -h),       // 2 mm out: a stray
                      behind(-2 * h, 1e-3 + 6e-5, -h),      // ahead of the edge
                      behind(2 * h, 1e-3 + 8e-5, 2 * R),    // chip
                      behind(2 * h, 1e-3 + 9e-5, -4 * h)};  // deep below the tip: not the machined surface
  EXPECT_NEAR(side_burr(x, in, lambda, 0.0, 1e-3), 3e-5, 1e-15);
  x.resize(2);
  x[0][1] = 5e-4;  // inside the faces: only the -y side's 10 um
  EXPECT_NEAR(side_burr(x, in, lambda, 0.0, 1e-3), 1e-5, 1e-15);
  x.resize(1);
  EXPECT_EQ(side_burr(x, in, lambda, 0.0, 1e-3), 0.0);
}

// The report's free-side figures: the passive force's steady mean, the flow angle's and the chip
// width's steady medians over the rows that measured them (chip_width > 0), beside Stabler's
// eta_c = lambda; hand-worked: steady rows 1..9, angles 12 14 13 0(unmeasured) 15 11 16 10 17
// -> sorted 10..17 without 0: median (13 + 14)/2 = 13.5.
TEST(CutReport, FreeSideFiguresAreTheSteadyRows) {
  CutSetup s;
  s.steady_from = 1.0;
  s.uncut_surface_z = 0.0;
  s.tool_tip = Vec3(0, 0, -2e-4);
  s.radius = 1e-5;
  s.width = 1e-3;
  s.inclination_deg = 15.0;
  s.free_sides = true;
  CutData d;
  d.time = {0.5, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  d.fc.assign(d.time.size(), 1.0);
  d.ft.assign(d.time.size(), 0.0);
  d.passive_force = {100, 2, 4, 6, 8, 10, 12, 14, 16, 18};
  d.chip_flow_angle = {90, 12, 14, 13, 0, 15, 11, 16, 10, 17};
  d.chip_width = {1, 1, 1, 1, 0, 1, 1, 1, 1, 1};
  d.fc_middle = {500, 1, 2, 3, 4, 5, 6, 7, 8, 9};  // steady mean 5
  d.ft_middle = {-50, 2, 2, 2, 2, 2, 2, 2, 2, 2};
  const CutResult r = analyze_cut(s, d);
  EXPECT_NEAR(r.cutting["passive_force_per_width_mean_N_per_m"].get<double>(), 10.0, 1e-12);
  EXPECT_NEAR(r.cutting["cutting_force_per_width_middle_mean_N_per_m"].get<double>(), 5.0, 1e-12);
  EXPECT_NEAR(r.cutting["thrust_force_per_width_middle_mean_N_per_m"].get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(r.chip["flow_angle_deg"].get<double>(), 13.5, 1e-12);
  EXPECT_EQ(r.chip["flow_angle_stabler_deg"].get<double>(), 15.0);
  EXPECT_NEAR(r.chip["width_to_cut_width"].get<double>(), std::cos(15.0 * kDeg) / 1e-3, 1e-9);
  EXPECT_EQ(r.chip["flow_rows"].get<int>(), 8);
  d.passive_force.clear();  // plane strain: none of it
  d.fc_middle.clear(), d.ft_middle.clear();
  EXPECT_FALSE(analyze_cut(s, d).chip.contains("flow_angle_deg"));
  EXPECT_FALSE(analyze_cut(s, d).cutting.contains("cutting_force_per_width_middle_mean_N_per_m"));
}

// The report's h_c is the median of the steady rows that measured the chip (0 = not
// measured), with the 10th and 90th percentiles; r and phi follow from it. Values hand-worked:
// steady rows hold 5 1 4 2 3 0 9 7 6 (x 1e-4 m), the row before steady_from 50e-4 (ignored):
// sorted 1 2 3 4 5 6 7 9, median (4 + 5)/2 = 4.5, 10 % at position 0.7: 1.7, 90 % at 6.3: 7.6.
TEST(CutReport, ChipThicknessIsTheMedianOfTheSteadyRows) {
  CutSetup s;
  s.steady_from = 1.0;
  s.rake_angle_deg = 10.0;
  s.uncut_surface_z = 0.0;
  s.tool_tip = Vec3(0, 0, -2e-4);  // h = 0.2 mm
  s.radius = 1e-5;
  CutData d;
  d.time = {0.5, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  d.fc.assign(d.time.size(), 1.0);
  d.ft.assign(d.time.size(), 0.0);
  for (double v : {50.0, 5.0, 1.0, 4.0, 2.0, 3.0, 0.0, 9.0, 7.0, 6.0}) d.chip_thickness.push_back(v * 1e-4);
  const CutResult r = analyze_cut(s, d);
  EXPECT_NEAR(r.chip["thickness_m"].get<double>(), 4.5e-4, 1e-16);
  EXPECT_NEAR(r.chip["thickness_p10_m"].get<double>(), 1.7e-4, 1e-16);
  EXPECT_NEAR(r.chip["thickness_p90_m"].get<double>(), 7.6e-4, 1e-16);
  EXPECT_EQ(r.chip["thickness_rows"].get<int>(), 8);
  EXPECT_NEAR(r.chip["compression_ratio"].get<double>(), 2e-4 / 4.5e-4, 1e-15);
  EXPECT_NEAR(r.chip["shear_angle_deg"].get<double>(), shear_angle_deg(2e-4 / 4.5e-4, 10.0), 1e-12);
  EXPECT_FALSE(r.chip.contains("thickness_final_m"));  // no particles at the end: nothing to measure
  // Fewer than 5 measured steady rows: no h_c, and a note that says why.
  d.chip_thickness = {50e-4, 5e-4, 0, 0, 0, 0, 0, 9e-4, 7e-4, 6e-4};
  const CutResult few = analyze_cut(s, d);
  EXPECT_FALSE(few.chip.contains("thickness_m"));
  EXPECT_NE(few.chip["note"].get<std::string>().find("4 steady rows"), std::string::npos) << few.chip.dump();
}

// The summary's curl keys are the end state's measure_chip_curl, and the table has a row for
// them; a chip that is not curled gives nulls, a note, and "not measured" in the table.
TEST(CutReport, TheChipsCurlRadiusIsTheEndStates) {
  const double R = 1e-5, h = 2e-4, hc = 3e-4, gamma = 10.0, ru = 5e-4;
  const ChipInput in = curled_chip(R, h, hc, gamma, 3 * h, ru, 120 * kDeg);
  CutSetup s;
  s.rake_angle_deg = gamma;
  s.uncut_surface_z = in.uncut_surface_z;
  s.tool_tip = in.tool_tip;
  s.radius = R;
  CutData d;
  d.position = in.position;
  const CutResult r = analyze_cut(s, d);
  const ChipCurl c = measure_chip_curl(in, measure_chip(in));
  ASSERT_TRUE(c.measured);
  EXPECT_EQ(r.chip["curl_radius_m"].get<double>(), c.radius);
  EXPECT_EQ(r.chip["curl_fit_rms_m"].get<double>(), c.fit_rms);
  EXPECT_EQ(r.chip["curl_arc_deg"].get<double>(), c.arc_deg);
  EXPECT_EQ(r.chip["curl_points"].get<std::size_t>(), c.points);
  EXPECT_FALSE(r.chip.contains("curl_note"));
  const std::string table = cut_table(r.cutting, r.chip, 0.0);
  EXPECT_NE(table.find(fmt::format("chip curl radius R_u (end)      {:>10.4g} mm (over {:.0f} deg, {} points",
                                   c.radius * 1e3, c.arc_deg, c.points)),
            std::string::npos)
      << table;
  d.position.clear();  // no chip
  const CutResult none = analyze_cut(s, d);
  EXPECT_TRUE(none.chip["curl_radius_m"].is_null());
  EXPECT_TRUE(none.chip["curl_arc_deg"].is_null());
  EXPECT_EQ(none.chip["curl_points"].get<int>(), 0);
  EXPECT_NE(none.chip["curl_note"].get<std::string>().find("not measured"), std::string::npos);
  EXPECT_NE(cut_table(none.cutting, none.chip, 0.0).find("chip curl radius R_u (end)      not measured\n  note: "),
            std::string::npos);
}

// The steady means carry 95 % intervals (postprocess/steady_stats.h): the forces' are the batch-
// means intervals of their steady rows, with the autocorrelation time in s (samples x the row
// interval) and the effective sample size; Ft/Fc, beta and Merchant's angle are linearised about
// the means over the same batches, h_c's comes from batch medians and r's and phi's from it. The
// linearised intervals are checked against the same statistic computed batch by batch without
// linearising: the two differ at second order, by about the batch means' relative scatter (1.5 %
// for Fc here; 7.5 % scatter gave 6 %, 0.75 % gave 0.4 %), so within 2.5 %. A steady part of fewer
// than 20 rows has no interval: null in the summary, "unavailable" in the table.
TEST(CutReport, SteadyMeansCarryConfidenceIntervals) {
  CutSetup s;
  s.steady_from = 99.5e-6;  // rows 100 to 299
  s.rake_angle_deg = 10.0;
  s.tool_tip = Vec3(0, 0, -5e-4);  // h = 0.5 mm
  s.radius = 1e-5;
  s.width = 8e-5;
  CutData d;
  std::vector<double> fc, ft, hc;  // the steady rows
  for (int k = 0; k < 300; ++k) {
    d.time.push_back(1e-6 * k);
    d.fc.push_back(1e5 + 1e4 * std::sin(0.7 * k * k));
    d.ft.push_back(1e4 + 0.1 * d.fc.back() + 3e3 * std::cos(0.3 * k * k));
    d.chip_thickness.push_back(6e-4 + 5e-5 * std::sin(1.1 * k * k));
    if (d.time.back() >= s.steady_from) {
      fc.push_back(d.fc.back());
      ft.push_back(d.ft.back());
      hc.push_back(d.chip_thickness.back());
    }
  }
  ASSERT_EQ(fc.size(), 200u);
  const CutResult r = analyze_cut(s, d);
  const SteadyStats fs = steady_stats(fc), ts = steady_stats(ft);
  const nlohmann::json& c = r.cutting;
  EXPECT_EQ(c["cutting_force_per_width_ci95_N_per_m"].get<double>(), fs.ci95);
  EXPECT_EQ(c["thrust_force_per_width_ci95_N_per_m"].get<double>(), ts.ci95);
  EXPECT_NEAR(c["cutting_force_per_width_autocorrelation_time_s"].get<double>(), fs.autocorrelation_time * 1e-6,
              1e-9 * fs.autocorrelation_time * 1e-6);
  EXPECT_EQ(c["thrust_force_per_width_effective_samples"].get<double>(), ts.effective_samples);
  EXPECT_EQ(c["steady_batches"].get<int>(), 10);
  EXPECT_EQ(c["steady_batch_samples"].get<int>(), 20);
  EXPECT_EQ(c["cutting_force_per_width_mean_N_per_m"].get<double>(), fs.mean);  // the existing keys stay
  EXPECT_EQ(c["cutting_force_per_width_std_N_per_m"].get<double>(), fs.std);
  // Without linearising: the statistic of each batch's means.
  const std::vector<double> bfc = batch_means(fc), bft = batch_means(ft), bhc = batch_medians(hc);
  std::vector<double> ratio, beta, cr, phi;
  for (std::size_t k = 0; k < bfc.size(); ++k) {
    ratio.push_back(bft[k] / bfc[k]);
    beta.push_back(friction_angle_deg(bfc[k], bft[k], 10.0));
    cr.push_back(5e-4 / bhc[k]);
    phi.push_back(shear_angle_deg(5e-4 / bhc[k], 10.0));
  }
  // Shop-floor units: kc = Fc/(b h) in N/mm^2 with its interval, the forces in N on the width.
  EXPECT_NEAR(c["specific_cutting_force_N_per_mm2"].get<double>(), fs.mean / 5e-4 * 1e-6, 1e-12 * fs.mean);
  EXPECT_NEAR(c["specific_cutting_force_ci95_N_per_mm2"].get<double>(), fs.ci95 / 5e-4 * 1e-6, 1e-12 * fs.ci95);
  EXPECT_EQ(c["cutting_force_N"].get<double>(), fs.mean * s.width);
  EXPECT_EQ(c["thrust_force_N"].get<double>(), ts.mean * s.width);
  EXPECT_EQ(c["thrust_to_cutting_force_ratio"].get<double>(), ts.mean / fs.mean);
  EXPECT_NEAR(c["thrust_to_cutting_force_ratio_ci95"].get<double>() / batch_ci95(ratio), 1.0, 0.025);
  EXPECT_NEAR(r.chip["friction_angle_ci95_deg"].get<double>() / batch_ci95(beta), 1.0, 0.025);
  EXPECT_EQ(r.chip["merchant_shear_angle_ci95_deg"].get<double>(),
            0.5 * r.chip["friction_angle_ci95_deg"].get<double>());
  EXPECT_EQ(r.chip["thickness_ci95_m"].get<double>(), batch_ci95(bhc));
  EXPECT_NEAR(r.chip["compression_ratio_ci95"].get<double>() / batch_ci95(cr), 1.0, 0.025);
  EXPECT_NEAR(r.chip["shear_angle_ci95_deg"].get<double>() / batch_ci95(phi), 1.0, 0.025);
  const std::string table = cut_table(r.cutting, r.chip, 0.0);
  EXPECT_NE(table.find(fmt::format("(95 % CI of the mean +- {:.3g} kN/m)", fs.ci95 / 1e3)), std::string::npos) << table;
  EXPECT_NE(table.find("from 10 batch means of 20 rows (Student t, 9 dof)"), std::string::npos) << table;
  EXPECT_NE(table.find(fmt::format("kc=Fc/bh {:>10.4g} N/mm^2 (95 % CI of the mean +- {:.3g} N/mm^2)",
                                   fs.mean / 5e-4 * 1e-6, fs.ci95 / 5e-4 * 1e-6)),
            std::string::npos)
      << table;
  EXPECT_NE(
      table.find(fmt::format("Fc, Ft on the width b = 0.08 mm {:>8.4g}, {:.4g} N", fs.mean * 8e-5, ts.mean * 8e-5)),
      std::string::npos)
      << table;

  // 15 steady rows: no interval, but the mean and deviation as before.
  d.time.resize(30);
  d.fc.resize(30);
  d.ft.resize(30);
  d.chip_thickness.resize(30);
  s.steady_from = 14.5e-6;  // rows 15 to 29
  const CutResult few = analyze_cut(s, d);
  EXPECT_EQ(few.cutting["steady_samples"].get<int>(), 15);
  EXPECT_TRUE(few.cutting["cutting_force_per_width_mean_N_per_m"].is_number());
  for (const char* k : {"cutting_force_per_width_ci95_N_per_m", "thrust_force_per_width_ci95_N_per_m",
                        "thrust_to_cutting_force_ratio_ci95", "cutting_force_per_width_effective_samples"})
    EXPECT_TRUE(few.cutting[k].is_null()) << k;
  EXPECT_EQ(few.cutting["steady_batches"].get<int>(), 0);
  EXPECT_TRUE(few.chip["friction_angle_ci95_deg"].is_null());
  EXPECT_TRUE(few.chip["thickness_ci95_m"].is_null());
  const std::string few_table = cut_table(few.cutting, few.chip, 0.0);
  EXPECT_NE(few_table.find("(95 % CI of the mean: unavailable, 15 steady rows, 20 needed)"), std::string::npos)
      << few_table;
  EXPECT_NE(few.cutting.dump().find("\"cutting_force_per_width_ci95_N_per_m\":null"), std::string::npos);
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// results.h5 layouts: a file of layout 1 (no 'format' attribute, 9 setup values) is read with
// an unknown face length; a file of layout 2 (format = 2) must hold all 10, or it is refused.
TEST(CutReport, TheSetupIsReadByTheFilesLayoutVersion) {
  test::TempDir dir("results_format");
  CutSetup s;
  s.tool_mesh = "tool";
  s.width = 1.5e-3;
  s.tool_tip = Vec3(1e-3, 0.0, 2e-3);
  s.face_length = 2e-3;
  s.steady_from = 1e-5;
  s.rake_angle_deg = 10;
  s.uncut_surface_z = 3e-3;
  s.radius = 1e-4;
  s.lattice_particles = 123;
  s.inclination_deg = 25;
  s.free_sides = true;
  {
    H5File f(dir / "new.h5", H5File::Mode::Create);
    f.write_attribute("format", kResultsFormat);
    write_cut_setup(f, s);
  }
  CutSetup r;
  ASSERT_TRUE(read_cut_setup(H5File(dir / "new.h5", H5File::Mode::Read), r));
  EXPECT_EQ(r.face_length, 2e-3);
  EXPECT_EQ(r.tool_tip, s.tool_tip);
  EXPECT_EQ(r.width, s.width);
  EXPECT_EQ(r.steady_from, s.steady_from);
  EXPECT_EQ(r.rake_angle_deg, s.rake_angle_deg);
  EXPECT_EQ(r.uncut_surface_z, s.uncut_surface_z);
  EXPECT_EQ(r.radius, s.radius);
  EXPECT_EQ(r.lattice_particles, 123u);
  EXPECT_EQ(r.tool_mesh, "tool");
  EXPECT_EQ(r.inclination_deg, 25);
  EXPECT_TRUE(r.free_sides);
  const std::vector<double> nine{1.5e-3, 0, 1e-3, 0, 2e-3, 10, 3e-3, 1e-4, 100};
  {
    H5File f(dir / "old.h5", H5File::Mode::Create);  // layout 1: no attribute
    f.write("/cutting/setup", nine.data(), nine.size());
  }
  CutSetup o;
  ASSERT_TRUE(read_cut_setup(H5File(dir / "old.h5", H5File::Mode::Read), o));
  EXPECT_EQ(o.face_length, HUGE_VAL);
  EXPECT_EQ(o.lattice_particles, 100u);
  {
    H5File f(dir / "bad.h5", H5File::Mode::Create);  // claims layout 2 with 9 values
    f.write_attribute("format", 2.0);
    f.write("/cutting/setup", nine.data(), nine.size());
  }
  CutSetup b;
  EXPECT_THROW(read_cut_setup(H5File(dir / "bad.h5", H5File::Mode::Read), b), InputError);
  {
    H5File f(dir / "bad3.h5", H5File::Mode::Create);  // layout 3 with a tool tip of 2 values
    f.write_attribute("format", kResultsFormat);
    const double one[1] = {1e-3}, two[2] = {0, 0};
    f.write("/cutting/width", one, 1);
    f.write("/cutting/steady_from", one, 1);
    f.write("/cutting/tool_tip", two, 2);
  }
  CutSetup c;
  EXPECT_THROW(read_cut_setup(H5File(dir / "bad3.h5", H5File::Mode::Read), c), InputError);
}

}  // namespace
}  // namespace swarf
