// material_lab.h: 'swarf material', the material lab: virtual tests of the bonded FCC lattice of
// a case (lattice_gen/lattice_material.h) written as CSV, PNG and material.json, with a table.
// docs/material-lab.md describes every option, column and key.
#pragma once

#include <string>
#include <vector>

namespace swarf {

struct MaterialOptions {
  std::string case_path;               ///< case file; empty = the built-in default case
  std::vector<std::string> overrides;  ///< --set key=value
  std::string test = "all";            ///< tension100, tension110, compression100, shear100, shear45, cyclic100, all
  double to = 0;                       ///< --to: the test's end strain (magnitude), or the cyclic amplitude
  bool to_given = false;
  double increment = 1e-4;  ///< strain step (log strain; gamma in shear), 1
  // The conditions of a rod law that reads them (setup/rod_laws/): the tests run with the law
  // at this temperature and equivalent plastic strain rate held fixed (its flow stresses times S).
  double temperature = 0;  ///< --temperature, K; 0 = the law's T_ref
  double strain_rate = 0;  ///< --strain-rate, equivalent plastic strain rate, 1/s; 0 = quasi-static
  std::string out_dir;     ///< output directory (required)
};

/// The names --test accepts (without "all").
std::vector<std::string> material_test_names();

/// Runs the tests, writes DIR/<test>.csv, DIR/<test>.png, DIR/material.json (and DIR/material.png
/// for more than one test), prints the table. Throws InputError on bad options (exit 2).
int run_material(const MaterialOptions& options);

}  // namespace swarf
