// contacts.h: Hertz contacts with friction between unbonded spheres and between spheres and
// triangles (paper section 4; docs/physics.md sections 5 and 6).
//
// Neighbour search: cell lists build Verlet lists of candidate pairs within the contact
// distance plus a skin; the lists are rebuilt when a particle (or a mesh) has moved more
// than half the skin since the last build, so the search costs O(N) and happens rarely.
// Bonded pairs are not contact pairs; a pair whose rod broke becomes one right after the
// break (add_pairs merges it into the lists). Lists are sorted, so results do not depend on
// the threads.
//
// Each contact is evaluated as a pure function of the current state and its COMMITTED
// friction history (the Cundall-Strack spring); the trial history is committed with the
// rods after a step converged. Histories follow their pair across rebuilds.
//
// Sphere-triangle: each triangle in reach contributes (Ao/Ac) (Hertz force) along its normal,
// Ao/Ac being the exact fraction of the sphere's cut circle inside the triangle
// (overlap_area.h), so flat surfaces push the same however they are triangulated.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/exact_sum.h"
#include "swarf/core/parallel.h"
#include "swarf/core/periodic.h"
#include "swarf/core/sym_tensor.h"
#include "swarf/core/vec3.h"
#include "swarf/geometry/overlap_area.h"
#include "swarf/laws/contact_params.h"
#include "swarf/laws/friction.h"
#include "swarf/laws/hertz.h"
#include "swarf/state/bodies.h"
#include "swarf/state/mesh.h"
#include "swarf/state/particles.h"

namespace swarf {

struct Rods;
class StateArchive;

class ContactSystem {
 public:
  struct Pair {  // a sphere-sphere candidate pair, i < j
    std::int32_t i, j;
  };
  void setup(const ContactParams& params, std::size_t n_particles, std::vector<MeshBody>* meshes,
             Periodic periodic = {});
  bool enabled() const { return enabled_; }

  /// Rebuilds the Verlet lists if anything moved more than half the skin (or 'force').
  /// 'moved2': the largest squared displacement (m^2) of a particle since the last build
  /// (from build_positions()) if the caller measured it in its own pass; < 0: measured here.
  void update_lists(const Particles& p, const Rods& rods, bool force, double moved2 = -1.0);
  /// Positions at the last build (null before the first): integrators measure the
  /// displacement since the build in the pass that moves the particles.
  const Vec3* build_positions(std::size_t n_particles) const {
    return x_build_.size() == n_particles ? x_build_.data() : nullptr;
  }

  /// Adds the pairs of rods that just broke to the lists (a full build is not needed: only
  /// those pairs change from bonded to candidates). Keeps the last evaluation's results.
  void add_pairs(const Particles& p, std::vector<std::array<std::int32_t, 2>> pairs);

  /// The candidate pairs (i < j, in list order) whose centres are closer than
  /// (r_i + r_j)(1 - overlap): the pairs that bond under bond_formation.h (overlap < 0: a gap,
  /// found only within the lists' skin). 'keep' filters them
  /// by their indices (the caller's own rule, e.g. lattice particles only).
  template <class Keep>
  std::vector<std::array<std::int32_t, 2>> pressed_pairs(const Particles& p, double overlap, Keep&& keep) const;
  /// Removes these pairs (i < j, sorted) from the lists with their histories: they were
  /// bonded. Pairs not in the lists are ignored. Keeps the others' last results.
  void remove_pairs(const Particles& p, const std::vector<std::array<std::int32_t, 2>>& pairs);

  /// Evaluates every contact at the current state over a step of size h (s) from the
  /// committed histories; fills per-contact forces and torques and trial histories.
  /// 'final': this evaluation is the step's last (explicit scheme): the histories are
  /// committed in place and commit() must not be called.
  void evaluate(const Particles& p, double h, bool final = false);

