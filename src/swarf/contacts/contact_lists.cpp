// contact_lists.cpp: the contact search: cell grid, Verlet lists of candidate pairs and
// sphere-triangle candidates, their per-particle rows and per-contact constants, merging the
// pairs of rods that just broke (see contacts.h).
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "swarf/contacts/contacts.h"
#include "swarf/core/parallel.h"
#include "swarf/geometry/overlap_area.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"

namespace swarf {

namespace {

// True if particles i and j are joined by an intact rod (a pair has one rod at most).
bool bonded(const Rods& rods, std::int32_t i, std::int32_t j) {
  if (rods.row_start.empty()) return false;
  for (std::int32_t e = rods.row_start[i]; e < rods.row_start[i + 1]; ++e)
    if (rods.entries[e].other == j) return rods.intact[rods.entries[e].rod] != 0;
  return false;
}

struct Grid {
  Vec3 lo;
  double cell = 1;
  std::array<std::int64_t, 3> n{1, 1, 1};
  double period = 0, cell_y = 1;    // periodic y: n[1] cells of cell_y = period / n[1] over [0, period)
  std::vector<std::int64_t> start;  // counting-sort offsets per cell
  std::vector<std::int32_t> items;

  std::array<std::int64_t, 3> cell_of(const Vec3& p) const {
    std::array<std::int64_t, 3> c{};
    for (int k = 0; k < 3; ++k)
      c[k] = std::clamp<std::int64_t>(std::int64_t(std::floor((p[k] - lo[k]) / cell)), 0, n[k] - 1);
    if (period > 0) c[1] = y_cell(p[1]);
    return c;
  }
  std::int64_t y_cell(double y) const {
    const double w = y - period * std::floor(y / period);  // in [0, period]
    return std::clamp<std::int64_t>(std::int64_t(std::floor(w / cell_y)), 0, n[1] - 1);
  }
  /// The distinct y cells at offsets -1, 0, +1 from cy (fewer when there are under 3 cells).
  int y_neighbours(std::int64_t cy, std::int64_t out[3]) const {
    if (period <= 0) {
      int k = 0;
      for (std::int64_t d = -1; d <= 1; ++d)
        if (cy + d >= 0 && cy + d < n[1]) out[k++] = cy + d;
      return k;
    }
    if (n[1] < 3) {
      for (std::int64_t d = 0; d < n[1]; ++d) out[d] = d;
      return static_cast<int>(n[1]);
    }
    for (int d = -1; d <= 1; ++d) out[d + 1] = (cy + d + n[1]) % n[1];
    return 3;
  }
  std::int64_t linear(const std::array<std::int64_t, 3>& c) const { return (c[2] * n[1] + c[1]) * n[0] + c[0]; }
};

}  // namespace

void ContactSystem::setup(const ContactParams& params, std::size_t n_particles, std::vector<MeshBody>* meshes,
                          Periodic periodic) {
  enabled_ = true;
  periodic_ = periodic;
  prm_ = params;
  meshes_ = meshes;
  tri_mesh_.clear();
  tri_local_.clear();
  tri_frame_.clear();
  for (std::size_t m = 0; m < meshes->size(); ++m)
    for (std::size_t t = 0; t < (*meshes)[m].mesh.triangles.size(); ++t) {
      tri_mesh_.push_back(static_cast<std::int32_t>(m));
      tri_local_.push_back(static_cast<std::int32_t>(t));
      // The meshes only translate: each triangle's normal and in-plane axes, from its
      // reference vertices, hold for the whole run.
      const TriangleMesh& tm = (*meshes)[m].mesh;
      const auto& tri = tm.triangles[t];
      tri_frame_.push_back(triangle_frame(tm.vertices[tri[0]], tm.vertices[tri[1]], tm.vertices[tri[2]]));
    }
  x_build_.clear();
  prow_.assign(n_particles + 1, 0);
  jrow_.assign(n_particles + 1, 0);
  trow_.assign(n_particles + 1, 0);
}

void ContactSystem::update_lists(const Particles& p, const Rods& rods, bool force, double moved2) {
  if (!enabled_) return;
  // (also when the meshes were never built: a run may start without particles, an inflow's)
  bool rebuild = force || x_build_.size() != p.size() || mesh_build_.size() != meshes_->size();
  if (!rebuild) {
    const double half = 0.5 * prm_.skin;
    double mesh_move = 0.0;
    for (std::size_t m = 0; m < meshes_->size(); ++m) {
      const MeshBody& mb = (*meshes_)[m];
      double move = (mb.offset - mesh_build_[m]).norm();
      // A turn by theta moves a vertex at distance r from the pivot by 2 r sin(theta/2), and
      // sin(theta/2) is the vector part's norm of the relative rotation.
      if (mb.turns) move += 2.0 * mb.reach * vec(qmul(qconj(mesh_build_turn_[m]), mb.turn)).norm();
      mesh_move = std::max(mesh_move, move);
    }
    double worst = moved2;
    if (worst < 0.0) {
      worst = 0.0;
      const std::size_t n = p.size();
#pragma omp parallel for schedule(static) reduction(max : worst)
      for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, (p.position[i] - x_build_[i]).squaredNorm());
    }
    // A particle and a mesh moving towards each other each use up part of the skin.
    rebuild = !(std::sqrt(worst) + mesh_move <= half);  // (NaN: rebuild, the step fails later)
  }
  if (rebuild) build(p, rods);
}

