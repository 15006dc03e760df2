// contacts.cpp: the contacts' evaluation over the lists (Hertz with overlap-area weighting,
// friction), their sums per particle, commit and energy (see contacts.h; the lists are built
// in contact_lists.cpp).
#include "swarf/contacts/contacts.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/parallel.h"
#include "swarf/geometry/overlap_area.h"
#include "swarf/laws/friction.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"

namespace swarf {
void ContactSystem::evaluate(const Particles& p, double h, bool final) {
  if (!enabled_) return;
  const FrictionRule rule{prm_.law, prm_.friction, prm_.regularization_speed, h};
  const double eta_ratio = prm_.tangential_damping;
  const std::size_t np = pairs_.size(), nt = tris_.size();
  // Raw pointers: the flag stores (uint8_t) may alias anything, and the compiler would
  // otherwise reload every array's base for every pair.
  const Pair* pairs = pairs_.data();
  const std::int32_t* prow = prow_.data();
  Result* psum = psum_.data();
  const PairConstants* pconst = pconst_.data();
  const bool uniform = uniform_;
  const PairConstants uc = uniform_constants_;
  Vec3* phist = phist_.data();
  // Final evaluation: the trial history is the committed one (written in place).
  Vec3* ph = final ? phist_.data() : ph_.data();
  std::uint8_t* touch = ptouch_.data();
  Result* pres = pres_.data();
  double* pe = pe_.data();
  TriPair* tris = tris_.data();
  Vec3* th = th_.data();
  std::uint8_t* ttouch = ttouch_.data();
  Result* tres = tres_.data();
  Vec3* tpoint = tpoint_.data();
  double* te = te_.data();
  const Vec3* x = p.position.data();
  const Vec3* v = p.velocity.data();
  const Vec3* w = p.omega.data();
  const double* radius = p.radius.data();
  const double* temperature = p.temperature.empty() ? nullptr : p.temperature.data();
  const StickingRule stick_rule = prm_.sticking;
  const SpeedFriction tool_friction = prm_.tool_friction;
  const Periodic periodic = periodic_;
  const std::vector<MeshBody>& meshes = *meshes_;
  const std::int32_t* tri_mesh = tri_mesh_.data();
  const std::int32_t* tri_local = tri_local_.data();
  const TriangleFrame* tri_frame = tri_frame_.data();
  // One parallel region for both kinds. Pairs: a fixed partition into contiguous rows, so
  // that each thread evaluates the pairs of particles it moved and will gather (the list is
  // sorted by first particle; static partitions beat dynamic chunks, validation/bench/README.md).
  // Triangle contacts: dynamic, they cost as much as tens of pairs each and
  // cluster at a wall or the tool; chunks small enough for every thread to get several. Each
  // contact writes only its own slots, and each particle's sum is made in pair order by one
  // thread (or again from the slots, see Sums): the results do not depend on the threads.
  const int tchunk = static_cast<int>(std::clamp<std::size_t>(nt / 64, 4, 256));
#pragma omp parallel if (np + 16 * nt > 256)
  {
    // Pairs in one flat loop (a loop per row, ~2 pairs long, mispredicted its exits and cost
    // more than the pairs), each thread over a contiguous range of rows (a row: the pairs
    // whose first particle is i) with an equal share of pairs and particles. Touching pairs
    // also add their results to both particles' sums, in pair order, when the thread owns
    // both (the gather then reads one sum; see Sums).
    const int nthreads = omp_get_num_threads();
#pragma omp single
    partition(nthreads);
    const std::size_t row_begin = row_split_[static_cast<std::size_t>(omp_get_thread_num())];
    const std::size_t row_end = row_split_[static_cast<std::size_t>(omp_get_thread_num()) + 1];
    std::fill(psum + row_begin, psum + row_end, Result{Vec3::Zero(), Vec3::Zero()});
    for (std::size_t k = static_cast<std::size_t>(prow[row_begin]), kend = static_cast<std::size_t>(prow[row_end]);
         k < kend; ++k) {
      const std::int32_t i = pairs[k].i, j = pairs[k].j;
      Vec3 d = x[j] - x[i];
      periodic.wrap(d);
      const double ri = radius[i], rj = radius[j];
      const double dist2 = d.squaredNorm(), sum = ri + rj;
      if (dist2 >= sum * sum) {
        // A near miss. A contact that just separated gets zero results; a final evaluation
        // also ends its history (trial evaluations leave that to commit()).
        if (touch[k]) {
          pres[k] = Result{Vec3::Zero(), Vec3::Zero()};
          if (final) phist[k] = Vec3::Zero();
          touch[k] = 0;
        }
        continue;
      }
      touch[k] = 1;
      const double dist = std::sqrt(dist2);
      const Vec3 n = (1.0 / dist) * d;
      const double delta = sum - dist, root = std::sqrt(delta), root4 = std::sqrt(root);
      const PairConstants& q = uniform ? uc : pconst[k];
      const HertzLaw hz{q.K, q.D};
      const Vec3 vrel = v[j] + w[j].cross(-rj * n) - v[i] - w[i].cross(ri * n);
      const double vn = vrel.dot(n);
      const double fn = hz.force(delta, root, root4, -vn);
      const Vec3 vt = vrel - vn * n;
      Vec3 hist = phist[k];
      const Vec3 ft_j = friction_force(rule, n, vt, fn, q.kt0 * root, eta_ratio * q.D * root4, hist);
      const Result r{-fn * n - ft_j, ft_j.cross(n)};
      pres[k] = r;
      psum[i].force += r.force;
      psum[i].torque_arm += r.torque_arm;
      if (static_cast<std::size_t>(j) < row_end) {  // (else j's sum is made from the results)
        psum[j].force -= r.force;
        psum[j].torque_arm += r.torque_arm;
      }
      ph[k] = hist;
      pe[k] = 0.4 * q.K * delta * delta * root;
    }
#pragma omp for schedule(dynamic, tchunk)
    for (std::size_t k = 0; k < nt; ++k) {
      TriPair& q = tris[k];
      const std::int32_t i = q.i, t = q.tri;
      const MeshBody& mb = meshes[tri_mesh[t]];
      const double R = radius[i];
      const SphereTriangleHit hit = triangle_hit(mb, tri_local[t], tri_frame[t], x[i], R);
      if (!hit.touching) {
        if (ttouch[k]) {
          tres[k] = Result{Vec3::Zero(), Vec3::Zero()};
          if (final) q.history = Vec3::Zero();
          ttouch[k] = 0;
        }
        continue;
      }
      ttouch[k] = 1;
      const Vec3 n = hit.normal;  // from the wall towards the sphere
      const HertzLaw hz{q.K, q.D};
      // The force acts on the wall at the sphere's surface point x - R n: its normal part
      // passes through the centre, its tangential part is the sphere's torque arm, so the
      // wall's torque about any point balances the sphere's angular momentum exactly.
      const Vec3 at = x[i] - R * n;
      tpoint[k] = at;
      const Vec3 vrel = v[i] + w[i].cross(-R * n) - mb.velocity_at(at);  // sphere relative to the wall
      const double vn = vrel.dot(n);
      const double root = std::sqrt(hit.overlap), root4 = std::sqrt(root);
      const double fn = hit.weight * hz.force(hit.overlap, root, root4, -vn);
      const Vec3 vt = vrel - vn * n;
      Vec3 hist = q.history;
      // The sphere plays body j (it moves relative to the wall): the friction on it is ft.
      const double slip = stick_rule.flow_zone > 0.0 ? vt.norm() : 0.0;  // the flow zone's heat (sticking.h)
      const double stick = hit.weight * sticking_cap(stick_rule, R, temperature ? temperature[i] : 0.0, slip);
      const Vec3 ft = friction_force(at_sliding_speed(rule, tool_friction, vt), n, vt, fn, hit.weight * q.kt0 * root,
                                     hit.weight * eta_ratio * q.D * root4, hist, stick);
      tres[k] = Result{fn * n + ft, ft.cross(n)};
      if (final)
        q.history = hist;
      else
        th[k] = hist;
      te[k] = hit.weight * 0.4 * q.K * hit.overlap * hit.overlap * root;
    }
  }
}

ContactSystem::Sums ContactSystem::sums() const {
  return Sums{pres_.data(), psum_.data(), spanning_.data(), prow_.data(),
              jrow_.data(), jent_.data(), tres_.data(),     trow_.data()};
}

void ContactSystem::partition(int nthreads) {
  if (partition_version_ == list_version_ && row_split_.size() == static_cast<std::size_t>(nthreads) + 1) return;
  // Equal shares of the weight w(i) = (pairs in rows before i) + kRowWeight i: the rows
  // cluster where the contacts are (a chip, a pile), so equal numbers of particles would not
  // do. The partition depends on the threads, the results do not (see Sums).
  constexpr std::int64_t kRowWeight = 2;
  const std::size_t n = prow_.size() - 1;
  const std::int32_t* prow = prow_.data();
  auto weight = [&](std::size_t i) { return std::int64_t(prow[i]) + kRowWeight * std::int64_t(i); };
  const std::int64_t total = weight(n);
  row_split_.assign(static_cast<std::size_t>(nthreads) + 1, n);
  row_split_[0] = 0;
  for (int s = 1; s < nthreads; ++s) {
    const std::int64_t target = total * s / nthreads;
    std::size_t lo = 0, hi = n;  // the first i with weight(i) >= target
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (weight(mid) < target)
        lo = mid + 1;
      else
        hi = mid;
    }
    row_split_[static_cast<std::size_t>(s)] = lo;
  }
  // A particle with a pair in an earlier thread's rows has its sum made from the results.
  spanning_.assign(n, 0);
  for (int t = 0; t < nthreads; ++t)
    for (std::size_t i = row_split_[t]; i < row_split_[t + 1]; ++i)
      spanning_[i] = static_cast<std::size_t>(jmin_[i]) < row_split_[t];
  partition_version_ = list_version_;
}

