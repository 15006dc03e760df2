// test_lattice_material.cpp: the material lab's homogeneous (Cauchy-Born) lattice against closed
// forms: the cubic elastic constants and the directional moduli and Poisson ratios they imply, the
// exact finite-strain elastic [100] tension, the small-strain plastic relation of docs/physics.md
// section 1, the rods that carry simple shear on the cube plane and on the 45-degree plane, the
// Bauschinger reversal, mirrored compression, and failure by the rods' strain.
#include <gtest/gtest.h>

#include <cmath>

#include "lattice_gen/cauchy_born.h"
#include "lattice_gen/lattice_material.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

// The default geometry: R = 10 um, l0 = 2R, a = sqrt(2) l0, A = pi R^2.
constexpr double kR = 1e-5;
const double kL0 = 2 * kR, kA = std::sqrt(2.0) * kL0, kArea = M_PI * kR * kR;
constexpr double kE = 200e9;
const double kKb = kE * kArea / kL0;  // rod stiffness, N/m
const double kC = kKb / kA;           // kb / a, Pa
const double kE100 = 4 * kKb / (3 * kA);

RodLaw elastic_law() {
  RodLaw law;
  law.youngs_modulus = kE;
  law.yield_strain = HUGE_VAL;
  law.tensile_strength = HUGE_VAL;
  return law;
}

RodLaw linear_law(double yield_strain, double hardening) {
  RodLaw law = elastic_law();
  law.yield_strain = yield_strain;
  law.hardening = hardening;
  return law;
}

// A hardening curve: 300 MPa, 400 MPa at 0.002, 450 MPa at 0.01, on with 2.5 GPa.
RodLaw curve_law() {
  RodLaw law = elastic_law();
  law.flow.points = 3;
  law.flow.plastic_strain = {0.0, 0.002, 0.01};
  law.flow.stress = {300e6, 400e6, 450e6};
  law.yield_strain = 300e6 / kE;
  return law;
}

// The rod's own monotonic response at strain e from the virgin state.
double rod_stress(const RodLaw& law, double e) { return evaluate(law, e, 0.0, 0.0).stress; }

TEST(LatticeMaterial, ElasticConstantsAreTheCentralForceLattice) {
  // docs/physics.md section 1: C11 = 2 kb/a, C12 = C44 = kb/a (the Cauchy relation), no coupling of
  // shear and normal components. Six products and sums: 1e-12 relative.
  const CauchyBornCrystal c(elastic_law(), kA, kArea);
  const auto C = c.elastic_constants();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double expected = 0;
      if (i < 3 && j < 3) expected = i == j ? 2 * kC : kC;
      if (i >= 3 && i == j) expected = kC;
      EXPECT_NEAR(C(i, j), expected, 1e-12 * kC) << i << "," << j;
    }
  EXPECT_NEAR(directional_youngs_modulus(C, {1, 0, 0}), kE100, 1e-12 * kE100);
  EXPECT_NEAR(directional_youngs_modulus(C, {1, 1, 0}), 2 * kC, 1e-12 * kC);
  EXPECT_NEAR(simple_shear_modulus(C, {1, 0, 0}, {0, 0, 1}), kC, 1e-12 * kC);  // C44
  EXPECT_NEAR(simple_shear_modulus(C, Eigen::Vector3d(1, 0, 1).normalized(), Eigen::Vector3d(-1, 0, 1).normalized()),
              0.5 * kC, 1e-12 * kC);  // (C11 - C12) / 2
  // Unbonded neighbours of the undeformed crystal: the second neighbours, a apart.
  EXPECT_NEAR(c.closest_unbonded(Eigen::Matrix3d::Identity()), kA, 1e-12 * kA);
}

// At a log strain of 1e-4 the finite-strain terms are O(strain): 1e-3 relative covers them
// (they are about 2e-4 here) and nothing else.
constexpr double kSmall = 1e-4, kSmallTol = 1e-3;

