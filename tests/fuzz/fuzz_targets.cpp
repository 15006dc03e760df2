// fuzz_targets.cpp: the readers as the fuzzers and the regression test drive them (see
// fuzz_targets.h). The text readers take the input as the file's bytes. The HDF5 readers take
// it as edits of a valid file: libhdf5 is not ours to fix and not instrumented (a fuzzer of
// its raw bytes reports crashes inside the library, which has had dozens of such CVEs), so
// these harnesses fuzz what swarf reads from a file HDF5 opens: which datasets exist, their
// shapes and every value (NaN, inf, huge, negative, out-of-range indices, duplicates), and
// the attributes, then go on as far as swarf would (a model built and stepped).
#include "fuzz_targets.h"

#include <fmt/format.h>
#include <hdf5.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string_view>

#include "app/observers/case_observers.h"
#include "app/observers/observer_set.h"
#include "app/run_limits.h"
#include "app/run_outputs.h"
#include "io/checkpoint.h"
#include "io/h5file.h"
#include "io/mesh_file.h"
#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/lattice_file.h"
#include "lattice_gen/membrane_lattice.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "study/study.h"
#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"

namespace swarf::fuzz {
namespace {

// A scratch directory of this process (in memory when /dev/shm exists: a file per input),
// removed at exit.
const std::string& scratch() {
  // (never destroyed: the exit handler below still reads it)
  static const std::string& dir = *new std::string([] {
    const std::filesystem::path base = std::filesystem::is_directory("/dev/shm")
                                           ? "/dev/shm"
                                           : std::filesystem::temp_directory_path();
    const std::string d = (base / fmt::format("swarf_fuzz_{}", ::getpid())).string();
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratch(), ec);
    });
    return d;
  }());
  return dir;
}

