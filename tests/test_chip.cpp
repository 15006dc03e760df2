// test_chip.cpp: chip metrics on a synthetic particle set with a known chip, and the
// shear-angle, friction-angle and Merchant relations against hand-worked values.
#include <gtest/gtest.h>

#include <cmath>

#include "postprocess/chip.h"

namespace swarf {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(Chip, SyntheticChipOfKnownThickness) {
  // Workpiece below z = 0 (not chip), and a chip: a slab of thickness hc lying on a rake face
  // of 10 deg through the tip (0, 0, -h), filled with a square grid of particle centres a
  // radius inside both free surfaces.
  const double R = 1e-5, h = 2e-4, hc = 5e-4, alpha = 10.0;
  ChipInput in;
  in.radius = R;
  in.uncut_surface_z = 0.0;
  in.tool_tip = Vec3(0, 0, -h);
  in.rake_angle_deg = alpha;
  in.depth_of_cut = h;
  const double a = alpha * kDeg;
  const Vec3 up(-std::sin(a), 0, std::cos(a)), normal(std::cos(a), 0, std::sin(a));
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
  EXPECT_NEAR(m.shear_angle_deg, shear_angle_deg(h / m.thickness, alpha), 1e-12);
}

TEST(Chip, AnglesAgainstHandWorkedValues) {
  // r = 0.5, alpha = 0: tan(phi) = 0.5 -> phi = 26.565 deg.
  EXPECT_NEAR(shear_angle_deg(0.5, 0.0), std::atan(0.5) / kDeg, 1e-12);
  // r = 0.5, alpha = 10 deg: tan(phi) = 0.5 cos10 / (1 - 0.5 sin10) = 0.5383.
  EXPECT_NEAR(std::tan(shear_angle_deg(0.5, 10.0) * kDeg), 0.5 * std::cos(10 * kDeg) / (1 - 0.5 * std::sin(10 * kDeg)),
              1e-12);
  // Fc = Ft: the resultant is 45 deg from the cutting direction: beta = alpha + 45.
  EXPECT_NEAR(friction_angle_deg(100.0, 100.0, 5.0), 50.0, 1e-12);
  // Merchant: 45 + alpha/2 - beta/2.
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

}  // namespace
}  // namespace swarf