TEST(LatticeMaterial, Tension100IsE100WithPoissonRatioOneThird) {
  const auto pts = uniaxial_test(elastic_law(), kA, kArea, {1, 0, 0}, {0, kSmall}, kSmall);
  ASSERT_EQ(pts.size(), 2u);
  const auto& p = pts[1];
  EXPECT_NEAR(p.stress / p.strain, kE100, kSmallTol * kE100);  // E100 = 4 kb / (3a)
  const double nu_y = -std::log(p.deformation[4]) / p.strain, nu_z = -std::log(p.deformation[8]) / p.strain;
  EXPECT_NEAR(nu_y, 1.0 / 3.0, kSmallTol);
  EXPECT_NEAR(nu_z, 1.0 / 3.0, kSmallTol);
  // The lateral stresses vanish to the solver's tolerance (1e-10 kb/a).
  for (int i : {1, 2, 3, 4, 5}) EXPECT_LT(std::abs(p.sigma[i]), 1e-9 * kC) << i;
  EXPECT_NEAR(p.plastic_strain, 0.0, kSmallTol * kSmall);
}

TEST(LatticeMaterial, Tension110IsTheCubicCompliance) {
  // Cubic compliances with C11 = 2c, C12 = C44 = c (c = kb/a):
  //   S11 = (C11 + C12)/((C11 - C12)(C11 + 2 C12)) = 3c/(c 4c) = 3/(4c),
  //   S12 = -C12/((C11 - C12)(C11 + 2 C12)) = -1/(4c),  S44 = 1/C44 = 1/c.
  // 1/E(n) = S11 - 2 (S11 - S12 - S44/2)(n1^2 n2^2 + n2^2 n3^2 + n3^2 n1^2); for [110] the sum is
  // 1/4: 1/E110 = (S11 + S12 + S44/2)/2 = (3/4 - 1/4 + 1/2)/(2c) = 1/(2c), E110 = 2 kb/a = 1.5 E100.
  // Strains under sigma along [110]: eps_zz = S12 sigma, so nu[110->001] = -S12 E110 = 1/2;
  // along m = [-110]/sqrt2: eps_mm = (S11 + S12) sigma/2 - S44 sigma/4 = 0, so nu[110->-110] = 0.
  const auto pts = uniaxial_test(elastic_law(), kA, kArea, {1, 1, 0}, {0, kSmall}, kSmall);
  const auto& p = pts.back();
  EXPECT_NEAR(p.stress / p.strain, 2 * kC, kSmallTol * 2 * kC);
  EXPECT_NEAR(-std::log(p.deformation[4]) / p.strain, 0.0, kSmallTol);  // test axis 2 = [-110]
  EXPECT_NEAR(-std::log(p.deformation[8]) / p.strain, 0.5, kSmallTol);  // test axis 3 = [001]
  // The off-diagonal stretches stay zero by symmetry.
  for (int i : {1, 2, 3, 5, 6, 7}) EXPECT_LT(std::abs(p.deformation[i]), 1e-12) << i;
}

TEST(LatticeMaterial, ShearModuliAndTheZenerRatio) {
  const auto cube = simple_shear_test(elastic_law(), kA, kArea, {1, 0, 0}, {0, 0, 1}, kSmall, kSmall);
  const auto diag = simple_shear_test(elastic_law(), kA, kArea, {1, 0, 1}, {-1, 0, 1}, kSmall, kSmall);
  const double g_cube = cube.back().stress / kSmall, g_diag = diag.back().stress / kSmall;
  EXPECT_NEAR(g_cube, kC, kSmallTol * kC);           // C44 = kb/a
  EXPECT_NEAR(g_diag, 0.5 * kC, kSmallTol * kC);     // (C11 - C12)/2 = kb/(2a)
  EXPECT_NEAR(g_cube / g_diag, 2.0, 2 * kSmallTol);  // Zener ratio 2 C44/(C11 - C12) = 2
}