std::string file_of(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

// Runs f; an InputError is a clean refusal, everything else escapes to the caller.
template <class F>
void refused_or_accepted(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

// A few steps of a built model; a SimulationError (the run would stop, exit 3) is clean too.
bool step_a_little(Model& model, int steps) {
  Simulation sim(model, model.step);
  try {
    for (int k = 0; k < steps; ++k) sim.step();
  } catch (const SimulationError&) {
    return false;
  }
  return true;
}

// The small case the HDF5 targets build around their files.
const char* const kSmallCase = R"([rod]
youngs_modulus = 200e9
yield_strain = 1e-3
hardening_modulus = 20e9
tensile_strength = 2.3e8
[contact]
youngs_modulus = 200e9
poisson_ratio = 0.3
friction = 0.3
[[group]]
name = "base"
side = "z-"
[[mesh]]
name = "tool"
rake_angle = 10.0
clearance_angle = 7.0
width = 4e-3
face_length = 2e-3
origin = [-0.05e-3, 1.0e-3, 1.0e-3]
motion = "velocity"
velocity = [20.0, 0.0, 0.0]
[integrator]
scheme = "newmark"
end_time = 1e-3
[output]
vtk = false
plots = false
progress = false
)";

// The files a fuzzed case may name (relative to the scratch directory).
void write_case_files() {
  static const bool done = [] {
    TriangleMesh m;
    m.vertices = {Vec3(0, 0, 0), Vec3(1e-3, 0, 0), Vec3(0, 1e-3, 0), Vec3(0, 0, 1e-3)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    write_stl(scratch() + "/tool.stl", m);
    std::ofstream(scratch() + "/tool.obj")
        << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    std::ofstream(scratch() + "/particles.txt") << "# id x y z vx vy vz\n0 0 0 0 0 0 0\n1 0.002 0 0 -1 0 0\n";
    FccSpec spec;
    spec.radius = 0.5e-3;
    spec.cells = {1, 1, 1};
    write_lattice(scratch() + "/lattice.h5", generate_fcc(spec));
    std::ofstream(scratch() + "/base.toml") << "[workpiece]\ncells = [2, 1, 1]\nradius = 0.5e-3\n[integrator]\n"
                                               "end_time = 1e-6\n[output]\nvtk = false\nplots = false\n";
    return true;
  }();
  (void)done;
}

// Whether a parsed case is small enough to build in a fuzzer's iteration (a few hundred
// particles; the program itself refuses cases larger than the machine's memory, app/run.cpp).
// A metal's flow curve is not built: its calibration runs the material lab (a minute per
// case under the sanitizers); the keys are still read and checked.
// The FCC cells of a generated workpiece (0 without one, or with a lattice file).
double workpiece_cells(const CaseSettings& cs) {
  const WorkpieceSettings& w = cs.workpiece;
  if (!w.enabled || !w.lattice_file.empty()) return 0.0;
  double cells = 1;
  const double a = 2.0 * std::sqrt(2.0) * w.radius;
  for (int k = 0; k < 3; ++k) cells *= w.cells[0] > 0 ? double(w.cells[k]) : w.size[k] / a + 1.0;
  return cells;
}

bool small(const CaseSettings& cs) {
  if (cs.particles.size() > 200 || cs.material.flow_curve) return false;
  return workpiece_cells(cs) <= 64.0;
}

// --- Edits of an HDF5 file's contents ---

// The input read as a stream of edit instructions; past its end everything reads 0.
class Bytes {
 public:
  Bytes(const std::uint8_t* p, std::size_t n) : p_(p), n_(n) {}
  bool empty() const { return n_ == 0; }
  std::uint8_t byte() {
    if (n_ == 0) return 0;
    --n_;
    return *p_++;
  }
  std::uint64_t u64(int bytes) {
    std::uint64_t v = 0;
    for (int k = 0; k < bytes; ++k) v = (v << 8) | byte();
    return v;
  }
  std::string text(std::size_t most) {
    std::string s;
    const std::size_t len = std::min<std::size_t>(byte(), most);
    for (std::size_t k = 0; k < len && !empty(); ++k) s += char(byte());
    return s;
  }

 private:
  const std::uint8_t* p_;
  std::size_t n_;
};

struct Dataset {
  std::string name;
  bool integer = false;
  std::vector<double> d;
  std::vector<std::int64_t> i;
  std::size_t rows = 0, cols = 1;
  std::size_t size() const { return integer ? i.size() : d.size(); }
};
struct Attribute {
  std::string name;
  bool text = false;
  std::string s;
  double v = 0;
};
struct H5Image {
  std::vector<Dataset> sets;
  std::vector<Attribute> attributes;
};

herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(std::string("/") + name);
  return 0;
}
herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

// Every dataset and root attribute of a file (the files swarf writes: numbers and strings).
H5Image load_image(const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::vector<std::string> links, attributes;
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  H5Lvisit(f, H5_INDEX_NAME, H5_ITER_INC, collect_link, &links);
  H5Aiterate2(f, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute, &attributes);
  H5Image img;
  const H5File file(path, H5File::Mode::Read);
  for (const std::string& name : links) {
    const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
    if (d < 0) continue;  // (a group)
    const hid_t t = H5Dget_type(d);
    Dataset s;
    s.name = name;
    s.integer = H5Tget_class(t) == H5T_INTEGER;
    H5Tclose(t);
    H5Dclose(d);
    if (s.integer)
      s.i = file.read_ints(name, s.rows, s.cols);
    else
      s.d = file.read_doubles(name, s.rows, s.cols);
    img.sets.push_back(std::move(s));
  }
  for (const std::string& name : attributes) {
    const hid_t a = H5Aopen(f, name.c_str(), H5P_DEFAULT);
    const hid_t t = H5Aget_type(a);
    Attribute at;
    at.name = name;
    at.text = H5Tget_class(t) == H5T_STRING;
    H5Tclose(t);
    H5Aclose(a);
    if (at.text)
      at.s = file.read_string_attribute(name);
    else
      at.v = file.read_double_attribute(name);
    img.attributes.push_back(std::move(at));
  }
  H5Fclose(f);
  return img;
}

void save_image(const H5Image& img, const std::string& path) {
  H5File f(path, H5File::Mode::Create);
  for (const Dataset& s : img.sets) {
    if (s.integer)
      f.write(s.name, s.i.data(), s.rows, s.cols);
    else
      f.write(s.name, s.d.data(), s.rows, s.cols);
  }
  for (const Attribute& a : img.attributes) {
    if (a.text)
      f.write_attribute(a.name, a.s);
    else
      f.write_attribute(a.name, a.v);
  }
  f.close();
}

double special_double(std::uint8_t k, const Dataset& s) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double table[] = {std::nan(""), inf,    -inf, 0.0,  -0.0,         1.0,    -1.0,           1e300, -1e300, 1e-300,
                          0.5,          2.5e-4, 1e6,  1e-3, 4294967299.0, 9.3e18, double(s.rows), -1e-3, 1e-30,  2e-3};
  return table[k % std::size(table)];
}
std::int64_t special_int(std::uint8_t k, const Dataset& s) {
  const std::int64_t table[] = {0,
                                -1,
                                1,
                                2,
                                std::numeric_limits<std::int32_t>::max(),
                                std::numeric_limits<std::int32_t>::min(),
                                std::numeric_limits<std::int64_t>::max(),
                                std::numeric_limits<std::int64_t>::min(),
                                std::int64_t(1) << 32,
                                std::int64_t(s.rows),
                                std::int64_t(s.rows) - 1,
                                std::int64_t(s.rows) + 1,
                                1000000,
                                255,
                                256};
  return table[k % std::size(table)];
}