void ContactSystem::add_to_particle(std::size_t i, double radius, Vec3& force, Vec3& torque) const {
  sums().add(i, radius, force, torque);
}

void ContactSystem::commit() {
  const std::size_t np = pairs_.size(), nt = tris_.size();
#pragma omp parallel
  {
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < np; ++k) phist_[k] = ptouch_[k] ? ph_[k] : Vec3::Zero();
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < nt; ++k) tris_[k].history = ttouch_[k] ? th_[k] : Vec3::Zero();
  }
}

void ContactSystem::mesh_forces(std::vector<Vec3>& out) const {
  out.assign(meshes_->size(), Vec3::Zero());
  for (std::size_t k = 0; k < tris_.size(); ++k)
    if (ttouch_[k]) out[tri_mesh_[tris_[k].tri]] -= tres_[k].force;
}

void ContactSystem::mesh_wrenches(std::vector<Vec3>& force, std::vector<Vec3>& torque) const {
  const std::size_t nm = meshes_->size();
  force.assign(nm, Vec3::Zero());
  torque.assign(nm, Vec3::Zero());
  for (std::size_t k = 0; k < tris_.size(); ++k) {
    if (!ttouch_[k]) continue;
    const std::int32_t m = tri_mesh_[tris_[k].tri];
    const Vec3 f = -tres_[k].force;
    force[m] += f;
    torque[m] += (tpoint_[k] - (*meshes_)[m].centre()).cross(f);
  }
}