  // Per-contact results of the last evaluation (zero for a contact that does not touch). The
  // tangential force ft on a sphere of radius R acts at -R n from its centre (n: unit normal
  // pointing at it), a torque R (ft x n) (same vector for both spheres of a pair: ft and n
  // both flip): 'torque_arm' holds ft x n, a particle's torque is its radius times the sum
  // of its contacts' arms.
  struct Result {
    Vec3 force;       // on sphere i of a pair (on the sphere for a triangle contact), N
    Vec3 torque_arm;  // ft x n, N
  };
  /// The results' per-particle sums, as raw pointers that a hot loop keeps in registers
  /// (valid until the lists change). The evaluation sums each particle's pair results in
  /// pair order; a particle whose pairs were evaluated by two threads ('spanning') gets the
  /// same sum, in the same order, from the per-pair results here, so the sums do not depend
  /// on the threads.
  struct Sums {
    const Result* pres;
    const Result* psum;            // per particle: the sum over its pairs, in pair order
    const std::uint8_t* spanning;  // per particle: psum not made (pairs in two threads)
    const std::int32_t *prow, *jrow, *jent;
    const Result* tres;
    const std::int32_t* trow;
    /// Adds the contact force and torque on particle i, of radius 'radius' (m), summed over
    /// its contacts in a fixed order, N and N m. No test per contact: results of contacts
    /// that do not touch are zero (a branch on the touch flag or on the side mispredicts
    /// often and costs more than the sums).
    void add(std::size_t i, double radius, Vec3& force, Vec3& torque) const {
      Vec3 f, arm;
      if (!spanning[i]) {
        f = psum[i].force;
        arm = psum[i].torque_arm;
      } else {
        // Pair order: the pairs where i is second come first (their first particle is lower).
        f = Vec3::Zero();
        arm = Vec3::Zero();
        for (std::int32_t e = jrow[i], end = jrow[i + 1]; e < end; ++e) {
          const Result& r = pres[jent[e]];
          f -= r.force;
          arm += r.torque_arm;
        }
        for (std::int32_t k = prow[i], end = prow[i + 1]; k < end; ++k) {
          f += pres[k].force;
          arm += pres[k].torque_arm;
        }
      }
      for (std::int32_t k = trow[i], end = trow[i + 1]; k < end; ++k) {  // triangle contacts, by particle
        f += tres[k].force;
        arm += tres[k].torque_arm;
      }
      force += f;
      torque += radius * arm;
    }
  };
  Sums sums() const;
  /// sums().add(i, radius, force, torque).
  void add_to_particle(std::size_t i, double radius, Vec3& force, Vec3& torque) const;

  /// Adds each touching contact's moment sym((x_c - x_i) (x) f) on each of its spheres to
  /// w[i] (xx, yy, zz, xy, yz, xz; N m), from the last evaluation's results: sphere-sphere at
  /// x_c - x_i = R_i n (n from i to j, nearest image), sphere-triangle at -R_i n (n from the
  /// wall to the sphere). Divided by a volume it is the contacts' part of the particle stress
  /// (measure/particle_fields.h). 'w' has one entry per particle.
  void add_virial(const Particles& p, std::vector<SymTensor>& w) const;

  /// Writes the trial histories back (after a converged step).
  void commit();

  // The contacts' part of the Newmark step's Jacobian, for the Newton solver (contact_tangent.cpp;
  // the rods' part is forces/rod_tangent.h). Each touching contact gets a block
  // S = kx K + kv C = lateral I + axial n n^T (kx = beta h^2 in s^2, kv = gamma h in s).
  /// Sets up every contact's block at the current state (that of the latest evaluate(), with
  /// the same step h) from the committed histories. Parallel over contacts.
  void tangent(const Particles& p, double h, double kx, double kv);
  /// Read access to the blocks, for the hot loops of the Krylov solve (valid until the lists
  /// change or tangent() runs again).
  struct TangentRows {
    const Pair* pairs;
    const std::int32_t *prow, *jrow, *jent, *trow;
    const Vec3 *paxis, *taxis;        // unit normals, 1
    const double *paxial, *plateral;  // sphere-sphere blocks, kg
    const double *taxial, *tlateral;  // sphere-triangle blocks, kg
    /// Adds particle i's diagonal block (its contacts' S) to b.
    template <class Matrix>
    void add_diagonal(std::size_t i, Matrix& b) const {
      auto add = [&](const Vec3& n, double axial, double lateral) {
        b.diagonal().array() += lateral;
        b.noalias() += axial * (n * n.transpose());
      };
      for (std::int32_t e = jrow[i], end = jrow[i + 1]; e < end; ++e)
        add(paxis[jent[e]], paxial[jent[e]], plateral[jent[e]]);
      for (std::int32_t k = prow[i], end = prow[i + 1]; k < end; ++k) add(paxis[k], paxial[k], plateral[k]);
      for (std::int32_t k = trow[i], end = trow[i + 1]; k < end; ++k) add(taxis[k], taxial[k], tlateral[k]);
    }
    /// Calls f(other, n, axial, lateral) for each of i's sphere-sphere contacts, in the order
    /// times() visits them: the off-diagonal blocks -S of an assembled J (integrate/tangent_matrix.h).
    template <class F>
    void for_each_pair(std::size_t i, F&& f) const {
      for (std::int32_t e = jrow[i], end = jrow[i + 1]; e < end; ++e) {
        const std::int32_t k = jent[e];
        f(pairs[k].i, paxis[k], paxial[k], plateral[k]);
      }
      for (std::int32_t k = prow[i], end = prow[i + 1]; k < end; ++k) f(pairs[k].j, paxis[k], paxial[k], plateral[k]);
    }
    /// The contacts' part of (J d)_i: minus the sum over i's pairs of S (d_other - d_i), plus
    /// S d_i for each triangle contact (the mesh's motion is prescribed), in a fixed order.
    Vec3 times(std::size_t i, const Vec3* d) const {
      Vec3 s = Vec3::Zero();
      const Vec3 di = d[i];
      for (std::int32_t e = jrow[i], end = jrow[i + 1]; e < end; ++e) {
        const std::int32_t k = jent[e];
        const Vec3 u = d[pairs[k].i] - di;
        s -= plateral[k] * u + (paxial[k] * paxis[k].dot(u)) * paxis[k];
      }
      for (std::int32_t k = prow[i], end = prow[i + 1]; k < end; ++k) {
        const Vec3 u = d[pairs[k].j] - di;
        s -= plateral[k] * u + (paxial[k] * paxis[k].dot(u)) * paxis[k];
      }
      for (std::int32_t k = trow[i], end = trow[i + 1]; k < end; ++k)
        s += tlateral[k] * di + (taxial[k] * taxis[k].dot(di)) * taxis[k];
      return s;
    }
  };
  TangentRows tangent_rows() const;