TEST(LatticeMaterial, FiniteStrainElasticTension100IsExact) {
  // Under uniaxial stress along [100] with axial stretch L and lateral stretch M, the four rods
  // (1,+-1,0), (1,0,+-1) stretch by s1 = sqrt((L^2 + M^2)/2) and the two (0,1,+-1) by s2 = M.
  // sigma_yy = 0 means 2 T1 M^2/(l0 s1) + 2 T2 M^2/(l0 s2) = 0 with T = E A (s - 1) (elastic
  // rods): 1/s1 + 1/s2 = 2. Then sigma_xx = 4 T1 (a/2)^2 L^2/(l0 s1) / ((a^3/4) L M^2). The
  // 1-D root is found here by bisection; the test's Newton stops at 1e-10 kb/a on the lateral
  // stresses, so stretch and stress agree to about 1e-10 relative; 1e-8 is asked.
  for (double eps : {0.05, 0.2, 0.5}) {
    const double L = std::exp(eps);
    double lo = 0.5, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
      const double M = 0.5 * (lo + hi), s1 = std::sqrt(0.5 * (L * L + M * M));
      (1 / s1 + 1 / M > 2 ? lo : hi) = M;
    }
    const double M = 0.5 * (lo + hi), s1 = std::sqrt(0.5 * (L * L + M * M));
    const double T1 = kE * kArea * (s1 - 1);
    const double sxx = 4 * T1 * 0.25 * kA * kA * L * L / (kL0 * s1) / (0.25 * kA * kA * kA * L * M * M);
    const auto pts = uniaxial_test(elastic_law(), kA, kArea, {1, 0, 0}, {0, eps}, 0.01);
    const auto& p = pts.back();
    EXPECT_NEAR(p.deformation[4], M, 1e-8) << eps;
    EXPECT_NEAR(p.stress, sxx, 1e-8 * sxx) << eps;
    EXPECT_NEAR(p.volume_ratio, L * M * M, 1e-8) << eps;
  }
}

TEST(LatticeMaterial, SmallStrainPlasticRelation100) {
  // docs/physics.md section 1: at small strain every rod carries |eps|/3 under uniaxial stress
  // along [100], so sigma_100(eps) = 3 (E100/E) sigma_rod(eps/3) for any rod law. The lattice
  // departs from it by the geometric nonlinearity (the rods turn towards the axis, the cross-
  // section changes, true stress against log strain), terms of relative size O(eps): measured
  // 2.5 eps (elastic, linear hardening and the curve alike, tension and compression to 0.01);
  // asked: 3 eps relative.
  for (const RodLaw& law : {linear_law(1e-3, 10e9), curve_law()})
    for (double end : {0.01, -0.01}) {
      const auto pts = uniaxial_test(law, kA, kArea, {1, 0, 0}, {0, end}, 1e-4);
      for (const auto& p : pts) {
        if (p.strain == 0) continue;
        const double small = 3 * kE100 / kE * rod_stress(law, p.strain / 3);
        EXPECT_NEAR(p.stress, small, 3 * std::abs(p.strain * small)) << "strain " << p.strain;
      }
    }
}

// The shear at which tau stops rising (its increment below half the elastic one): yield of
// perfectly plastic rods. 'modulus' the elastic shear modulus.
double shear_yield(const std::vector<MaterialPoint>& pts, double modulus) {
  for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    if (pts[i + 1].stress - pts[i].stress < 0.5 * modulus * (pts[i + 1].strain - pts[i].strain)) return pts[i].strain;
  return NAN;
}