Vec3 ContactSystem::mesh_force_in_band(std::size_t m, int axis, double lo, double hi) const {
  Vec3 f = Vec3::Zero();
  for (std::size_t k = 0; k < tris_.size(); ++k)
    if (ttouch_[k] && static_cast<std::size_t>(tri_mesh_[tris_[k].tri]) == m && tpoint_[k][axis] >= lo &&
        tpoint_[k][axis] < hi)
      f -= tres_[k].force;
  return f;
}

double ContactSystem::elastic_energy() const {
  double e = 0.0;
  for (std::size_t k = 0; k < pe_.size(); ++k)
    if (ptouch_[k]) e += pe_[k];
  for (std::size_t k = 0; k < te_.size(); ++k)
    if (ttouch_[k]) e += te_[k];
  return e;
}

std::size_t ContactSystem::touching_pairs() const {
  std::size_t c = 0;
  for (auto t : ptouch_) c += t;
  return c;
}

std::size_t ContactSystem::touching() const {
  std::size_t c = touching_pairs();
  for (auto t : ttouch_) c += t;
  return c;
}

double ContactSystem::ghost_reach(const Particles& p) const {
  double largest = 0.0;
  for (double r : p.radius) largest = std::max(largest, r);
  return 2.0 * largest + prm_.skin;
}

}  // namespace swarf
