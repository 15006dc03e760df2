// vtk_output.h: the ParaView series DIR/particles.pvd over frames/*.vtu.
//
// Each frame is two unstructured grids: the particles as vertices (point data: the per-particle
// fields of output_fields.h, then orientations, group and id) and the rods as lines between them
// (cell data stress Pa, strain 1, plastic_shift 1, state 1 = intact / 0 = broken), and each
// triangle mesh (walls, tools) as polydata at its current position. The .pvd lists them as
// parts 0, 1, 2, ... of every time step; ParaView opens it as one series. The particles carry
// their stable ids (point data id), and every grid its time (field data TimeValue, s).
// The .pvd is rewritten (atomically) after every frame.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "io/output_fields.h"
#include "swarf/contacts/contacts.h"
#include "swarf/core/periodic.h"
#include "swarf/measure/particle_fields.h"
#include "swarf/state/mesh.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"

namespace swarf {

class VtkSeries {
 public:
  /// 'with_orientations': the particles' orientations and angular velocities as point data.
  /// 'fields': the point arrays of the table (output_fields.h) written besides those always
  /// written, by name (output.fields).
  VtkSeries(const std::string& dir, bool with_rods, bool with_orientations, std::vector<std::string> fields);
  /// Writes frame number 'frames()' at simulated time t (s): particles, rods and each mesh at
  /// its current placement (reference vertices + offset).
  /// 'fields' (may be null): the measured fields (measure/particle_fields.h) that the table's
  /// rows marked 'measured' need; without them those rows are left out.
  void write_frame(double t, const Particles& p, const Rods& r, const std::vector<MeshBody>& meshes = {},
                   const ParticleFields* fields = nullptr);
  std::size_t frames() const { return times_.size(); }
  const std::vector<double>& times() const { return times_; }
  /// Periodic width: rod strains from the nearest image (the lines still join the stored positions).
  void set_periodic(Periodic periodic) { periodic_ = periodic; }
  /// Continues a series from a checkpoint: frames 0..times.size()-1 exist already.
  void resume(const std::vector<double>& times) { times_ = times; }
  /// The particles' file of frame k, relative to the directory ("frames/particles_00003.vtu").
  static std::string particles_file(std::size_t k);
  /// Lists an extra file (relative to the directory) as a part of the last time step, e.g.
  /// the chip surface; rewrites the .pvd.
  void add_final_part(const std::string& name, const std::string& file);

 private:
  void write_pvd() const;
  std::string dir_;
  bool with_rods_;
  bool with_orientations_;
  std::vector<std::string> fields_;
  std::vector<double> times_;
  std::vector<std::string> mesh_names_;
  std::vector<std::pair<std::string, std::string>> final_parts_;
  Periodic periodic_;
};

/// Writes a triangle mesh as a VTK XML polydata file (.vtp), atomically.
void write_vtp(const std::string& path, const TriangleMesh& mesh);

/// Fraction of each particle's rods that are broken (0 for a particle without rods); with rods
/// formed during the run, the share of its original rods' count it lacks (1 - intact / original).
std::vector<double> broken_fraction_per_particle(const Particles& p, const Rods& r);
/// That of particle i alone (its rod list, Rods::row_start, must be current).
double broken_fraction_of(const Rods& r, std::size_t i);

}  // namespace swarf