void ContactSystem::build(const Particles& p, const Rods& rods) {
  ++builds_;
  const std::size_t n = p.size();
  max_radius_ = 0;
  Vec3 lo = Vec3::Constant(HUGE_VAL), hi = Vec3::Constant(-HUGE_VAL);
  for (std::size_t i = 0; i < n; ++i) {
    max_radius_ = std::max(max_radius_, p.radius[i]);
    lo = lo.cwiseMin(p.position[i]);
    hi = hi.cwiseMax(p.position[i]);
  }
  if (n == 0) lo = hi = Vec3::Zero();  // (no particles yet: one cell; an inflow adds them later)
  const double skin = prm_.skin;
  Grid g;
  g.cell = n == 0 ? 1.0 : 2.0 * max_radius_ + skin;
  // Keep the grid to about a few cells per particle even if particles fly far apart.
  for (;;) {
    // (counted in double and capped: particles restored 1e21 m apart made a count beyond
    // int64, whose conversion is undefined; found by the checkpoint fuzzer)
    for (int k = 0; k < 3; ++k) {
      const double cells = std::floor((hi[k] - lo[k]) / g.cell) + 1.0;
      g.n[k] = cells < 4e18 ? std::max<std::int64_t>(1, std::int64_t(cells)) : std::int64_t(4e18);
    }
    if (periodic_.on()) {  // whole cells over the period, none smaller than the reach
      g.period = periodic_.period;
      g.n[1] = std::max<std::int64_t>(1, std::int64_t(std::floor(g.period / g.cell)));
      g.cell_y = g.period / double(g.n[1]);
    }
    if (double(g.n[0]) * double(g.n[1]) * double(g.n[2]) <= 8.0 * double(n) + 64.0) break;
    g.cell *= 1.5;
  }
  g.lo = lo;
  const std::size_t ncell = static_cast<std::size_t>(g.n[0] * g.n[1] * g.n[2]);
  std::vector<std::int64_t> cell_id(n);
  g.start.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    cell_id[i] = g.linear(g.cell_of(p.position[i]));
    ++g.start[cell_id[i] + 1];
  }
  for (std::size_t c = 1; c <= ncell; ++c) g.start[c] += g.start[c - 1];
  g.items.assign(n, 0);
  {
    std::vector<std::int64_t> fill(g.start.begin(), g.start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) g.items[fill[cell_id[i]]++] = static_cast<std::int32_t>(i);
  }

  // Candidates are listed per chunk of particles (in parallel, dynamic: the density varies)
  // and the chunks joined in order: the lists, sorted by particle and then by partner, are
  // the same for any thread count.
  constexpr std::size_t kChunk = 256;
  const std::size_t nchunk = (n + kChunk - 1) / kChunk;
  // Old rows, to carry the committed histories over: pairs_ and tris_ are still the previous
  // lists, prow_ and trow_ their rows (if they were built for these particles).
  const bool carry = prow_.size() == n + 1 && std::size_t(prow_.back()) == pairs_.size() && trow_.size() == n + 1 &&
                     std::size_t(trow_.back()) == tris_.size();

  // Sphere-sphere candidates, i < j.
  std::vector<std::vector<Pair>> pchunk(nchunk);
  std::vector<std::vector<Vec3>> hchunk(nchunk);
