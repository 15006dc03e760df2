// vtk_output.h: the ParaView series DIR/particles.pvd over frames/*.vtu.
//
// Each frame is two unstructured grids: the particles as vertices (point data velocity m/s,
// displacement m, radius m, broken_fraction 1, group) and the rods as lines between them
// (cell data stress Pa, strain 1, plastic_shift 1, state 1 = intact / 0 = broken). The
// .pvd lists both as parts 0 and 1 of every time step; ParaView opens it as one series.
// The .pvd is rewritten (atomically) after every frame.
#pragma once

#include <string>
#include <vector>

#include "mesh.h"
#include "particles.h"
#include "rods.h"

namespace swarf {

class VtkSeries {
 public:
  VtkSeries(const std::string& dir, bool with_rods);
  /// Writes frame number 'frames()' at simulated time t (s).
  void write_frame(double t, const Particles& p, const Rods& r);
  std::size_t frames() const { return times_.size(); }

 private:
  void write_pvd() const;
  std::string dir_;
  bool with_rods_;
  std::vector<double> times_;
};

/// Writes a triangle mesh as a VTK XML polydata file (.vtp), atomically.
void write_vtp(const std::string& path, const TriangleMesh& mesh);

/// Fraction of each particle's rods that are broken (0 for a particle without rods).
std::vector<double> broken_fraction_per_particle(const Particles& p, const Rods& r);

}  // namespace swarf