TEST(LatticeMaterial, ShearOnTheCubePlane) {
  // F = I + g e_x (x) e_z moves a bond a/2 (x, y, z) to a/2 (x + g z, y, z). The rods (1,0,+-1)
  // go from length^2 (a/2)^2 2 to (a/2)^2 ((1 +- g)^2 + 1): strain +-g/2 to first order; the
  // rods (0,1,+-1) go to (a/2)^2 (2 + g^2): second order; (1,+-1,0) keep their length. So only
  // the two (1,0,+-1) rods carry, at +-s, and
  //   tau = sigma_xz = (1/(a^3/4)) 2 s A (a/2)^2 / (a/sqrt2) = 2 sqrt2 s A / a^2 = 2 s kb/(E a)
  // (A = kb l0/E, l0 = a/sqrt2). They yield at g = 2 eps_y.
  const CauchyBornCrystal c(elastic_law(), kA, kArea);
  const double g = kSmall;
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 2) = g;
  const auto t = c.evaluate(F);
  EXPECT_NEAR(t.rod_strain[2], g / 2, kSmallTol * g / 2);
  EXPECT_NEAR(t.rod_strain[3], -g / 2, kSmallTol * g / 2);
  for (int k : {0, 1}) EXPECT_NEAR(t.rod_strain[k], 0.0, 1e-15);
  for (int k : {4, 5}) EXPECT_LT(std::abs(t.rod_strain[k]), g * g);
  const double s = t.rod_stress[2];
  EXPECT_NEAR(t.sigma(0, 2), 2 * s * kKb / (kE * kA), kSmallTol * std::abs(2 * s * kKb / (kE * kA)));

  // Yield: perfectly plastic rods (k = 0); tau stops rising at g = 2 eps_y = 2e-3 (within one
  // increment, 1e-6, and the O(g) geometry).
  const double ey = 1e-3;
  const auto pts = simple_shear_test(linear_law(ey, 0.0), kA, kArea, {1, 0, 0}, {0, 0, 1}, 4 * ey, 1e-6);
  EXPECT_NEAR(shear_yield(pts, kC), 2 * ey, 2e-3 * 2 * ey);
  const double tau_y = 2 * (kE * ey) * kKb / (kE * kA);
  EXPECT_NEAR(pts.back().stress, tau_y, 2e-3 * tau_y);
  // Against [100] tension, sigma_y = 3 (E100/E) E eps_y = 4 kb E eps_y/(a E): tau_y/sigma_y = 1/2,
  // Tresca's ratio (von Mises would say 1/sqrt3). Same law, same strain range to yield and beyond.
  const auto ten = uniaxial_test(linear_law(ey, 0.0), kA, kArea, {1, 0, 0}, {0, 6 * ey}, 1e-6);
  EXPECT_NEAR(pts.back().stress / ten.back().stress, 0.5, 5e-3);
}

TEST(LatticeMaterial, ShearOnThe45DegreePlane) {
  // s = [101]/sqrt2, m = [-101]/sqrt2: a bond along the unit n stretches by g (n.s)(n.m) to first
  // order. (1,0,1): n.m = 0; (1,0,-1): n.s = 0; (1,+-1,0): n.s = 1/2, n.m = -1/2, strain -g/4;
  // (0,1,+-1): n.s = +-1/2, n.m = +-1/2, strain +g/4. Four rods at +-s, and
  //   tau = (1/(a^3/4)) sum s_k A (a/sqrt2)(n.s)(n.m) = (4/a^3) A (a/sqrt2) 4 s/4 = 2 s kb/(E a),
  // the same tau(s) as on the cube plane at twice the shear: yield at g = 4 eps_y.
  const CauchyBornCrystal c(elastic_law(), kA, kArea);
  const Eigen::Vector3d s = Eigen::Vector3d(1, 0, 1).normalized(), m = Eigen::Vector3d(-1, 0, 1).normalized();
  const double g = kSmall;
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + g * s * m.transpose();
  const auto t = c.evaluate(F);
  for (int k : {0, 1}) EXPECT_NEAR(t.rod_strain[k], -g / 4, kSmallTol * g / 4);
  for (int k : {4, 5}) EXPECT_NEAR(t.rod_strain[k], g / 4, kSmallTol * g / 4);
  for (int k : {2, 3}) EXPECT_LT(std::abs(t.rod_strain[k]), g * g);
  const double tau = s.dot(t.sigma * m), rod = t.rod_stress[4];
  EXPECT_NEAR(tau, 2 * rod * kKb / (kE * kA), kSmallTol * std::abs(tau));

  const double ey = 1e-3;
  const auto pts = simple_shear_test(linear_law(ey, 0.0), kA, kArea, {1, 0, 1}, {-1, 0, 1}, 6 * ey, 1e-6);
  EXPECT_NEAR(shear_yield(pts, 0.5 * kC), 4 * ey, 2e-3 * 4 * ey);
  const double tau_y = 2 * (kE * ey) * kKb / (kE * kA);
  EXPECT_NEAR(pts.back().stress, tau_y, 3e-3 * tau_y);
}