#pragma omp parallel
  {
    std::vector<std::int32_t> js;
#pragma omp for schedule(dynamic, 1)
    for (std::size_t ch = 0; ch < nchunk; ++ch) {
      auto& out = pchunk[ch];
      auto& hist = hchunk[ch];
      for (std::size_t i = ch * kChunk, end = std::min(n, (ch + 1) * kChunk); i < end; ++i) {
        const auto c = g.cell_of(p.position[i]);
        std::int64_t ys[3];
        const int ny = g.y_neighbours(c[1], ys);
        js.clear();
        for (std::int64_t dz = -1; dz <= 1; ++dz)
          for (int iy = 0; iy < ny; ++iy)
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
              const std::array<std::int64_t, 3> o{c[0] + dx, ys[iy], c[2] + dz};
              if (o[0] < 0 || o[2] < 0 || o[0] >= g.n[0] || o[2] >= g.n[2]) continue;
              const auto l = g.linear(o);
              for (std::int64_t s = g.start[l]; s < g.start[l + 1]; ++s) {
                const std::int32_t j = g.items[s];
                if (j <= static_cast<std::int32_t>(i)) continue;
                const double reach = p.radius[i] + p.radius[j] + skin;
                Vec3 dij = p.position[j] - p.position[i];
                periodic_.wrap(dij);
                if (dij.squaredNorm() > reach * reach) continue;
                if (bonded(rods, static_cast<std::int32_t>(i), j)) continue;
                js.push_back(j);
              }
            }
        std::sort(js.begin(), js.end());
        for (auto j : js) {
          out.push_back(Pair{static_cast<std::int32_t>(i), j});
          Vec3 h = Vec3::Zero();
          if (carry)  // the old pairs of particle i (a handful)
            for (std::int32_t k = prow_[i]; k < prow_[i + 1]; ++k)
              if (pairs_[k].j == j) {
                h = phist_[k];
                break;
              }
          hist.push_back(h);
        }
      }
    }
  }
  {
    std::size_t total = 0;
    for (const auto& c : pchunk) total += c.size();
    pairs_.clear();
    pairs_.reserve(total);
    phist_.clear();
    phist_.reserve(total);
    for (std::size_t ch = 0; ch < nchunk; ++ch) {
      pairs_.insert(pairs_.end(), pchunk[ch].begin(), pchunk[ch].end());
      phist_.insert(phist_.end(), hchunk[ch].begin(), hchunk[ch].end());
    }
  }

  // Sphere-triangle candidates: each triangle is binned into the cells its box (grown by the
  // reach) overlaps (cell lists by counting sort); each particle tests the triangles of its
  // own cell.
  std::vector<TriPair> tris;
  if (!tri_mesh_.empty()) {
    const double reach = max_radius_ + skin;
    // Calls visit(cell) for each cell the box of triangle t overlaps.
    auto for_cells = [&](std::size_t t, auto&& visit) {
      const MeshBody& mb = (*meshes_)[tri_mesh_[t]];
      const auto& tri = mb.mesh.triangles[tri_local_[t]];
      Vec3 tlo = Vec3::Constant(HUGE_VAL), thi = Vec3::Constant(-HUGE_VAL);
      for (int k = 0; k < 3; ++k) {
        const Vec3 v = mb.vertex(tri[k]);
        tlo = tlo.cwiseMin(v);
        thi = thi.cwiseMax(v);
      }
      tlo.array() -= reach;
      thi.array() += reach;
      bool outside = false;
      for (int k = 0; k < 3; ++k) outside = outside || thi[k] < lo[k] || tlo[k] > hi[k];
      if (outside) return;
      const auto c0 = g.cell_of(tlo), c1 = g.cell_of(thi);
      // The y cells the box covers (periodic: wrapped; a box wider than the period covers all).
      std::vector<std::int64_t> ycells;
      if (g.period > 0) {
        const double y0 = std::floor(tlo[1] / g.cell_y), y1 = std::floor(thi[1] / g.cell_y);
        if (y1 - y0 + 1 >= double(g.n[1]))
          for (std::int64_t y = 0; y < g.n[1]; ++y) ycells.push_back(y);
        else
          for (double y = y0; y <= y1; y += 1.0) ycells.push_back((std::int64_t(y) % g.n[1] + g.n[1]) % g.n[1]);
      } else {
        for (std::int64_t y = c0[1]; y <= c1[1]; ++y) ycells.push_back(y);
      }
      for (std::int64_t z = c0[2]; z <= c1[2]; ++z)
        for (std::int64_t y : ycells)
          for (std::int64_t x = c0[0]; x <= c1[0]; ++x) visit(g.linear({x, y, z}));
    };
    std::vector<std::int64_t> tstart(ncell + 1, 0);
    for (std::size_t t = 0; t < tri_mesh_.size(); ++t) for_cells(t, [&](std::int64_t c) { ++tstart[c + 1]; });
    for (std::size_t c = 1; c <= ncell; ++c) tstart[c] += tstart[c - 1];
    std::vector<std::int32_t> titems(tstart.back());
    {
      std::vector<std::int64_t> fill(tstart.begin(), tstart.end() - 1);
      for (std::size_t t = 0; t < tri_mesh_.size(); ++t)
        for_cells(t, [&](std::int64_t c) { titems[fill[c]++] = static_cast<std::int32_t>(t); });
    }
    std::vector<std::vector<TriPair>> tchunk(nchunk);
#pragma omp parallel
    {
      std::vector<std::int32_t> ts;
#pragma omp for schedule(dynamic, 1)
      for (std::size_t ch = 0; ch < nchunk; ++ch)
        for (std::size_t i = ch * kChunk, end = std::min(n, (ch + 1) * kChunk); i < end; ++i) {
          const std::int64_t c = cell_id[i];
          if (tstart[c] == tstart[c + 1]) continue;
          ts.clear();
          for (std::int64_t s = tstart[c]; s < tstart[c + 1]; ++s) {
            const std::int32_t t = titems[s];
            const MeshBody& mb = (*meshes_)[tri_mesh_[t]];
            const auto& tri = mb.mesh.triangles[tri_local_[t]];
            const Vec3 q = closest_on_triangle(p.position[i], mb.vertex(tri[0]), mb.vertex(tri[1]), mb.vertex(tri[2]));
            const double r = p.radius[i] + skin;
            if ((q - p.position[i]).squaredNorm() <= r * r) ts.push_back(t);
          }
          std::sort(ts.begin(), ts.end());
          for (auto t : ts) {
            TriPair tp{static_cast<std::int32_t>(i), t, Vec3::Zero()};
            if (carry)
              for (std::int32_t k = trow_[i]; k < trow_[i + 1]; ++k)
                if (tris_[k].tri == t) {
                  tp.history = tris_[k].history;
                  break;
                }
            tchunk[ch].push_back(tp);
          }
        }
    }
    for (const auto& c : tchunk) tris.insert(tris.end(), c.begin(), c.end());
  }
  tris_.swap(tris);
  finish_build(p);
  x_build_ = p.position;
  mesh_build_.resize(meshes_->size());
  mesh_build_turn_.resize(meshes_->size());
  for (std::size_t m = 0; m < meshes_->size(); ++m) {
    mesh_build_[m] = (*meshes_)[m].offset;
    mesh_build_turn_[m] = (*meshes_)[m].turn;
  }
}

