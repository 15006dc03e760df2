// chip.cpp: chip identification and metrics (see chip.h).
#include "postprocess/chip.h"

#include <fmt/format.h>

#include <Eigen/Dense>
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

using Vec2 = Eigen::Vector2d;
Vec2 in_plane(const Vec3& x) { return {x[0], x[2]}; }  // (x, z)

constexpr double kCurlStepRadii = 4.0;     // centreline step: two particle diameters, in R
constexpr std::size_t kCurlMinPoints = 5;  // fewer centreline points: not measured
constexpr double kCurlMinArcDeg = 30.0;    // a smaller arc: a nearly straight chip, not measured
constexpr double kCurlMaxTurnDeg = 30.0;   // a larger turn in one step: the march has left the chip

struct Circle {
  Vec2 centre = Vec2::Zero();
  double radius = NAN;
  double rms = NAN;
};

double circle_rms(const std::vector<Vec2>& p, const Vec2& c, double r) {
  double s = 0.0;
  for (const Vec2& q : p) s += std::pow((q - c).norm() - r, 2);
  return std::sqrt(s / double(p.size()));
}

// Kasa's algebraic fit (x^2 + z^2 + D x + E z + F = 0 in least squares, about the points' mean for
// conditioning), then Gauss-Newton on the geometric distance, kept when it lowers the rms. No circle
// (radius NaN) for collinear points.
Circle fit_circle(const std::vector<Vec2>& p) {
  Circle c;
  Vec2 mean = Vec2::Zero();
  for (const Vec2& q : p) mean += q;
  mean /= double(p.size());
  Eigen::MatrixXd a(p.size(), 3);
  Eigen::VectorXd b(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 q = p[i] - mean;
    a.row(i) << q[0], q[1], 1.0;
    b[i] = -q.squaredNorm();
  }
  const auto qr = a.colPivHouseholderQr();
  if (qr.rank() < 3) return c;
  const Eigen::Vector3d def = qr.solve(b);
  const double r2 = 0.25 * (def[0] * def[0] + def[1] * def[1]) - def[2];
  if (!(r2 > 0) || !std::isfinite(r2)) return c;
  c.centre = mean - 0.5 * Vec2(def[0], def[1]);
  c.radius = std::sqrt(r2);
  c.rms = circle_rms(p, c.centre, c.radius);
  Vec2 gc = c.centre;
  double gr = c.radius;
  for (int it = 0; it < 20; ++it) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (const Vec2& q : p) {
      const Vec2 d = q - gc;
      const double n = d.norm();
      if (!(n > 0)) return c;
      const Eigen::Vector3d j(-d[0] / n, -d[1] / n, -1.0);
      jtj += j * j.transpose();
      jtr += j * (n - gr);
    }
    const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) break;
    gc += step.head<2>();
    gr += step[2];
    if (step.norm() < 1e-12 * std::abs(gr)) break;
  }
  const double grms = gr > 0 ? circle_rms(p, gc, gr) : NAN;
  if (grms < c.rms) c = {gc, gr, grms};
  return c;
}
}  // namespace

Vec3 to_tool_frame(const Vec3& v, double inclination_deg) {
  if (inclination_deg == 0.0) return v;
  const double l = inclination_deg * kDeg, c = std::cos(l), s = std::sin(l);
  return Vec3(c * v[0] + s * v[1], -s * v[0] + c * v[1], v[2]);
}

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
    m.head = std::max(m.head, along);
    if (along < 2.0 * in.depth_of_cut || along >= section_end) continue;  // edge region, or curled away
    dist.push_back(rel.dot(normal));
  }
  m.measured_particles = dist.size();
  if (dist.size() < 10 || !(in.depth_of_cut > 0)) return m;
  if (m.head < section_end + 0.5 * in.depth_of_cut) return m;  // the head still crosses the section (chip.h)
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

