// main.cpp: co-simulation of swarf with an outside multibody code (docs/embedding.md,
// "Co-simulation"), through swarf/body_coupling.h.
//
// The multibody code is written here: a swing, a bucket of mass M hung from two parallel links
// of length L (a parallelogram, so the bucket translates on a circle without turning), one
// degree of freedom, the angle theta, integrated by velocity Verlet with its own step H:
//     M L theta'' = -M g sin(theta) + F . e_t,    e_t = (cos theta, 0, sin theta),
// F being the force the particles exert on the bucket. swarf owns a bed of loose spheres on a
// floor under gravity and the bucket's triangles, held (fixed = xyz, no rotation) for the
// multibody code to drive. Each exchange (every H):
//   1. the swing takes its step with the force of the last exchange held, and says where the
//      bucket is at its end;
//   2. swarf moves the bucket there over H at the secant velocity, sub-cycling its own steps
//      (10 of dt here), and returns the particles' impulse on it;
//   3. the swing holds impulse / H over its next step.
// Released at theta0, the bucket swings down through the bed, throws spheres ahead and loses
// energy to them.
//
// Checks (exit 1 if one fails): the work the particles did on the bucket as the swing saw it
// (its held forces over its own displacements) and as swarf measured it (each step's force
// over the bucket's displacement) agree within 10 % of it: they differ by the interface's
// first-order error (tests/test_body_coupling.cpp measures its order); and the swing's energy
// change equals the work it received to 1e-3 of its initial energy (its own Verlet's error).
// Writes cosim_swing.csv (the exchanges) in the working directory. Units SI.
#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

#include "swarf/body_coupling.h"
#include "swarf/core/errors.h"
#include "swarf/geometry/mass_properties.h"
#include "swarf/geometry/shapes.h"
#include "swarf/laws/hertz.h"
#include "swarf/simulation.h"

namespace {

using swarf::Vec3;

// The swing (the multibody side).
constexpr double kLinkLength = 0.05;  // m
constexpr double kBucketMass = 5e-3;  // kg
constexpr double kTheta0 = -0.3;      // rad, released from rest
constexpr double kPivotZ = 0.053;     // m: the bucket's centre passes 3 mm above the floor
constexpr double kGravity = 9.81;     // m/s^2
// The bed (swarf's side): spheres in a simple cubic pack on a floor at z = 0.
constexpr double kRadius = 1e-3;      // m
constexpr int kBed[3] = {10, 4, 2};   // spheres along x, y, z
constexpr double kDensity = 2500.0;   // kg/m^3
constexpr double kYoungs = 1e8;       // Pa
constexpr double kRestitution = 0.5;  // 1
constexpr double kFriction = 0.3;     // 1
constexpr double kDt = 5e-6;          // s: swarf's step (a fifth of the spheres' Rayleigh time is 1.1e-5 s)
constexpr int kSubSteps = 10;         // swarf steps per exchange
constexpr double kEndTime = 0.3;      // s

Vec3 bucket_at(double theta) {
  return Vec3(kLinkLength * std::sin(theta), 0.0, kPivotZ - kLinkLength * std::cos(theta));
}

swarf::World make_world() {
  swarf::World w;
  auto& p = w.particles;
  const int n = kBed[0] * kBed[1] * kBed[2];
  p.resize(n);
  const double m = kDensity * 4.0 / 3.0 * M_PI * kRadius * kRadius * kRadius;
  int i = 0;
  for (int k = 0; k < kBed[2]; ++k)
    for (int j = 0; j < kBed[1]; ++j)
      for (int l = 0; l < kBed[0]; ++l, ++i) {
        p.position[i] = p.initial_position[i] = Vec3(-4e-3 + 2 * kRadius * l, -3e-3 + 2 * kRadius * j,
                                                     kRadius + 2 * kRadius * k);
        p.radius[i] = kRadius;
        p.mass[i] = m;
        p.inv_mass[i] = 1.0 / m;
        p.inertia[i] = Vec3::Constant(0.4 * m * kRadius * kRadius);
        p.inv_inertia[i] = 1.0 / p.inertia[i][0];
      }
  w.rods.build_rows(n);  // (no rods: a loose bed)
  // The floor: a fixed slab under the bed. The bucket: a box held for the swing to drive.
  swarf::MeshBody floor;
  floor.name = "floor";
  floor.mesh = swarf::box_mesh(Vec3(0.0, 0.0, -1e-3), Vec3(0.1, 0.02, 2e-3));
  floor.youngs_modulus = HUGE_VAL;
  w.meshes.push_back(floor);
  w.mesh_motion.push_back(swarf::Motion{});
  swarf::MeshBody bucket;
  bucket.name = "bucket";
  bucket.mesh = swarf::box_mesh(bucket_at(kTheta0), Vec3(4e-3, 10e-3, 4e-3));
  bucket.youngs_modulus = HUGE_VAL;
  w.meshes.push_back(bucket);
  w.mesh_motion.push_back(swarf::Motion{});
  // (swarf's mass for the held bucket does not enter its motion; the swing's M does)
  swarf::RigidBody rb = swarf::rigid_body_of(1, w.meshes[1].mesh, 1000.0);
  rb.fixed = 7;
  rb.rotation = swarf::BodyRotation::Prescribed;
  w.bodies.push_back(rb);
  w.contacts = true;
  w.contact.youngs_modulus = kYoungs;
  w.contact.poisson_ratio = 0.3;
  w.contact.alpha = swarf::restitution_to_alpha(kRestitution);
  w.contact.friction = kFriction;
  w.contact.law = swarf::FrictionLaw::Spring;
  w.contact.skin = 0.2 * kRadius;
  w.gravity = Vec3(0.0, 0.0, -kGravity);
  return w;
}

}  // namespace