void ContactSystem::finish_build(const Particles& p) {
  const std::size_t n = p.size();
  fill_constants(p);
  pair_rows(n);
  trow_.assign(n + 1, 0);
  for (const auto& q : tris_) ++trow_[q.i + 1];
  for (std::size_t i = 0; i < n; ++i) trow_[i + 1] += trow_[i];

  // Results: zero for contacts that do not touch (the evaluation keeps them so), so the
  // per-particle sums need no test; the other scratch arrays are written before they are read.
  const std::size_t np = pairs_.size(), nt = tris_.size();
  pres_.assign(np, Result{Vec3::Zero(), Vec3::Zero()});
  psum_.assign(n, Result{Vec3::Zero(), Vec3::Zero()});
  spanning_.assign(n, 0);  // (sums of zero results until the next evaluation partitions the rows)
  ph_.resize(np);
  pe_.resize(np);
  tres_.assign(nt, Result{Vec3::Zero(), Vec3::Zero()});
  tpoint_.assign(nt, Vec3::Zero());
  th_.resize(nt);
  te_.resize(nt);
  ptouch_.resize(np);
  for (std::size_t k = 0; k < np; ++k) ptouch_[k] = phist_[k] != Vec3::Zero();
  ttouch_.resize(nt);
  for (std::size_t k = 0; k < nt; ++k) ttouch_[k] = tris_[k].history != Vec3::Zero();
}