TEST(LatticeMaterial, CyclicBauschinger100) {
  // Linear kinematic hardening (k = 20 GPa, eps_y = 1e-3) through 0 -> 0.012 -> -0.012. At the
  // peak the rods sit at strain ~0.004 on the band's upper edge, sigma_rod = k 0.004 + (E - k)
  // eps_y = 260 MPa. Unloading runs down the elastic line (slope E) while the band's lower edge
  // k eps - (E - k) eps_y moves with the strain: they meet 2 E eps_y = 400 MPa lower (physics
  // notes section 4: the elastic range spans 2 sigma_02), at -140 MPa. The lateral stresses
  // vanish when the lateral rods carry minus the stress of the inclined ones, so all six re-yield
  // together, and in the bar (section 5) the reversal is at 3 (E100/E)(-140 MPa) = -311 MPa,
  // 2 x 3 (E100/E) E eps_y = 889 MPa below the peak. It is found where the unloading tangent first
  // falls below E100/2. Tolerance: 2 % of the 889 MPa range (the O(eps) geometry at eps = 0.012,
  // about 1.5 %, and one increment of 1e-5, 1.5 MPa).
  const double ey = 1e-3, k = 20e9;
  const auto pts = uniaxial_test(linear_law(ey, k), kA, kArea, {1, 0, 0}, {0, 0.012, -0.012}, 1e-5);
  std::size_t peak = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (pts[i].strain > pts[peak].strain) peak = i;
  double s_rev = NAN;
  for (std::size_t i = peak + 1; i + 1 < pts.size(); ++i) {
    const double tangent = (pts[i + 1].stress - pts[i].stress) / (pts[i + 1].strain - pts[i].strain);
    if (tangent < 0.5 * kE100) {
      s_rev = pts[i].stress;
      break;
    }
  }
  const double factor = 3 * kE100 / kE, range = 2 * factor * kE * ey;
  EXPECT_NEAR(s_rev, factor * (k * 0.004 + (kE - k) * ey - 2 * kE * ey), 0.02 * range);
  EXPECT_NEAR(pts[peak].stress - s_rev, range, 0.02 * range);
}

TEST(LatticeMaterial, CompressionMirrorsTensionAtSmallStrain) {
  // The rod law is odd (compression mirrors tension); the lattice breaks the symmetry only through
  // the geometry: each side departs from the small-strain relation by about 2.5 |eps| (above), in
  // opposite senses, so |sigma(-eps)| and sigma(eps) differ by about 5 |eps| relative (measured
  // 5.0 eps to |eps| = 0.01); asked: 6 |eps|. The plastic strains differ by that stress difference
  // over E100.
  for (const RodLaw& law : {linear_law(1e-3, 10e9), curve_law()}) {
    const auto t = uniaxial_test(law, kA, kArea, {1, 0, 0}, {0, 0.005}, 1e-4);
    const auto c = uniaxial_test(law, kA, kArea, {1, 0, 0}, {0, -0.005}, 1e-4);
    ASSERT_EQ(t.size(), c.size());
    for (std::size_t i = 1; i < t.size(); ++i) {
      const double tol = 6 * t[i].strain * std::abs(t[i].stress);
      EXPECT_DOUBLE_EQ(c[i].strain, -t[i].strain);
      EXPECT_NEAR(-c[i].stress, t[i].stress, tol) << t[i].strain;
      EXPECT_NEAR(c[i].plastic_strain, t[i].plastic_strain, tol / kE100) << t[i].strain;
    }
  }
}