  /// The contacts' part of the heat (issue 33; laws/heat_conduction.h), from the last
  /// evaluation's results and the state now (the step's end). Per particle, summed over its
  /// contacts in a fixed order (the same bits for any thread count): 'friction' += half of each
  /// touching contact's frictional power max(0, -ft . vt) (W; the other half goes to the other
  /// particle or to the mesh), 'flux' += the heat conducted in, sum G (T_other - T_i) (W) and
  /// 'conductance' += sum G (W/K). Per mesh (in list order): 'mesh_friction' += its half of the
  /// frictional power (W), 'mesh_flux' += the heat conducted into it (W), 'mesh_conductance' += sum G (W/K). The
  /// outputs must be sized (particles, meshes); the conduction terms only with 'temperature'.
  struct HeatInput {
    const double* temperature = nullptr;       ///< per particle, K; null: friction only
    double conductivity = 0.0;                 ///< of the particles, W/(m K)
    const double* mesh_temperature = nullptr;  ///< per mesh, K
    double mesh_conductivity = 0.0;            ///< of the meshes, W/(m K); 0: no conduction into them
    bool friction = true;                      ///< add the frictional power
    double mesh_share = 0.5;                   ///< share of a triangle contact's frictional power into the mesh, 1
    /// Domains (issue 38): per particle, 1 for one this domain owns; the meshes' shares of the
    /// triangle contacts of those particles are then also added exactly, each term times 'scale'
    /// (a step or sub-step, s: J), into HeatOutput's mesh_*_exact.
    const std::uint8_t* counted = nullptr;
    double scale = 1.0;
  };
  struct HeatOutput {
    std::vector<double> friction, flux, conductance;                 ///< per particle: W, W, W/K
    std::vector<double> mesh_friction, mesh_flux, mesh_conductance;  ///< per mesh: W, W, W/K
    std::vector<ExactSum> mesh_friction_exact, mesh_flux_exact;      ///< per mesh, with 'counted': J
  };
  void heat(const Particles& p, const HeatInput& in, HeatOutput& out) const;

  /// Force the particles exert on each mesh (sums over its contacts in a fixed order), N; one pass.
  void mesh_forces(std::vector<Vec3>& out) const;
  /// Force (N) and torque about each mesh's centre() (N m) that the particles exert on each
  /// mesh, summed over its contacts in list order (a rigid body's wrench).
  void mesh_wrenches(std::vector<Vec3>& force, std::vector<Vec3>& torque) const;
  /// The part of mesh m's force (N) from its contacts whose point of action lies in the band
  /// lo <= x[axis] < hi (m), in list order: a tool's force by strip of its edge.
  Vec3 mesh_force_in_band(std::size_t m, int axis, double lo, double hi) const;
  /// Elastic energy stored in the contacts, J (2/5 K delta^(5/2), weighted for triangles).
  double elastic_energy() const;
  /// Domains (issue 38): how far beyond its region a rank needs copies of particles for the
  /// sphere-sphere candidates, the contact distance of the two largest spheres plus the skin, m.
  double ghost_reach(const Particles& p) const;
  /// Current number of touching sphere-sphere and sphere-triangle contacts.
  std::size_t touching() const;
  /// Current number of touching sphere-sphere contacts.
  std::size_t touching_pairs() const;
  std::size_t list_builds() const { return builds_; }