void ContactSystem::pair_rows(std::size_t n) {
  // Per-particle rows: pairs_ and tris_ are sorted by their first particle, so those rows are
  // ranges; the pairs in which a particle is the second get an index list.
  prow_.assign(n + 1, 0);
  jrow_.assign(n + 1, 0);
  for (const auto& q : pairs_) {
    ++prow_[q.i + 1];
    ++jrow_[q.j + 1];
  }
  for (std::size_t i = 0; i < n; ++i) {
    prow_[i + 1] += prow_[i];
    jrow_[i + 1] += jrow_[i];
  }
  jent_.assign(jrow_.back(), 0);
  {
    std::vector<std::int32_t> fill(jrow_.begin(), jrow_.end() - 1);
    for (std::size_t k = 0; k < pairs_.size(); ++k) jent_[fill[pairs_[k].j]++] = static_cast<std::int32_t>(k);
  }
  // The first particle of a particle's earliest pair (jent_ is in pair order), itself if none.
  jmin_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    jmin_[i] = jrow_[i] < jrow_[i + 1] ? pairs_[jent_[jrow_[i]]].i : static_cast<std::int32_t>(i);
  ++list_version_;
}

void ContactSystem::add_pairs(const Particles& p, std::vector<std::array<std::int32_t, 2>> extra) {
  if (!enabled_ || extra.empty() || x_build_.size() != p.size()) return;  // (no list yet: the build finds them)
  for (auto& e : extra)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  // Merge into the sorted list; every per-pair array follows, the new pairs with no history,
  // no result and not touching: the last evaluation's results stay valid as they are.
  const std::size_t np = pairs_.size();
  std::vector<Pair> pairs;
  std::vector<Vec3> hist, ph;
  std::vector<Result> res;
  std::vector<double> pe;
  std::vector<std::uint8_t> touch;
  const std::size_t cap = np + extra.size();
  pairs.reserve(cap);
  hist.reserve(cap);
  ph.reserve(cap);
  res.reserve(cap);
  pe.reserve(cap);
  touch.reserve(cap);
  auto copy_old = [&](std::size_t k) {
    pairs.push_back(pairs_[k]);
    hist.push_back(phist_[k]);
    ph.push_back(ph_[k]);
    res.push_back(pres_[k]);
    pe.push_back(pe_[k]);
    touch.push_back(ptouch_[k]);
  };
  std::size_t k = 0;
  for (const auto& e : extra) {
    auto before = [&](const Pair& q) { return q.i < e[0] || (q.i == e[0] && q.j < e[1]); };
    while (k < np && before(pairs_[k])) copy_old(k++);
    if (k < np && pairs_[k].i == e[0] && pairs_[k].j == e[1]) continue;  // already a candidate
    pairs.push_back(Pair{e[0], e[1]});
    hist.push_back(Vec3::Zero());
    ph.push_back(Vec3::Zero());
    res.push_back(Result{Vec3::Zero(), Vec3::Zero()});
    pe.push_back(0.0);
    touch.push_back(0);
  }
  while (k < np) copy_old(k++);
  pairs_.swap(pairs);
  phist_.swap(hist);
  ph_.swap(ph);
  pres_.swap(res);
  pe_.swap(pe);
  ptouch_.swap(touch);
  fill_constants(p);
  pair_rows(p.size());
}

void ContactSystem::remove_pairs(const Particles& p, const std::vector<std::array<std::int32_t, 2>>& gone) {
  if (!enabled_ || gone.empty() || x_build_.size() != p.size()) return;
  std::size_t out = 0, g = 0;
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const Pair q = pairs_[k];
    auto before = [&](const std::array<std::int32_t, 2>& e) { return e[0] < q.i || (e[0] == q.i && e[1] < q.j); };
    while (g < gone.size() && before(gone[g])) ++g;
    if (g < gone.size() && gone[g][0] == q.i && gone[g][1] == q.j) continue;
    pairs_[out] = q;
    phist_[out] = phist_[k];
    ph_[out] = ph_[k];
    pres_[out] = pres_[k];
    pe_[out] = pe_[k];
    ptouch_[out] = ptouch_[k];
    ++out;
  }
  if (out == pairs_.size()) return;
  pairs_.resize(out);
  phist_.resize(out);
  ph_.resize(out);
  pres_.resize(out);
  pe_.resize(out);
  ptouch_.resize(out);
  fill_constants(p);
  pair_rows(p.size());
}

