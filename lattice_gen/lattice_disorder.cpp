// lattice_disorder.cpp: the seeded position jitter (see lattice_disorder.h).
#include "lattice_gen/lattice_disorder.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "swarf/core/errors.h"

namespace swarf {

namespace {

constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ull;

// SplitMix64's output function (Steele, Lea and Flood 2014): a bijection of 64-bit words
// whose outputs for consecutive inputs pass BigCrush, so mix(key + n golden) is a stream.
std::uint64_t mix(std::uint64_t z) {
  z += kGolden;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace

Vec3 unit_ball_jitter(std::uint64_t seed, std::uint64_t id) {
  const std::uint64_t key = mix(mix(seed) ^ id);
  // Each component an integer c in [-2^30, 2^30) from the top 31 bits of a draw; the point is
  // kept when c . c <= 2^60 (exact in 64 bits: the sum is below 3 x 2^60), else the next three
  // draws are tried. Accepted with probability pi/6, so 1000 tries all fail with probability
  // (1 - pi/6)^1000 < 1e-300: never, but the loop ends.
  constexpr std::int64_t kHalf = std::int64_t{1} << 30;
  constexpr std::uint64_t kOne = std::uint64_t{1} << 60;
  std::uint64_t n = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    std::int64_t c[3];
    for (auto& ck : c) ck = static_cast<std::int64_t>(mix(key + (n++) * kGolden) >> 33) - kHalf;
    const std::uint64_t r2 = static_cast<std::uint64_t>(c[0] * c[0]) + static_cast<std::uint64_t>(c[1] * c[1]) +
                             static_cast<std::uint64_t>(c[2] * c[2]);
    if (r2 <= kOne) return Vec3(double(c[0]), double(c[1]), double(c[2])) * (1.0 / double(kHalf));  // (exact)
  }
  return Vec3::Zero();
}

void jitter_lattice(Lattice& lat, std::uint64_t seed, double amplitude, std::size_t count, const Periodic& periodic) {
  if (!(amplitude >= 0.0 && amplitude <= kMaxPositionJitter))
    throw InputError(
        fmt::format("lattice: the position jitter must lie in [0, {}] radii, got {}", kMaxPositionJitter, amplitude));
  if (count > lat.position.size() || lat.radius.size() != lat.position.size())
    throw std::logic_error("jitter_lattice: count exceeds the lattice's particles");
  if (seed == 0 || amplitude == 0.0) return;
  const auto n = static_cast<std::int64_t>(count);
  // Each particle's move is a function of (seed, i) alone: any thread may take any i.
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i)
    lat.position[i] += (amplitude * lat.radius[i]) * unit_ball_jitter(seed, static_cast<std::uint64_t>(i));
  // Rest lengths: the moved distance, measured as the rod kernel measures it (the nearest image,
  // the square root of the squared length), so the first evaluation finds each rod at rest.
  const auto m = static_cast<std::int64_t>(lat.rods.size());
  lat.rest_length.resize(lat.rods.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t b = 0; b < m; ++b) {
    Vec3 dx = lat.position[lat.rods[b][1]] - lat.position[lat.rods[b][0]];
    periodic.wrap(dx);
    lat.rest_length[b] = std::sqrt(dx.squaredNorm());
  }
}

}  // namespace swarf