  /// A contact's state as it travels between domains or to a run's mirror (issue 38): its ends
  /// (particle indices, i < j; a triangle contact: the particle and the global triangle index),
  /// its committed friction history, whether it touched in the last evaluation and what that
  /// evaluation gave (its result, elastic energy and, for a triangle, point of action).
  struct PairRecord {
    std::int32_t i = 0, j = 0;
    Vec3 history = Vec3::Zero();
    std::uint8_t touching = 0;
    Result result{Vec3::Zero(), Vec3::Zero()};
    double energy = 0.0;  ///< J
  };
  struct TriangleRecord {
    std::int32_t i = 0, tri = 0;
    Vec3 history = Vec3::Zero();
    std::uint8_t touching = 0;
    Result result{Vec3::Zero(), Vec3::Zero()};
    Vec3 point = Vec3::Zero();  ///< m
    double energy = 0.0;        ///< J
  };
  struct Records {
    std::vector<PairRecord> pairs;          ///< sorted by (i, j)
    std::vector<TriangleRecord> triangles;  ///< sorted by (i, tri)
  };
  /// The contacts that touched in the last evaluation or carry a history (all others are
  /// candidates only: a new list finds them again), in list order (contact_records.cpp).
  Records records() const;
  /// New lists over 'p' (after the door replaced the particles and rods) with the contacts of
  /// 'r' (indices into p, sorted; no rod between a pair's ends) carried: their histories, touch
  /// flags and last results as they were, so that the next evaluation and the outputs read
  /// them as if the contacts had never moved. The lists are built (a full search) and valid
  /// for the next step.
  void replace(const Particles& p, const Rods& rods, const Records& r);
  /// The contacts' shares counted by particle (a domain's, issue 38; counted: per particle,
  /// 1 if this domain owns it), each term added exactly (core/exact_sum.h), so that the sums
  /// over all domains are the same bits for any partition: the elastic energy of the touching
  /// pairs whose first particle is counted and of the triangle contacts of counted particles,
  /// J; per mesh, the force those triangle contacts exert on it, N (3 sums per mesh: x y z).
  ExactSum elastic_energy_exact(const std::uint8_t* counted) const;
  std::vector<ExactSum> mesh_forces_exact(const std::uint8_t* counted) const;

  /// Follows a change of particle indices (state/reindex.h): contacts of removed particles
  /// are dropped, the others renumbered with their histories (a pair whose ends swap keeps
  /// its history negated: it is j's displacement relative to i) and sorted again. 'p' is the
  /// particles after the change. A list not built yet stays unbuilt.
  void reindex(const std::vector<std::int32_t>& new_index, std::size_t new_count, const Particles& p);

  /// The state: the lists as built (pairs, triangle contacts, committed histories, build
  /// reference), each field named once (state_visit.cpp); per-contact constants and rows are
  /// derived again on load.
  void visit_state(StateArchive& ar, const Particles& p);

 private:
  // Per-contact constants are computed when the list is built: the evaluation then needs
  // no division for the material law (K, damping and tangential stiffness factor).
  // Sphere-sphere pairs: the indices alone in one array (8 bytes, all that a near miss
  // reads), their constants and committed histories in others.
  struct PairConstants {
    double K = 0, D = 0, kt0 = 0;  // Hertz K (N/m^1.5), damping alpha sqrt(m* K), 8 G* sqrt(R*) (N/m^1.5)
  };
  struct TriPair {        // sphere-triangle
    std::int32_t i, tri;  // tri: global triangle index
    Vec3 history = Vec3::Zero();
    double K = 0, D = 0, kt0 = 0;
  };
  // The overlap of sphere (x, R) with global triangle t of 'mb' where the meshes are now
  // (evaluate's geometry; contact_heat.cpp recomputes it).
  static SphereTriangleHit triangle_hit(const MeshBody& mb, std::int32_t local, const TriangleFrame& frame,
                                        const Vec3& x, double R) {
    const auto& tri = mb.mesh.triangles[local];
    // (A turning mesh's frames turn with it: made from its placed vertices.)
    return mb.turns ? sphere_triangle(x, R, mb.placed[tri[0]], mb.placed[tri[1]], mb.placed[tri[2]])
                    : sphere_triangle(x, R, mb.mesh.vertices[tri[0]] + mb.offset, mb.mesh.vertices[tri[1]] + mb.offset,
                                      mb.mesh.vertices[tri[2]] + mb.offset, frame);
  }
  void partition(int nthreads);  // row_split_, spanning_ for the lists and the number of threads
  void fill_constants(const Particles& p);
  void build(const Particles& p, const Rods& rods);
  void finish_build(const Particles& p);  // constants, per-particle rows, scratch arrays
  void pair_rows(std::size_t n);          // prow_, jrow_, jent_ from pairs_