ChipCurl measure_chip_curl(const ChipInput& in, const ChipMetrics& m) {
  ChipCurl c;
  const auto [up3, normal3] = rake_frame(in.rake_angle_deg);
  const Vec2 up = in_plane(up3), tip = in_plane(in.tool_tip);
  const double step = kCurlStepRadii * in.radius, h = in.depth_of_cut;
  if (!(h > 0) || !(in.radius > 0)) {
    c.note = "no depth of cut or particle radius";
    return c;
  }
  std::vector<Vec2> chip;
  chip.reserve(m.members.size());
  for (std::size_t i : m.members) chip.push_back(in_plane(in.position[i]));
  // The chip leaves the face past the last particle that touches it, and not before the thickness section ends.
  c.start = std::max(rake_contact_length(in), 3.0 * h);
  // The slab of the chip particles about 'centre' (along 'dir' within +- step/2, across within +- width): their
  // positions across it.
  const auto slab = [&](const Vec2& centre, const Vec2& dir, double width) {
    const Vec2 across(dir[1], -dir[0]);
    std::vector<double> u;
    for (const Vec2& x : chip) {
      const Vec2 rel = x - centre;
      const double a = rel.dot(across);
      if (std::abs(rel.dot(dir)) < 0.5 * step && std::abs(a) < width) u.push_back(a);
    }
    return u;
  };
  // The first point: mid-thickness of the slab on the face just before s0 (the whole chip's width across).
  const Vec2 first = tip + (c.start - 0.5 * step) * up;
  const std::vector<double> u0 = slab(first, up, HUGE_VAL);
  const std::size_t min_count = std::max<std::size_t>(3, u0.size() / 3);
  if (u0.size() < 3) {
    c.note = fmt::format("the chip does not reach {:.3g} mm along the rake face, where it would leave it",
                         c.start * 1e3);
    return c;
  }
  // (across the first slab is the face's normal: u is the distance from the face)
  const double lo0 = quantile(u0, 0.02), hi0 = quantile(u0, 0.98);
  const double width = hi0 - lo0 + 2.0 * in.radius;  // the local thickness: the window is +- one thickness
  std::vector<Vec2> pts{first + 0.5 * (lo0 + hi0) * Vec2(up[1], -up[0])};
  std::vector<double> counts;  // particles in each slab after the first
  Vec2 dir = up;
  double turned = 0.0;
  for (std::size_t k = 0; k < chip.size() && turned < 2 * M_PI; ++k) {
    const Vec2 guess = pts.back() + step * dir;
    const std::vector<double> u = slab(guess, dir, width);
    if (u.size() < min_count) break;
    const Vec2 next = guess + 0.5 * (quantile(u, 0.02) + quantile(u, 0.98)) * Vec2(dir[1], -dir[0]);
    const Vec2 d = (next - pts.back()).normalized();
    // A turn of more than 30 deg in one step (a radius under about 2 steps, 8 R, which slabs of 4 R
    // cannot resolve) is the march leaving the chip: at its end, slabs of a few end particles and
    // strays pull the point aside, and the next slabs can run back along the chip.
    const double turn = std::abs(std::atan2(dir[0] * d[1] - dir[1] * d[0], dir.dot(d)));
    if (turn > kCurlMaxTurnDeg * kDeg) break;
    turned += turn;
    dir = d;
    pts.push_back(next);
    counts.push_back(double(u.size()));
  }
  // The slabs at the chip's end reach past it: partly filled, and unevenly across (its end face is not
  // across the slab), so their midpoints are off the centreline (a point 20 um off at the end of a 90 deg
  // curl of 0.5 mm gave 4 % on R_u). Trailing slabs with less than 3/4 of the median slab's particles go.
  if (counts.size() >= 2) {
    const double full = quantile(counts, 0.5);
    while (!counts.empty() && counts.back() < 0.75 * full) {
      counts.pop_back();
      pts.pop_back();
    }
  }
  c.points = pts.size();
  for (const Vec2& p : pts) c.centreline.emplace_back(p[0], 0.0, p[1]);
  if (pts.size() < kCurlMinPoints) {
    c.note = fmt::format(
        "{} centreline points (at least {} needed): the chip reaches only about {:.3g} mm past {:.3g} mm "
        "along the rake face, where it leaves it",
        pts.size(), kCurlMinPoints, double(pts.size() - 1) * step * 1e3, c.start * 1e3);
    return c;
  }
  const Circle fit = fit_circle(pts);
  if (std::isfinite(fit.radius)) {
    // The angle the points cover: their angles about the centre, unwrapped along the centreline.
    double angle = 0.0, lo = 0.0, hi = 0.0;
    for (std::size_t k = 1; k < pts.size(); ++k) {
      const Vec2 a = pts[k - 1] - fit.centre, b = pts[k] - fit.centre;
      angle += std::atan2(a[0] * b[1] - a[1] * b[0], a.dot(b));
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
    }
    c.arc_deg = (hi - lo) / kDeg;
    c.centre = Vec3(fit.centre[0], 0.0, fit.centre[1]);
  }
  if (!(c.arc_deg >= kCurlMinArcDeg)) {
    c.note = fmt::format(
        "the {} centreline points cover {:.3g} deg of their circle (at least {} deg needed): a nearly straight "
        "chip, whose curl radius is not defined{}",
        pts.size(), c.arc_deg, kCurlMinArcDeg,
        std::isfinite(fit.radius) ? fmt::format(" (the fit's {:.3g} mm is not a measurement)", fit.radius * 1e3)
                                  : std::string(" (the points lie on a line)"));
    return c;
  }
  // An up-curl turns away from the face: its centre lies on the chip's side of the first point. A centre on the
  // tool's side is a centreline bending back towards the face (a chip's rounded head, thinning towards its end).
  if ((fit.centre - pts.front()).dot(Vec2(up[1], -up[0])) < 0) {
    c.note = fmt::format(
        "the {} centreline points bend towards the rake face (their circle, of {:.3g} mm over {:.3g} deg, has its "
        "centre on the tool's side): not a curl away from the face",
        pts.size(), fit.radius * 1e3, c.arc_deg);
    return c;
  }
  c.measured = true;
  c.radius = fit.radius;
  c.fit_rms = fit.rms;
  return c;
}

