// push_case.h: the elastic tool-push case shared by test_cut_force.cpp (guided y faces) and
// test_periodic.cpp (periodic width): a rake-0 tool moves u into the x- face of a block whose
// x+ face is clamped and whose other particles are guided; its closed form; the series' last row.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

namespace swarf::test {

struct PushCase {
  int nx = 4, ny = 3, nz = 3;              ///< cells
  double R = 1e-4;                         ///< m
  double u = 1e-6;                         ///< tool displacement, m
  double E_contact = 2e14, nu = 0.3;       ///< Pa, 1 (stiff contacts: the lattice dominates)
  bool periodic = false;                   ///< periodic width instead of guided y faces
  std::string guide_dofs = "yz";           ///< components held for all but the clamped layer
  double tool_y = 0, tool_width = 1.2e-3;  ///< m
};

inline std::string push_case_toml(const PushCase& c) {
  const double h = std::sqrt(2.0) * c.R, x_max = (2 * c.nx - 1) * h;
  return fmt::format(R"([workpiece]
cells = [{nx}, {ny}, {nz}]
radius = {R}
periodic_width = {per}
[rod]
youngs_modulus = 2e11
damping_ratio = 0.5
[contact]
youngs_modulus = {Ec}
poisson_ratio = {nu}
friction = 0.0
[[group]]
name = "clamp"
side = "x+"
[[group]]
name = "guide"
box_max = [{xg}, 1.0, 1.0]
dofs = "{dofs}"
[[mesh]]
name = "tool"
rake_angle = 0.0
width = {tw}
face_length = 1.5e-3
origin = [{x0}, {yc}, -2e-4]
motion = "table"
table_time = [0.0, 2e-5]
table_displacement = [[0.0, 0.0, 0.0], [{u}, 0.0, 0.0]]
[integrator]
end_time = 3e-5
[output]
vtk = false
plots = false
series_interval = 1e-6
)",
                     fmt::arg("nx", c.nx), fmt::arg("ny", c.ny), fmt::arg("nz", c.nz), fmt::arg("R", c.R),
                     fmt::arg("per", c.periodic ? "true" : "false"), fmt::arg("Ec", c.E_contact), fmt::arg("nu", c.nu),
                     fmt::arg("xg", x_max - 0.5 * h), fmt::arg("dofs", c.guide_dofs), fmt::arg("tw", c.tool_width),
                     fmt::arg("x0", -c.R), fmt::arg("yc", c.tool_y), fmt::arg("u", c.u));
}

/// The tool force F (N) that moves the tool by u: 'gaps' identical gaps of n_cross rods of
/// stiffness kb (direction cosine 1/sqrt 2: F = n_cross kb d / 2 per gap) in series with
/// n_face Hertz contacts of constant K (N/m^1.5); solved by bisection.
inline double push_force_closed_form(int gaps, int n_cross, double kb, int n_face, double K, double u) {
  auto u_of = [&](double F) { return gaps * 2.0 * F / (n_cross * kb) + std::pow(F / (n_face * K), 2.0 / 3.0); };
  double lo = 0, hi = 1e6;
  for (int k = 0; k < 200; ++k) (u_of(0.5 * (lo + hi)) < u ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

/// The last row of a series.csv, by column name.
inline std::map<std::string, double> last_row(const std::string& csv_text) {
  std::istringstream csv(csv_text);
  std::string head, line, last;
  std::getline(csv, head);
  while (std::getline(csv, line))
    if (!line.empty()) last = line;
  std::map<std::string, double> row;
  std::istringstream hs(head), ls(last);
  std::string h, v;
  while (std::getline(hs, h, ',') && std::getline(ls, v, ',')) row[h] = std::stod(v);
  return row;
}

}  // namespace swarf::test