// Applies the input's edits: set a value (special or raw bits), resize, reshape, delete a
// dataset, swap two values, edit an attribute.
void edit(H5Image& img, Bytes& in) {
  const int edits = 1 + in.byte() % 8;
  for (int e = 0; e < edits && !in.empty(); ++e) {
    const int op = in.byte() % 8;
    if (op == 7) {
      if (img.attributes.empty()) continue;
      Attribute& a = img.attributes[in.byte() % img.attributes.size()];
      if (a.text) {
        if (in.byte() % 2)
          a.s = in.text(64);
        else
          a.s += "\n" + in.text(64);
      } else {
        const std::uint8_t k = in.byte();
        Dataset none;
        a.v = k < 128 ? special_double(k, none) : std::bit_cast<double>(in.u64(8));
      }
      continue;
    }
    if (img.sets.empty()) return;
    const std::size_t which = in.u64(2) % img.sets.size();
    Dataset& s = img.sets[which];
    const std::size_t n = s.size();
    switch (op) {
      case 0:
      case 1: {  // a value: special, or raw bits
        if (n == 0) break;
        const std::size_t k = in.u64(3) % n;
        const std::uint8_t x = in.byte();
        if (s.integer)
          s.i[k] = op == 0 ? special_int(x, s) : std::int64_t(in.u64(8));
        else
          s.d[k] = op == 0 ? special_double(x, s) : std::bit_cast<double>(in.u64(8));
        break;
      }
      case 2: {  // a value nudged (an index by one, a length by a little)
        if (n == 0) break;
        const std::size_t k = in.u64(3) % n;
        const int delta = int(in.byte() % 5) - 2;
        // (The edit itself must not fault: an integer wraps, where -2^63 nudged down was a
        // signed overflow of the harness's own, input int64_min_nudged; a NaN, or a value the
        // nudge would overflow, is left as it is.)
        if (s.integer)
          s.i[k] = std::int64_t(std::uint64_t(s.i[k]) + std::uint64_t(std::int64_t(delta)));
        else if (finite_bits(s.d[k]) && std::abs(s.d[k]) <= 1e300)
          s.d[k] *= 1.0 + 0.25 * delta;
        break;
      }
      case 3: {  // rows
        s.rows = in.u64(2) % (2 * s.rows + 3);
        s.i.resize(s.integer ? s.rows * s.cols : 0, 1);
        s.d.resize(s.integer ? 0 : s.rows * s.cols, 1.0);
        break;
      }
      case 4: {  // columns
        s.cols = 1 + in.byte() % 4;
        s.rows = n / s.cols;
        if (s.integer)
          s.i.resize(s.rows * s.cols);
        else
          s.d.resize(s.rows * s.cols);
        break;
      }
      case 5:  // gone
        img.sets.erase(img.sets.begin() + std::ptrdiff_t(which));
        break;
      case 6: {  // two values swapped
        if (n == 0) break;
        const std::size_t a = in.u64(3) % n, b = in.u64(3) % n;
        if (s.integer)
          std::swap(s.i[a], s.i[b]);
        else
          std::swap(s.d[a], s.d[b]);
        break;
      }
      default:
        break;
    }
  }
}

// The valid files the HDF5 targets edit.
const H5Image& base_lattice() {
  static const H5Image img = [] {
    FccSpec spec;
    spec.radius = 0.5e-3;
    spec.cells = {2, 2, 2};
    write_lattice(scratch() + "/base_lattice.h5", generate_fcc(spec));
    return load_image(scratch() + "/base_lattice.h5");
  }();
  return img;
}

std::string small_case_with_workpiece(const std::string& workpiece) {
  return fmt::format("[workpiece]\n{}\n{}", workpiece, kSmallCase);
}

