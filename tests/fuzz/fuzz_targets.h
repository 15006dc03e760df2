// fuzz_targets.h: what each fuzzer feeds its input to (issue 18, item 3). One function per
// reader; a libFuzzer harness (fuzz_main.cpp) calls one of them per input, and the ctest
// suite (test_fuzz_regressions.cpp) calls them on every seed and every input a fuzzer found.
//
// An input passes when the reader accepts it or refuses it with InputError (a clear message:
// file, key, value). Anything else escapes: another exception (std::bad_alloc,
// std::out_of_range, toml++'s own), a crash, a sanitizer report or a hang is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace swarf::fuzz {

/// A case file: leading lines "--set key=value" are overrides, the rest is the TOML. The
/// case is parsed and, when it is small (a few hundred particles), built into a model
/// (derived quantities, groups, meshes, the output schedule). Relative file names resolve in
/// a directory holding tool.stl, tool.obj, particles.txt and lattice.h5.
void case_file(const std::uint8_t* data, std::size_t size);
/// A case of the tables added after case_file was written ([cut] with heat, [[inflow]] and
/// [[outflow]], a rigid body, [membrane], a compliant tool): the first byte picks a valid base
/// case, each following line is a 'key=value' override (as --set); the case passes the run's
/// memory and step checks (app/run_limits.h), is built when small and stepped three times.
void case_model(const std::uint8_t* data, std::size_t size);
/// How a case_model input ended: refused (an InputError), too large to build here, built and
/// stopped by a SimulationError in its three steps, or built and stepped.
enum class ModelOutcome { refused, too_large, stopped, stepped };
ModelOutcome case_model_outcome(const std::uint8_t* data, std::size_t size);
/// The number of base cases (the first byte of an input picks one, modulo this).
std::size_t case_model_bases();
/// An STL file (ASCII or binary), read as a mesh.
void stl(const std::uint8_t* data, std::size_t size);
/// An OBJ file, read as a mesh.
void obj(const std::uint8_t* data, std::size_t size);
/// A study file; when it expands to few cases, the base case is read with each case's
/// overrides (as 'swarf sweep' does before it runs).
void study_file(const std::uint8_t* data, std::size_t size);
/// A lattice file (HDF5), as the contents swarf reads: the input edits the datasets and
/// attributes of a valid 2 x 2 x 2-cell lattice (shapes, values, NaNs, huge or negative
/// indices, missing datasets), the result is written with HDF5 and read by read_lattice; a
/// lattice it accepts is built into a model and stepped.
void lattice_file(const std::uint8_t* data, std::size_t size);
/// A checkpoint (HDF5), likewise: the input edits the datasets and attributes of a valid
/// checkpoint of a small cut with contacts; the result is restarted as 'swarf run --restart'
/// does (case, model, state, run record) and stepped.
void checkpoint(const std::uint8_t* data, std::size_t size);

/// The targets by name (the fuzzers' names and the folders of their corpora).
struct Target {
  const char* name;
  void (*run)(const std::uint8_t*, std::size_t);
};
const std::vector<Target>& targets();

}  // namespace swarf::fuzz