int main() {
  try {
    swarf::World world = make_world();
    swarf::StepSettings set;
    set.dt = kDt;
    swarf::Simulation sim(world, set);
    swarf::BodyCoupling coupling(sim, 0);

    const double H = kSubSteps * kDt, M = kBucketMass, L = kLinkLength;
    double theta = kTheta0, omega = 0.0;
    Vec3 F = Vec3::Zero();  // N: the force held over the swing's step (the last exchange's)
    auto accel = [&](double th) {
      const Vec3 e_t(std::cos(th), 0.0, std::sin(th));
      return (-M * kGravity * std::sin(th) + F.dot(e_t)) / (M * L);
    };
    auto energy = [&] { return 0.5 * M * L * L * omega * omega + M * kGravity * bucket_at(theta).z(); };
    const double e0 = energy();
    double work_swing = 0.0, work_swarf = 0.0, lowest = 1.0;  // J, J, m
    std::FILE* csv = std::fopen("cosim_swing.csv", "w");
    if (!csv) throw swarf::InputError("cannot write cosim_swing.csv in the working directory");
    std::fprintf(csv,
                 "time_s,angle_rad,angular_velocity_rad_per_s,force_x_N,force_z_N,swing_energy_J,"
                 "work_on_swing_J,work_measured_by_swarf_J\n");
    while (sim.time() < kEndTime) {
      // 1. the swing's velocity Verlet step under the held force
      const Vec3 x0 = bucket_at(theta);
      omega += 0.5 * H * accel(theta);
      theta += H * omega;
      omega += 0.5 * H * accel(theta);
      const Vec3 x1 = bucket_at(theta);
      work_swing += F.dot(x1 - x0);
      // 2. swarf moves the bucket there and steps the bed
      const swarf::BodyExchange ex = coupling.advance(x1, H);
      work_swarf += ex.work.sum();
      // 3. the force to hold next
      F = ex.impulse / H;
      lowest = std::min(lowest, world.bodies[0].state.position.z());
      std::fprintf(csv, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", sim.time(), theta, omega, F.x(), F.z(), energy(),
                   work_swing, work_swarf);
    }
    std::fclose(csv);
    const double e1 = energy();
    std::printf("swing: released at %.3f rad, at t = %.3f s at %.4f rad, %.4f rad/s; bucket centre as low as %.2f mm\n",
                kTheta0, sim.time(), theta, omega, lowest * 1e3);
    std::printf("swing energy %.6g J -> %.6g J (change %.4g J)\n", e0, e1, e1 - e0);
    std::printf("work of the particles on the bucket: %.6g J as the swing saw it, %.6g J as swarf measured it\n",
                work_swing, work_swarf);
    const double mismatch = std::abs(work_swing - work_swarf), scale = std::abs(work_swarf);
    const double swing_error = std::abs(e1 - e0 - work_swing);
    std::printf("interface mismatch %.3g J (%.2f %% of the work); swing's own energy error %.3g J (%.2e of e0)\n",
                mismatch, 100 * mismatch / scale, swing_error, swing_error / e0);
    bool ok = true;
    if (!(scale > 0.05 * e0)) {
      std::printf("FAIL: the bucket did not plough the bed (work %.3g J against e0 %.3g J)\n", scale, e0);
      ok = false;
    }
    if (!(mismatch <= 0.1 * scale)) {
      std::printf("FAIL: the interface's work mismatch exceeds 10 %%\n");
      ok = false;
    }
    if (!(swing_error <= 1e-3 * e0)) {
      std::printf("FAIL: the swing's energy change is not the work it received\n");
      ok = false;
    }
    std::printf("wrote cosim_swing.csv (%s)\n", ok ? "checks passed" : "checks FAILED");
    return ok ? 0 : 1;
  } catch (const swarf::InputError& e) {
    std::fprintf(stderr, "cosim: %s\n", e.what());
    return 2;
  } catch (const swarf::SimulationError& e) {
    std::fprintf(stderr, "cosim: the run blew up: %s\n", e.what());
    return 3;
  }
}