// A run as app/run.cpp makes one: the model, its observers and its outputs (in 'dir').
struct Run {
  Model model;
  Simulation sim;
  ObserverSet observers;
  RunOutputs outputs;
  Run(const CheckpointCase& c, const std::string& dir)
      : model(build_model(parse_case(c.toml, c.source, c.overrides, c.directory))),
        sim(model, model.step),
        observers(sim, observers_for(model)),
        outputs((std::filesystem::create_directories(dir), dir), model, sim, observers, c) {}
  void steps(int n) {
    const double end = model.settings.integrator.end_time;
    for (int k = 0; k < n && sim.time() < end; ++k) {
      sim.step(end - sim.time());
      outputs.after_step(false);
    }
  }
};

const H5Image& base_checkpoint() {
  static const H5Image img = [] {
    const std::string toml = small_case_with_workpiece("cells = [3, 2, 2]\nradius = 0.5e-3");
    const CheckpointCase c{toml, "fuzz_checkpoint.toml", scratch(), {}, 0.0, 0.0};
    Run run(c, scratch() + "/base_run");
    run.outputs.begin();
    while (run.sim.time() < 2e-5) run.steps(1);  // (the tool is in contact by then)
    run.outputs.write_checkpoint_now();
    return load_image(scratch() + "/base_run/checkpoint.h5");
  }();
  return img;
}

}  // namespace

void case_file(const std::uint8_t* data, std::size_t size) {
  write_case_files();
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  while (text.starts_with("--set ")) {
    const std::size_t eol = text.find('\n');
    overrides.emplace_back(text.substr(6, eol == std::string_view::npos ? std::string_view::npos : eol - 6));
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
  }
  refused_or_accepted([&] {
    const CaseSettings cs = parse_case(std::string(text), "fuzz.toml", overrides, scratch());
    if (small(cs)) build_model(cs);
  });
}

namespace {

// The bases of case_model: a case of each table the case_file seeds hardly reach, small enough
// to build and step in an iteration.
const char* const kModelBases[] = {
    // 0: a [cut] with heat, Johnson-Cook rods and sticking (the default's form), 3 layers (480 particles)
    "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 10.0\nlength_of_cut = 0.05e-3\nrake_angle = 10.0\n"
    "edge_radius = 0.0\nmaterial = \"C45\"\nlayers = 3\n[rod]\nlaw = \"johnson_cook\"\n"
    "[contact]\nsticking = true\n[heat]\nheld_groups = [\"base\"]\n[output]\nvtk = false\nplots = false\n"
    "progress = false\n",
    // 1: spheres from an [[inflow]] into an [[outflow]]
    "[material]\ndensity = 2500.0\n[contact]\nyoungs_modulus = 1e8\n[[inflow]]\nbox_min = [0.0, 0.0, 0.0]\n"
    "box_max = [0.004, 0.004, 0.002]\nrate = 2e4\nradius_min = 0.4e-3\nradius_max = 0.6e-3\n"
    "velocity = [0.0, 0.0, -2.0]\n[[outflow]]\nplane_point = [0.0, 0.0, -0.01]\nplane_normal = [0.0, 0.0, -1.0]\n"
    "[integrator]\nscheme = \"verlet\"\nend_time = 2e-5\n[output]\nvtk = false\nplots = false\nprogress = false\n",
    // 2: a rigid body (a box mesh with mass properties) and a particle
    "[[particle]]\nposition = [0.1, 0.2, 0.34]\nradius = 1e-3\nvelocity = [0.0, 0.0, -1.0]\n[material]\n"
    "density = 1000.0\n[contact]\n[integrator]\nend_time = 1e-5\n[output]\nvtk = false\nplots = false\n"
    "progress = false\n[[mesh]]\nname = \"b\"\ndynamics = \"rigid_body\"\nbox_size = [0.02, 0.04, 0.06]\n"
    "origin = [0.1, 0.2, 0.3]\nmass = 0.1\ncentre_of_mass = [0.1, 0.2, 0.3]\n"
    "inertia = [4e-5, 3e-5, 2e-5, 0.0, 0.0, 0.0]\n",
    // 3: a [membrane] with clamped edges and a ball
    "[membrane]\nlength = 4e-3\nwidth = 4e-3\nradius = 0.5e-3\nthickness = 1e-4\nyoungs_modulus = 1e9\n"
    "pre_tension = 10.0\nclamp_edges = true\n[[particle]]\nposition = [2e-3, 2e-3, 1.2e-3]\nradius = 0.5e-3\n"
    "velocity = [0.0, 0.0, -1.0]\n[contact]\n[integrator]\nend_time = 1e-5\n[output]\nvtk = false\n"
    "plots = false\nprogress = false\n",
    // 4: a [cut] with a compliant tool, cold and on the paper's rods
    "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 10.0\nlength_of_cut = 0.05e-3\nrake_angle = 0.0\n"
    "material = \"Al2024-T351\"\nlayers = 3\ntool_stiffness = 1e9\ntool_mass = 0.1\n"
    "[output]\nvtk = false\nplots = false\nprogress = false\n",
};

// Whether a parsed case of case_model is small enough to build and step in an iteration: the
// memory and step checks of 'swarf run' first (their refusals are clean), then at most a few
// hundred particles. A flow curve is built only with the closed-form calibration.
bool small_model(const CaseSettings& cs) {
  check_memory(cs, false);
  if (cs.material.flow_curve && cs.material.calibration == "shear") return false;
  if (cs.particles.size() > 200) return false;
  if (cs.membrane.enabled) {
    const MembraneSettings& ms = cs.membrane;
    return membrane_site_count(ms.length, ms.width, ms.radius) <= 400.0;
  }
  return workpiece_cells(cs) <= 200.0;
}

}  // namespace