TEST(LatticeMaterial, FailureByStrainWhereTheMostStretchedRodReachesIt) {
  RodLaw law = elastic_law();
  law.failure_strain = 0.05;
  // [100]: the four (1,+-1,0), (1,0,+-1) rods are the most stretched, at s1 = 1.05 when they
  // fail; with the lateral relation above (1/s1 + 1/M = 2), M = 1/(2 - 1/s1) and
  // L = sqrt(2 s1^2 - M^2): ln L = 0.12881. The first break lies within the increment before it;
  // then only the (0,1,+-1) rods are left, perpendicular to the axis: no stress, and the test stops.
  {
    const double s1 = 1.05, M = 1 / (2 - 1 / s1), eps_f = std::log(std::sqrt(2 * s1 * s1 - M * M));
    const double inc = 1e-4;
    const auto pts = uniaxial_test(law, kA, kArea, {1, 0, 0}, {0, 0.5}, inc);
    std::size_t b = 0;
    while (b < pts.size() && pts[b].broken == 0) ++b;
    ASSERT_LT(b, pts.size());
    EXPECT_EQ(pts[b].broken, 4);
    EXPECT_LE(pts[b - 1].strain, eps_f);
    EXPECT_GE(pts[b].strain, eps_f);
    EXPECT_EQ(b, pts.size() - 1);  // stopped: the stress dropped to zero
    EXPECT_NEAR(pts.back().stress, 0.0, 1e-6 * kC);
  }
  // [110]: the (1,1,0) rod lies on the axis, its stretch is the axial stretch: it fails at
  // ln 1.05 exactly; the rest is a stress-free mechanism then, and the test stops.
  {
    const auto pts = uniaxial_test(law, kA, kArea, {1, 1, 0}, {0, 0.5}, 1e-4);
    std::size_t b = 0;
    while (b < pts.size() && pts[b].broken == 0) ++b;
    ASSERT_LT(b, pts.size());
    EXPECT_LE(pts[b - 1].strain, std::log(1.05));
    EXPECT_GE(pts[b].strain, std::log(1.05));
    EXPECT_LT(pts.back().equivalent_stress, 1e-6 * pts[b - 1].equivalent_stress);
  }
}

TEST(LatticeMaterial, ContactRangeInLargeShear) {
  // At gamma = 2 on the cube plane the third neighbour a/2 (-2,1,1) lands on a/2 (0,1,1): one
  // rest length away, the DEM's contact range 2R.
  const auto pts = simple_shear_test(elastic_law(), kA, kArea, {1, 0, 0}, {0, 0, 1}, 2.0, 0.01);
  EXPECT_DOUBLE_EQ(pts.back().strain, 2.0);
  EXPECT_NEAR(pts.back().closest_unbonded, kL0, 1e-12 * kL0);
  EXPECT_NEAR(pts.back().volume_ratio, 1.0, 1e-14);
}

TEST(LatticeMaterial, BadArgumentsAreRefused) {
  const RodLaw law = elastic_law();
  EXPECT_THROW(uniaxial_test(law, kA, kArea, {0, 0, 0}, {0, 0.1}, 1e-3), InputError);
  EXPECT_THROW(uniaxial_test(law, kA, kArea, {1, 0, 0}, {0.1, 0.2}, 1e-3), InputError);
  EXPECT_THROW(uniaxial_test(law, kA, kArea, {1, 0, 0}, {0, 0.1}, 0.0), InputError);
  EXPECT_THROW(uniaxial_test(law, -kA, kArea, {1, 0, 0}, {0, 0.1}, 1e-3), InputError);
  EXPECT_THROW(simple_shear_test(law, kA, kArea, {1, 0, 0}, {1, 0, 1}, 1.0, 1e-3), InputError);
  EXPECT_THROW(simple_shear_test(law, kA, kArea, {1, 0, 0}, {0, 0, 1}, -1.0, 1e-3), InputError);
}

}  // namespace
}  // namespace swarf