void ContactSystem::fill_constants(const Particles& p) {
  const double E = prm_.youngs_modulus, nu = prm_.poisson_ratio;
  const double G = E / (2.0 * (1.0 + nu));
  const double inv_E_pp = 2.0 * (1.0 - nu * nu) / E;  // 1/E* of two particles
  const double inv_G_pp = 2.0 * (2.0 - nu) / G;       // 1/G* (Mindlin)
  auto pair_constants = [&](double ri, double rj, double mi, double mj) {
    PairConstants c;
    const double rstar = ri * rj / (ri + rj);
    const double mstar = mi * mj / (mi + mj);
    c.K = 4.0 / 3.0 / inv_E_pp * std::sqrt(rstar);
    c.D = prm_.alpha * std::sqrt(mstar * c.K);
    c.kt0 = 8.0 / inv_G_pp * std::sqrt(rstar);
    return c;
  };
  // Equal particles (a lattice, a monodisperse packing) share one set of constants: the
  // evaluation then reads no per-pair array.
  const std::size_t n = p.size(), np = pairs_.size();
  uniform_ = n > 0;
  for (std::size_t i = 1; i < n && uniform_; ++i) uniform_ = p.radius[i] == p.radius[0] && p.mass[i] == p.mass[0];
  if (uniform_) {
    uniform_constants_ = pair_constants(p.radius[0], p.radius[0], p.mass[0], p.mass[0]);
    pconst_.clear();
  } else {
    pconst_.resize(np);
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < np; ++k) {
      const Pair& q = pairs_[k];
      pconst_[k] = pair_constants(p.radius[q.i], p.radius[q.j], p.mass[q.i], p.mass[q.j]);
    }
  }
  for (auto& q : tris_) {
    const MeshBody& mb = (*meshes_)[tri_mesh_[q.tri]];
    const double R = p.radius[q.i];
    const double inv_E = inverse_effective_modulus(E, nu, mb.youngs_modulus, mb.poisson_ratio);
    const double Gw = mb.youngs_modulus / (2.0 * (1.0 + mb.poisson_ratio));
    const double inv_G = (2.0 - nu) / G + (std::isfinite(Gw) ? (2.0 - mb.poisson_ratio) / Gw : 0.0);
    q.K = 4.0 / 3.0 / inv_E * std::sqrt(R);
    q.D = prm_.alpha * std::sqrt(p.mass[q.i] * q.K);
    q.kt0 = 8.0 / inv_G * std::sqrt(R);
  }
}

void ContactSystem::reindex(const std::vector<std::int32_t>& new_index, std::size_t new_count, const Particles& p) {
  if (!enabled_) return;
  constexpr std::int32_t kGone = -1;
  const bool built = x_build_.size() == new_index.size();
  std::vector<std::pair<Pair, Vec3>> pairs;
  pairs.reserve(pairs_.size());
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    std::int32_t i = new_index[pairs_[k].i], j = new_index[pairs_[k].j];
    if (i == kGone || j == kGone) continue;
    Vec3 h = phist_[k];
    if (i > j) {
      std::swap(i, j);
      h = -h;
    }
    pairs.push_back({Pair{i, j}, h});
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
    return a.first.i < b.first.i || (a.first.i == b.first.i && a.first.j < b.first.j);
  });
  pairs_.resize(pairs.size());
  phist_.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    pairs_[k] = pairs[k].first;
    phist_[k] = pairs[k].second;
  }
  std::vector<TriPair> tris;
  tris.reserve(tris_.size());
  for (const TriPair& t : tris_) {
    const std::int32_t i = new_index[t.i];
    if (i == kGone) continue;
    tris.push_back(t);
    tris.back().i = i;
  }
  std::stable_sort(tris.begin(), tris.end(),
                   [](const TriPair& a, const TriPair& b) { return a.i < b.i || (a.i == b.i && a.tri < b.tri); });
  tris_.swap(tris);
  if (built) {
    std::vector<Vec3> xb(new_count, Vec3::Zero());
    for (std::size_t i = 0; i < new_index.size(); ++i)
      if (new_index[i] != kGone) xb[new_index[i]] = x_build_[i];
    x_build_.swap(xb);
  }
  finish_build(p);
}

}  // namespace swarf