std::size_t case_model_bases() { return std::size(kModelBases); }

ModelOutcome case_model_outcome(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return ModelOutcome::refused;
  write_case_files();
  const std::string base = kModelBases[data[0] % std::size(kModelBases)];
  std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  std::vector<std::string> overrides;
  while (!text.empty() && overrides.size() < 16) {
    const std::size_t eol = text.find('\n');
    std::string line(text.substr(0, eol));
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) overrides.push_back(std::move(line));
  }
  ModelOutcome outcome = ModelOutcome::refused;
  refused_or_accepted([&] {
    const CaseSettings cs = parse_case(base, "fuzz_model.toml", overrides, scratch());
    if (!small_model(cs)) {
      outcome = ModelOutcome::too_large;
      return;
    }
    Model model = build_model(cs);
    // (a step count beyond integrator.max_steps is refused too; a few steps are taken anyway)
    check_run_length(model, true, false, 0.0);
    outcome = step_a_little(model, 3) ? ModelOutcome::stepped : ModelOutcome::stopped;
  });
  return outcome;
}

void case_model(const std::uint8_t* data, std::size_t size) { case_model_outcome(data, size); }

void stl(const std::uint8_t* data, std::size_t size) {
  const std::string path = file_of("mesh.stl", data, size);
  refused_or_accepted([&] { read_mesh(path); });
}

void obj(const std::uint8_t* data, std::size_t size) {
  const std::string path = file_of("mesh.obj", data, size);
  refused_or_accepted([&] { read_mesh(path); });
}

void study_file(const std::uint8_t* data, std::size_t size) {
  write_case_files();
  refused_or_accepted([&] {
    const Study s = parse_study(std::string(reinterpret_cast<const char*>(data), size), "fuzz_study.toml", scratch());
    if (s.cases.size() <= 8) check_cases(s);
  });
}

void lattice_file(const std::uint8_t* data, std::size_t size) {
  H5Image img = base_lattice();
  Bytes in(data, size);
  edit(img, in);
  const std::string path = scratch() + "/lattice_edited.h5";
  save_image(img, path);
  refused_or_accepted([&] {
    read_lattice(path);
    Model model = build_model(parse_case(small_case_with_workpiece("lattice_file = \"lattice_edited.h5\""),
                                         "fuzz_lattice.toml", {}, scratch()));
    step_a_little(model, 3);
  });
}

void checkpoint(const std::uint8_t* data, std::size_t size) {
  H5Image img = base_checkpoint();
  Bytes in(data, size);
  edit(img, in);
  const std::string path = scratch() + "/checkpoint_edited.h5";
  save_image(img, path);
  refused_or_accepted([&] {
    // As app/run.cpp restarts: the stored case, its model and outputs, the state, the record
    // and the observers' state; then a few steps with their outputs.
    const CheckpointCase c = read_checkpoint_case(path);
    Run run(c, scratch() + "/restarted");
    run.outputs.restore(path);
    try {
      run.steps(3);
    } catch (const SimulationError&) {
    }
  });
}

const std::vector<Target>& targets() {
  static const std::vector<Target> t = {{"case_file", case_file},
                                        {"case_model", case_model},
                                        {"stl", stl},
                                        {"obj", obj},
                                        {"study_file", study_file},
                                        {"lattice_file", lattice_file},
                                        {"checkpoint", checkpoint}};
  return t;
}

}  // namespace swarf::fuzz