  bool enabled_ = false;
  ContactParams prm_;
  Periodic periodic_;  // nearest image along y for sphere-sphere pairs
  std::vector<MeshBody>* meshes_ = nullptr;
  std::vector<std::int32_t> tri_mesh_, tri_local_;  // global triangle -> mesh, local index
  std::vector<TriangleFrame> tri_frame_;            // global triangle -> its normal and in-plane axes
  double max_radius_ = 0;
  std::size_t builds_ = 0;

  std::vector<Pair> pairs_;
  std::vector<PairConstants> pconst_;  // per pair; empty when all particles are equal:
  bool uniform_ = false;               // then every pair has uniform_constants_
  PairConstants uniform_constants_;
  std::vector<Vec3> phist_;  // committed tangential spring displacement of each pair, m
  std::vector<TriPair> tris_;
  std::vector<Result> pres_, tres_;
  std::vector<Vec3> tpoint_;  // per triangle contact: where its force acts on the mesh, m
  std::vector<Result> psum_;  // per particle: the sum of its pairs' results (see Sums)
  // The pair loop's partition: thread t evaluates the rows (first particles) row_split_[t] to
  // row_split_[t + 1] - 1; spanning_: 1 for a particle with pairs in two threads' rows;
  // jmin_: the lowest first particle of a particle's pairs (itself if none). Made again when
  // the lists (list_version_) or the number of threads change.
  std::vector<std::size_t> row_split_;
  std::vector<std::uint8_t> spanning_;
  std::vector<std::int32_t> jmin_;
  std::uint64_t list_version_ = 0, partition_version_ = ~std::uint64_t{0};
  std::vector<Vec3> ph_, th_;    // trial histories, m
  std::vector<double> pe_, te_;  // elastic energy, J
  // 1 if the contact touched in the last evaluation; after a build, 1 for a carried history
  // (an evaluation zeroes the results, and a final one the history, of a contact that stopped
  // touching by this flag).
  std::vector<std::uint8_t> ptouch_, ttouch_;
  // Per-particle rows: the pairs whose first particle is i are pairs_[prow_[i]] to
  // pairs_[prow_[i + 1] - 1], its triangle contacts tris_[trow_[i]] to tris_[trow_[i + 1] - 1]
  // (both lists are sorted by particle); the pairs whose second particle it is are listed in
  // jent_[jrow_[i]] to jent_[jrow_[i + 1] - 1], in pair order.
  std::vector<std::int32_t> prow_, trow_, jrow_, jent_;
  // Reference state of the last build.
  std::vector<Vec3> x_build_;
  std::vector<Vec3> mesh_build_;
  std::vector<Quat> mesh_build_turn_;  // the meshes' turns at the build (turning meshes)
  // Newton tangent blocks (tangent()): per pair and per triangle contact; zero for a contact
  // that does not touch.
  std::vector<Vec3> ptan_axis_, ttan_axis_;
  std::vector<double> ptan_axial_, ptan_lateral_, ttan_axial_, ttan_lateral_;
};

template <class Keep>
std::vector<std::array<std::int32_t, 2>> ContactSystem::pressed_pairs(const Particles& p, double overlap,
                                                                      Keep&& keep) const {
  // Per block of pairs, joined in block order: the list order, for any thread count. (Every
  // step of a cut scans all pairs here; serial, it was a tenth of the commit stage.)
  const std::size_t m = pairs_.size(), nb = block_count(m);
  std::vector<std::vector<std::array<std::int32_t, 2>>> part(nb);
#pragma omp parallel for schedule(static) if (nb > 1)
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t end = std::min(m, (b + 1) * kBlock);
    for (std::size_t k = b * kBlock; k < end; ++k) {
      if (overlap >= 0.0 && !ptouch_[k]) continue;  // (only a touching pair can be pressed)
      const Pair q = pairs_[k];
      Vec3 d = p.position[q.j] - p.position[q.i];
      periodic_.wrap(d);
      const double reach = (p.radius[q.i] + p.radius[q.j]) * (1.0 - overlap);
      if (d.squaredNorm() < reach * reach && keep(q.i, q.j)) part[b].push_back({q.i, q.j});
    }
  }
  std::vector<std::array<std::int32_t, 2>> out;
  for (const auto& v : part) out.insert(out.end(), v.begin(), v.end());
  return out;
}

}  // namespace swarf
