// rod_forces.cpp: the rod kernel (see rod_forces.h).
#include "swarf/forces/rod_forces.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "swarf/core/parallel.h"
#include "swarf/forces/lagged_rate.h"

namespace swarf {

namespace {

// The rod kernel over one block of rods. Raw pointers keep the compiler from reloading the
// arrays' bases after every store (the uint8_t stores may alias anything). 'Rate' is a
// compile-time switch so a law that reads no strain rate (the undamped paper's law) does not
// gather velocities.
//
// 'Temp' (only for a law with kReadsTemperature) gives evaluate the rod's temperature, the mean
// of its ends' (laws/johnson_cook_rod_law.h).
// A law whose rate and temperature enter as one scale of its flow stresses, S = R(rate) Theta(T)
// (Johnson-Cook): the kernel computes S for a chunk of rods in vector loops (the logarithm of the
// rate factor is the expensive part) before the law's pass.
template <class Law>
concept ScalesFlow = requires(const Law& l) {
  rate_factor(l, 0.0);
  thermal_factor(l, 0.0);
  linear_thermal_factor(l, 0.0);
  evaluate_scaled(l, 0.0, 0.0, 0.0, 1.0);
};

template <class Law, bool Rate, bool Wrap, bool Temp>
void rod_block(const Law& law, double A, std::size_t begin, std::size_t end, const std::array<std::int32_t, 2>* ends,
               const double* rest_length, const double* shift, const std::uint8_t* intact, const Vec3* x, const Vec3* v,
               const double* temperature, const Vec3* lag_x, const Vec3* lag_v, double* trial_shift,
               std::uint8_t* trial_broken, double* stress, double* coef, double& viscous_power, int& changed,
               Periodic periodic, double* rod_visc) {
  double visc = 0.0;
  int any = 0;
  // In chunks, three passes: the rods' vectors (scalar gathers), their lengths, inverse lengths
  // and inverse rest lengths (a loop of square roots and divisions the compiler vectorises: in
  // one loop with the law, their latency bound the kernel), then the law. The same values, bit
  // for bit. (1/L0 is computed, not stored: 8 B per rod less, for a small cost on one thread and
  // none measurable on two, validation/bench/README.md.)
  //
  // A law that scales its flow stresses (ScalesFlow) has a fourth pass before the law's: the
  // velocity differences and end temperatures are gathered with the vectors, and the rates and
  // scales computed in a vector loop. With lag_x and lag_v (Newton's step start), the rate factor
  // is read at the rod's rate there instead (computed in the gather pass, one rod at a time: only
  // the Newton solve pays for it); the viscous stress keeps the trial's rate.
  constexpr bool kScaled = ScalesFlow<Law>;
  const bool lagged = kScaled && Rate && lag_x != nullptr;
  constexpr std::size_t kChunk = 256;
  alignas(64) double dxs[3][kChunk], len_c[kChunk], inv_c[kChunk], inv0_c[kChunk];
  [[maybe_unused]] alignas(64) double dvs[3][kChunk], temp_c[kChunk], rate_c[kChunk], scale_c[kChunk], lag_c[kChunk];
  for (std::size_t c0 = begin; c0 < end; c0 += kChunk) {
    const std::size_t nc = std::min(kChunk, end - c0);
    for (std::size_t c = 0; c < nc; ++c) {
      const std::size_t k = c0 + c;
      const std::int32_t i = ends[k][0], j = ends[k][1];
      Vec3 dx = x[j] - x[i];
      if constexpr (Wrap) periodic.wrap(dx);
      dxs[0][c] = dx[0];
      dxs[1][c] = dx[1];
      dxs[2][c] = dx[2];
      len_c[c] = intact[k] ? dx.squaredNorm() : 1.0;  // (broken rods are skipped below)
      if constexpr (kScaled && Rate) {
        const Vec3 dv = v[j] - v[i];
        dvs[0][c] = dv[0];
        dvs[1][c] = dv[1];
        dvs[2][c] = dv[2];
        if (lagged) lag_c[c] = intact[k] ? lagged_rate<Wrap>(lag_x, lag_v, i, j, 1.0 / rest_length[k], periodic) : 0.0;
      }
      if constexpr (kScaled && Temp) temp_c[c] = rod_temperature(law, temperature[i], temperature[j]);
    }
#pragma omp simd
    for (std::size_t c = 0; c < nc; ++c) {
      len_c[c] = std::sqrt(len_c[c]);
      inv_c[c] = 1.0 / len_c[c];
      inv0_c[c] = 1.0 / rest_length[c0 + c];
    }
    if constexpr (kScaled) {
#pragma omp simd
      for (std::size_t c = 0; c < nc; ++c) {
        double rate = 0.0;
        if constexpr (Rate)
          rate = (dxs[0][c] * dvs[0][c] + dxs[1][c] * dvs[1][c] + dxs[2][c] * dvs[2][c]) * inv_c[c] * inv0_c[c];
        rate_c[c] = rate;
        scale_c[c] = rate_factor(law, rate);
      }
      if (lagged) {
#pragma omp simd
        for (std::size_t c = 0; c < nc; ++c) scale_c[c] = rate_factor(law, lag_c[c]);
      }
      // Theta: at m = 1 in a vector loop; otherwise (a call to pow) one rod at a time.
      if constexpr (Temp) {
        if (law.softening_exponent == 1.0) {
#pragma omp simd
          for (std::size_t c = 0; c < nc; ++c) scale_c[c] *= linear_thermal_factor(law, temp_c[c]);
        } else {
          for (std::size_t c = 0; c < nc; ++c) scale_c[c] *= thermal_factor(law, temp_c[c]);
        }
      }
    }
    for (std::size_t c = 0; c < nc; ++c) {
      const std::size_t k = c0 + c;
      if (rod_visc) rod_visc[k] = 0.0;
      if (!intact[k]) continue;
      const double len = len_c[c];
      const double inv_len = inv_c[c];
      const double l0 = rest_length[k];
      const double inv_l0 = inv0_c[c];
      const double strain = (len - l0) * inv_l0;
      double rate = 0.0;
      if constexpr (kScaled) {
        rate = rate_c[c];
      } else if constexpr (Rate) {
        const std::int32_t i = ends[k][0], j = ends[k][1];
        const Vec3 dx(dxs[0][c], dxs[1][c], dxs[2][c]);
        rate = dx.dot(v[j] - v[i]) * inv_len * inv_l0;
      }
      RodResponse res;
      if constexpr (kScaled) {
        res = evaluate_scaled(law, strain, rate, shift[k], scale_c[c]);
      } else if constexpr (Temp) {
        const double t = rod_temperature(law, temperature[ends[k][0]], temperature[ends[k][1]]);
        res = evaluate(law, strain, rate, shift[k], t);
      } else {
        res = evaluate(law, strain, rate, shift[k]);
      }
      trial_shift[k] = res.shift;
      trial_broken[k] = res.broken;
      stress[k] = res.stress;
      any |= (res.shift != shift[k]) | res.broken;
      if (res.broken) {
        coef[k] = 0.0;
      } else {
        coef[k] = (res.stress + res.viscous_stress) * A * inv_len;
        if constexpr (Rate) {
          const double sA = res.viscous_stress * rate * A;
          // (the fused sum the compiler made of 'visc += sA * l0' before the per-rod power was
          // also stored, which stops the contraction: the golden series keep their bits)
#if defined(__FMA__)
          visc = std::fma(sA, l0, visc);
#else
          visc += sA * l0;
#endif
          if (rod_visc) rod_visc[k] = sA * l0;
        }
      }
    }
  }
  viscous_power = visc;
  changed = any;
}

// All the rods with one concrete law; 'Temp' as in rod_block.
template <class Law, bool Temp>
void evaluate_rods_with(const Law& rod_law, double area, const RodKernelView& view, Periodic periodic) {
  // Copies in locals: through references the compiler would reload them after every store
  // (the uint8_t stores may alias anything).
  const Law law = rod_law;
  const double A = area;
  const std::size_t m = view.rods, nb = block_count(m);
  if (m == 0) return;
  const auto* ends = view.ends;
  const double* l0 = view.rest_length;
  const double* shift = view.shift;
  const std::uint8_t* intact = view.intact;
  const Vec3* x = view.x;
  const Vec3* v = view.v;
  const double* temp = view.temperature;
  const Vec3* lag_x = view.rate_v != nullptr ? view.rate_x : nullptr;
  const Vec3* lag_v = view.rate_v;
  double* trial_shift = view.trial_shift;
  std::uint8_t* trial_broken = view.trial_broken;
  double* stress = view.stress;
  double* coef = view.coef;
  double* block_visc = view.block_viscous;
  int* block_changed = view.block_changed;
  double* rod_visc = view.rod_viscous;
  const bool rate = uses_rate(law);
  // Dynamic: in a cut the rods' cost is uneven (the chip's flow, the formed rods at the list's
  // end), and a static split left one thread waiting (validation/bench/README.md). Each block
  // writes its own sums, so the bits do not depend on which thread took it.
#pragma omp parallel for schedule(dynamic)
  for (std::size_t b = 0; b < nb; ++b) {
    const std::size_t begin = b * kBlock, end = std::min(m, (b + 1) * kBlock);
    // Compile-time switches: the common rate-free or non-periodic cases pay for neither.
    if (rate && periodic.on())
      rod_block<Law, true, true, Temp>(law, A, begin, end, ends, l0, shift, intact, x, v, temp, lag_x, lag_v,
                                       trial_shift, trial_broken, stress, coef, block_visc[b], block_changed[b],
                                       periodic, rod_visc);
    else if (rate)
      rod_block<Law, true, false, Temp>(law, A, begin, end, ends, l0, shift, intact, x, v, temp, lag_x, lag_v,
                                        trial_shift, trial_broken, stress, coef, block_visc[b], block_changed[b],
                                        periodic, rod_visc);
    else if (periodic.on())
      rod_block<Law, false, true, Temp>(law, A, begin, end, ends, l0, shift, intact, x, v, temp, lag_x, lag_v,
                                        trial_shift, trial_broken, stress, coef, block_visc[b], block_changed[b],
                                        periodic, rod_visc);
    else
      rod_block<Law, false, false, Temp>(law, A, begin, end, ends, l0, shift, intact, x, v, temp, lag_x, lag_v,
                                         trial_shift, trial_broken, stress, coef, block_visc[b], block_changed[b],
                                         periodic, rod_visc);
  }
}

}  // namespace

void evaluate_rods(const AnyRodLaw& law, double area, const RodKernelView& view, Periodic periodic) {
  // One visit per call: the loops above see the concrete law.
  std::visit(
      [&](const auto& l) {
        using Law = std::decay_t<decltype(l)>;
        // The temperature only where it can change the law and the World has one.
        if constexpr (Law::kReadsTemperature)
          if (view.temperature != nullptr && reads_temperature(l))
            return evaluate_rods_with<Law, true>(l, area, view, periodic);
        evaluate_rods_with<Law, false>(l, area, view, periodic);
      },
      law);
}

}  // namespace swarf
