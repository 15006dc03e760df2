// chip.cpp: chip identification and metrics (see chip.h).
#include "postprocess/chip.h"

#include <algorithm>
#include <cmath>

namespace swarf {

namespace {
constexpr double kDeg = M_PI / 180.0;

// The rake face through the tip: the direction up the face and the outward normal (into the chip).
struct RakeFrame {
  Vec3 up, normal;
};
RakeFrame rake_frame(double rake_angle_deg) {
  const double a = rake_angle_deg * kDeg;
  return {Vec3(-std::sin(a), 0.0, std::cos(a)), Vec3(std::cos(a), 0.0, std::sin(a))};
}
}  // namespace

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * double(v.size() - 1);
  const std::size_t k = static_cast<std::size_t>(pos);
  const double f = pos - double(k);
  return k + 1 < v.size() ? v[k] * (1 - f) + v[k + 1] * f : v[k];
}

double shear_angle_deg(double r, double gamma_deg) {
  const double a = gamma_deg * kDeg;
  return std::atan2(r * std::cos(a), 1.0 - r * std::sin(a)) / kDeg;
}

double friction_angle_deg(double fc, double ft, double gamma_deg) { return gamma_deg + std::atan2(ft, fc) / kDeg; }

double merchant_shear_angle_deg(double gamma_deg, double beta_deg) { return 45.0 + 0.5 * gamma_deg - 0.5 * beta_deg; }

ChipMetrics measure_chip(const ChipInput& in) {
  ChipMetrics m;
  const auto [up, normal] = rake_frame(in.rake_angle_deg);
  const double section_end = std::min(3.0 * in.depth_of_cut, in.face_length);
  std::vector<double> dist;
  for (std::size_t i = 0; i < in.position.size(); ++i) {
    const Vec3& x = in.position[i];
    if (!(x[2] > in.uncut_surface_z + in.radius)) continue;
    ++m.chip_particles;
    m.members.push_back(i);
    const Vec3 rel = x - in.tool_tip;
    const double along = rel.dot(up);
    if (along < 2.0 * in.depth_of_cut || along >= section_end) continue;  // edge region, or curled away
    dist.push_back(rel.dot(normal));
  }
  m.measured_particles = dist.size();
  if (dist.size() < 10 || !(in.depth_of_cut > 0)) return m;
  m.thickness = quantile(dist, 0.98) - quantile(dist, 0.02) + 2.0 * in.radius;
  m.compression_ratio = in.depth_of_cut / m.thickness;
  m.shear_angle_deg = shear_angle_deg(m.compression_ratio, in.rake_angle_deg);
  return m;
}

double rake_contact_length(const ChipInput& in) {
  const auto [up, normal] = rake_frame(in.rake_angle_deg);
  double length = 0.0;
  for (const Vec3& x : in.position) {
    const Vec3 rel = x - in.tool_tip;
    const double along = rel.dot(up), off = rel.dot(normal);
    if (along >= 0.0 && along <= in.face_length && off > -in.radius && off < in.radius)
      length = std::max(length, along);
  }
  return length;
}

ChipHeat chip_heat(const ChipInput& in, const ChipMetrics& m, const std::vector<double>& temperature) {
  ChipHeat h;
  double sum = 0.0;
  for (std::size_t i : m.members) sum += temperature[i];
  if (!m.members.empty()) h.chip_mean = sum / double(m.members.size());
  const auto [up, normal] = rake_frame(in.rake_angle_deg);
  for (std::size_t i = 0; i < in.position.size(); ++i) {
    const Vec3 rel = in.position[i] - in.tool_tip;
    const double along = rel.dot(up), off = rel.dot(normal);
    // (a particle on the face has its centre R off it; the edge's rounding puts the first
    // layer near the tip a little further: 2 R takes the first layer and not the second)
    if (along >= 0.0 && along <= in.face_length && off > -in.radius && off < 2.0 * in.radius)
      h.rake_face_max = std::max(h.rake_face_max, temperature[i]);
  }
  return h;
}

}  // namespace swarf