ChipFlow measure_chip_flow(const ChipInput& in, const ChipMetrics& m, const std::vector<Vec3>& velocity,
                           double cut_width) {
  ChipFlow f;
  const auto [up, normal] = rake_frame(in.rake_angle_deg);
  const double section_end = std::min(3.0 * in.depth_of_cut, in.face_length);
  std::vector<double> across;
  Vec3 sum = Vec3::Zero();
  std::size_t middle = 0;
  for (std::size_t i : m.members) {
    const Vec3 rel = in.position[i] - in.tool_tip;
    const double along = rel.dot(up);
    if (along < in.depth_of_cut || along >= section_end) continue;  // past the edge, on the face
    across.push_back(rel[1]);
    if (std::abs(rel[1]) > 0.25 * cut_width) continue;  // the side flow's quarters
    sum += velocity[i];
    ++middle;
  }
  f.particles = middle;
  if (across.size() < 10 || middle < 10) return f;
  f.width = quantile(across, 0.98) - quantile(across, 0.02) + 2.0 * in.radius;
  f.flow_angle_deg = std::atan2(sum[1], sum.dot(up)) / kDeg;  // (y is the edge, up the face's normal to it)
  return f;
}

double side_burr(const std::vector<Vec3>& world_position, const ChipInput& in, double inclination_deg, double y_lo,
                 double y_hi) {
  const double h = in.depth_of_cut;
  double burr = 0.0;
  for (const Vec3& x : world_position) {
    if (x[2] > in.uncut_surface_z + in.radius || x[2] < in.tool_tip[2] - 2.0 * h) continue;  // chip, or deep
    if (!(to_tool_frame(x - in.tool_tip, inclination_deg)[0] < -h)) continue;                // not yet behind the edge
    const double out = std::max(x[1] - y_hi, y_lo - x[1]);
    if (out < 5.0 * h) burr = std::max(burr, out);
  }
  return burr;
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
