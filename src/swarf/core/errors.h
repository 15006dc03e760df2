// errors.h: the exception types that reach the user as a clear message and exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace swarf {

/// Bad input: a case file, option, mesh or lattice file the user must fix. Exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An output could not be written (a full disk, no permission). Exit code 1; the file it
/// was writing keeps its .part name, and no earlier complete file is replaced.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The simulation became invalid (NaN, runaway motion, unstable step). Exit code 3.
struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace swarf
