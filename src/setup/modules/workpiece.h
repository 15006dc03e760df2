// workpiece.h: the workpiece's module of setup: [workpiece]'s settings, key table, rules (cells,
// size or a lattice file; the periodic width; the disorder), its build (the FCC lattice, bonded across
// the periodic width) and its lines of the setup printout. Listed once in each central list:
// parse_case (case_config.cpp), the key rows (case_key_text.cpp), the case echo (app/case_echo.cpp),
// build_model (model.cpp) and the setup printout (app/setup_report.cpp). [cut] reads its keys too
// (cut_case.cpp).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Lattice;
struct Model;
struct Periodic;

/// [workpiece]: the bonded FCC block (optional when [[particle]] or [particles] give particles).
struct WorkpieceSettings {
  bool enabled = false;                 ///< true when the table is present
  std::string lattice_file;             ///< HDF5 lattice from 'swarf lattice'; empty = generate
  std::array<int, 3> cells{0, 0, 0};    ///< conventional FCC cells per axis (generate by cells)
  std::array<double, 3> size{0, 0, 0};  ///< box size, m (generate by size, if cells not given)
  double radius = 0.5e-3;               ///< particle radius R, m (nearest-neighbour distance 2R)
  double bond_tolerance = 1e-6;         ///< relative tolerance on the rod length 2R, 1
  bool periodic_width = false;          ///< periodic along y (plane strain): period = cells[1] x a
  double lattice_rotation = 0.0;        ///< turn of the lattice about y, deg (fcc_lattice.h)
  int disorder_seed = 0;                ///< seed of the position jitter (lattice_disorder.h); 0 = the ordered lattice
  double position_jitter = 0.02;        ///< largest jitter displacement, in radii R, 1 (used when disorder_seed > 0)
};

const std::vector<Key<WorkpieceSettings>>& workpiece_keys();

/// Reads [workpiece] when present and checks its rules; the first table read.
void read_workpiece(const CaseInput& in, CaseSettings& cs);

/// The workpiece's lattice: read from its lattice file or generated (with its rods across a periodic
/// width, which sets 'periodic'); empty without [workpiece] (free particles only).
Lattice workpiece_lattice(const CaseSettings& cs, Periodic& periodic);

/// The setup printout's lines on the workpiece's disorder and periodic width (empty without either).
std::string workpiece_echo(const Model& m);

}  // namespace swarf
