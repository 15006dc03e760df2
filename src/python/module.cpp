// module.cpp: the Python module swarf._swarf (docs/python.md).
//
// A case is built and stepped as by 'swarf run'; the particles', rods' and bodies' arrays are
// NumPy views of the engine's structure-of-arrays storage (no copy): they stay valid while the
// particle count does not change (an inflow or outflow reallocates the arrays: take the view
// again after a step that may have changed it). Views of what the step derives (positions,
// forces, masses) are read-only; positions and a body's pose are set through setters that
// tell the step (the contact lists are rebuilt from the new places); velocities and angular
// velocities are writable in place. Units are SI, as everywhere in swarf.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "app/interrupt.h"
#include "app/run.h"
#include "app/threads.h"
#include "python/py_simulation.h"
#include "swarf/body_coupling.h"
#include "swarf/core/errors.h"
#include "swarf/measure/particle_fields.h"
#include "swarf/version.h"

namespace swarf::python {
namespace {

// An (n, k) view of n records of k T's each, 'stride' bytes apart; 'base' keeps the storage's
// owner alive for as long as the view lives.
template <class T>
py::array view(T* data, std::size_t n, std::size_t k, std::size_t stride, py::handle base, bool writable) {
  static T none{};
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)}, strides{static_cast<py::ssize_t>(stride)};
  if (k > 1) {
    shape.push_back(static_cast<py::ssize_t>(k));
    strides.push_back(static_cast<py::ssize_t>(sizeof(T)));
  }
  py::array a(py::dtype::of<T>(), shape, strides, n == 0 ? &none : data, base);
  if (!writable) py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}
py::array vec3s(std::vector<Vec3>& v, py::handle base, bool writable) {
  return view(v.empty() ? nullptr : v[0].data(), v.size(), 3, sizeof(Vec3), base, writable);
}
template <class T>
py::array scalars(std::vector<T>& v, py::handle base, bool writable) {
  return view(v.data(), v.size(), 1, sizeof(T), base, writable);
}
py::array vec3_copy(const Vec3& v) {
  py::array_t<double> a(3);
  for (int c = 0; c < 3; ++c) a.mutable_at(c) = v[c];
  return a;
}
Vec3 to_vec3(const py::array_t<double, py::array::c_style | py::array::forcecast>& a, const char* what) {
  if (a.ndim() != 1 || a.shape(0) != 3) throw py::value_error(std::string(what) + ": expected 3 numbers");
  return Vec3(a.at(0), a.at(1), a.at(2));
}

// The particles of a Simulation (what sim.particles returns; it keeps the Simulation alive).
struct ParticlesView {
  PySimulation* owner;
  Particles& p() const { return owner->model().particles; }
};
struct RodsView {
  PySimulation* owner;
  Rods& r() const { return owner->model().rods; }
};
// The per-particle fields of the state now (measure/particle_fields.h), as the frames and
// results.h5 carry them: each access computes them (copies, not views).
ParticleFields fields_of(const ParticlesView& v) {
  return particle_fields(v.p(), v.owner->model().rods, v.owner->model().periodic, &v.owner->sim().contacts());
}
py::array_t<double> doubles_copy(const double* data, std::size_t n, std::size_t k) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(n)};
  if (k > 1) shape.push_back(static_cast<py::ssize_t>(k));
  py::array_t<double> a(shape);
  if (n > 0) std::copy(data, data + n * k, a.mutable_data());
  return a;
}

// A property's getter: one scalar field of the particles, computed at each access (a copy).
auto field_copy(std::vector<double> ParticleFields::*member) {
  return [member](const ParticlesView& v) {
    const ParticleFields f = fields_of(v);
    return doubles_copy((f.*member).data(), (f.*member).size(), 1);
  };
}
// One scalar read off each particle's stress tensor (von_mises, hydrostatic), a copy.
auto stress_part(double (*part)(const SymTensor&)) {
  return [part](const ParticlesView& v) {
    const ParticleFields f = fields_of(v);
    std::vector<double> values(f.stress.size());
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = part(f.stress[i]);
    return doubles_copy(values.data(), values.size(), 1);
  };
}

// A held body coupled to an outside code (swarf/body_coupling.h); keeps its Simulation alive.
struct CouplingView {
  PySimulation* owner;
  BodyCoupling coupling;
};
struct BodyView {
  PySimulation* owner;
  std::size_t index;
  RigidBody& b() const { return owner->model().bodies.at(index); }
};

// The index of a mesh or group given by name or by index ('what' names the kind in errors).
template <class Items>
std::size_t index_of(const Items& items, const py::object& key, const char* what) {
  if (py::isinstance<py::str>(key)) {
    const auto name = key.cast<std::string>();
    for (std::size_t k = 0; k < items.size(); ++k)
      if (items[k].name == name) return k;
    throw py::key_error(std::string("no ") + what + " '" + name + "'");
  }
  const auto k = key.cast<long long>();
  if (k < 0 || static_cast<std::size_t>(k) >= items.size())
    throw py::index_error(std::string(what) + " " + std::to_string(k) + " of " + std::to_string(items.size()));
  return static_cast<std::size_t>(k);
}

// What a listener of swarf.run() is given around each step: the running Simulation of 'swarf
// run', valid only during the call.
struct RunStepView {
  Simulation* sim;
};

// The Python callables of swarf.run(before=..., after=...), called with a RunStepView. Made and
// destroyed with the GIL held (run_program); the step runs without it, a call takes it.
class RunListener final : public StepListener {
 public:
  RunListener(py::object before, py::object after) : before_(std::move(before)), after_(std::move(after)) {}
  void before_step(Simulation& s) override { call(before_, s); }
  void after_step(Simulation& s) override { call(after_, s); }

 private:
  void call(const py::object& f, Simulation& s) {
    if (f.is_none()) return;
    py::gil_scoped_acquire gil;
    f(RunStepView{&s});
  }
  py::object before_, after_;
};

// swarf.run(): 'swarf run' in this process. The run's SIGINT/SIGTERM handlers replace
// Python's while it runs and are put back after, so Ctrl-C reaches Python again.
void run_program(const py::object& case_path, const py::object& out, const std::vector<std::string>& set, int threads,
                 const py::object& restart, bool energy_check, const py::object& before, const py::object& after) {
  RunOptions o;
  if (!case_path.is_none()) o.case_path = py::str(case_path);
  if (!out.is_none()) o.out_dir = py::str(out);
  if (!restart.is_none()) o.restart = py::str(restart);
  o.overrides = set;
  o.threads = threads;
  if (threads != 0) check_thread_count(threads, "threads");
  o.energy_check = energy_check;
  RunListener listener(before, after);
  if (!before.is_none() || !after.is_none()) o.listeners.push_back(&listener);
  struct sigaction old_int {
  }, old_term{};
  sigaction(SIGINT, nullptr, &old_int);
  sigaction(SIGTERM, nullptr, &old_term);
  struct Restore {
    struct sigaction &i, &t;
    ~Restore() {
      sigaction(SIGINT, &i, nullptr);
      sigaction(SIGTERM, &t, nullptr);
    }
  } restore{old_int, old_term};
  try {
    py::gil_scoped_release free;
    run_case(o);
  } catch (const Interrupted& e) {
    PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    throw py::error_already_set();
  }
}

}  // namespace
}  // namespace swarf::python

PYBIND11_MODULE(_swarf, m) {
  namespace py = pybind11;
  using namespace swarf;
  using namespace swarf::python;
  m.doc() = "swarf: DEM simulation of orthogonal metal cutting (the compiled part; see swarf.__doc__)";
  m.attr("__version__") = SWARF_VERSION;
  // Bad input and a run that blew up keep their meaning: ValueError and RuntimeError.
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<SimulationError>(m, "SimulationError", PyExc_RuntimeError);
  py::register_exception<OutputError>(m, "OutputError", PyExc_OSError);

  m.def(
      "set_threads",
      [](int n) {
        check_thread_count(n, "threads");
        return set_threads(n);
      },
      py::arg("n"), "Sets the OpenMP thread count of the steps (1 <= n); returns the count in effect.");
  m.def(
      "default_case_text", [] { return std::string(kDefaultCaseToml); },
      "The built-in default case (the C45 cut of docs/default-case.md) as TOML text.");
  m.def("run", &run_program, py::arg("case") = py::none(), py::arg("out") = py::none(),
        py::arg("set") = std::vector<std::string>{}, py::arg("threads") = 0, py::arg("restart") = py::none(),
        py::arg("energy_check") = true, py::arg("before") = py::none(), py::arg("after") = py::none(),
        "Runs a case as 'swarf run' does, with every output (series.csv, summary.json, results.h5, ParaView "
        "files, plots) in 'out'. case: a case file (None: the built-in default case); set: 'key=value' "
        "overrides; threads: 0 for OpenMP's default; restart: a checkpoint to continue; before, after: "
        "callables f(step) around every step (step: a RunStep).");

  py::class_<RunStepView>(m, "RunStep",
                          "What a listener of swarf.run() is given around each step: the run's clock and forces "
                          "(valid only during the call).")
      .def_property_readonly(
          "time", [](const RunStepView& v) { return v.sim->time(); }, "s")
      .def_property_readonly("steps", [](const RunStepView& v) { return v.sim->steps(); })
      .def_property_readonly(
          "last_dt", [](const RunStepView& v) { return v.sim->last_dt(); }, "s")
      .def_property_readonly("broken_rods", [](const RunStepView& v) { return v.sim->broken_rods(); })
      .def_property_readonly("mesh_names",
                             [](const RunStepView& v) {
                               std::vector<std::string> n;
                               for (const auto& mb : v.sim->world().meshes) n.push_back(mb.name);
                               return n;
                             })
      .def(
          "mesh_force",
          [](const RunStepView& v, const py::object& k) {
            return vec3_copy(v.sim->mesh_force(index_of(v.sim->world().meshes, k, "mesh")));
          },
          py::arg("mesh"), "Force of the particles on a mesh (index or name) in the last step, N.");

  py::class_<ParticlesView>(m, "Particles", "The particles' arrays: NumPy views of the engine's storage, SI units.")
      .def("__len__", [](const ParticlesView& v) { return v.p().size(); })
      .def_property_readonly(
          "position", [](py::object s) { return vec3s(s.cast<ParticlesView&>().p().position, s, false); },
          "(n, 3) m, read-only (set with Simulation.set_positions)")
      .def_property_readonly(
          "velocity", [](py::object s) { return vec3s(s.cast<ParticlesView&>().p().velocity, s, true); },
          "(n, 3) m/s, writable between steps (a prescribed component is overwritten by its motion)")
      .def_property_readonly(
          "acceleration", [](py::object s) { return vec3s(s.cast<ParticlesView&>().p().acceleration, s, false); },
          "(n, 3) m/s^2 of the last force evaluation")
      .def_property_readonly(
          "force", [](py::object s) { return vec3s(s.cast<ParticlesView&>().p().force, s, false); },
          "(n, 3) N, total force of the last evaluation")
      .def_property_readonly(
          "initial_position",
          [](py::object s) { return vec3s(s.cast<ParticlesView&>().p().initial_position, s, false); }, "(n, 3) m")
      .def_property_readonly(
          "omega", [](py::object s) { return vec3s(s.cast<ParticlesView&>().p().omega, s, true); },
          "(n, 3) rad/s, world frame, writable (integrated only when rotations are on; (0, 3) in a run whose particles "
          "cannot turn: no contacts, bodies, flows or output.orientations)")
      .def_property_readonly(
          "torque", [](py::object s) { return vec3s(s.cast<ParticlesView&>().p().torque, s, false); }, "(n, 3) N m")
      .def_property_readonly(
          "orientation",
          [](py::object s) {
            auto& q = s.cast<ParticlesView&>().p().orientation;
            return view(q.empty() ? nullptr : q[0].data(), q.size(), 4, sizeof(Quat), s, false);
          },
          "(n, 4) unit quaternions (w, x, y, z), body to world")
      .def_property_readonly(
          "mass", [](py::object s) { return scalars(s.cast<ParticlesView&>().p().mass, s, false); }, "(n,) kg")
      .def_property_readonly(
          "radius", [](py::object s) { return scalars(s.cast<ParticlesView&>().p().radius, s, false); }, "(n,) m")
      .def_property_readonly(
          "id", [](py::object s) { return scalars(s.cast<ParticlesView&>().p().id, s, false); },
          "(n,) stable identities (creation order, never reused)")
      .def_property_readonly(
          "group", [](py::object s) { return scalars(s.cast<ParticlesView&>().p().group, s, false); },
          "(n,) index of the particle's group, -1 if none")
      .def_property_readonly(
          "prescribed", [](py::object s) { return scalars(s.cast<ParticlesView&>().p().prescribed, s, false); },
          "(n,) bitmask of prescribed components (1 x, 2 y, 4 z)")
      .def_property_readonly(
          "temperature", [](py::object s) { return scalars(s.cast<ParticlesView&>().p().temperature, s, false); },
          "(n,) K, read-only ([heat]; (0,) without heat)")
      .def_property_readonly(
          "stress",
          [](const ParticlesView& v) {
            const ParticleFields f = fields_of(v);
            return doubles_copy(f.stress.empty() ? nullptr : f.stress[0].data(), f.stress.size(), 6);
          },
          "(n, 6) Pa, the particles' virial stress (xx, yy, zz, xy, yz, xz; positive in tension), computed "
          "at each access (a copy)")
      .def_property_readonly("von_mises_stress", stress_part(&von_mises),
                             "(n,) Pa, von Mises stress, computed at each access (a copy)")
      .def_property_readonly(
          "hydrostatic_stress", stress_part(&hydrostatic),
          "(n,) Pa, trace of the stress over 3 (positive in tension), computed at each access (a copy)")
      .def_property_readonly("plastic_strain", field_copy(&ParticleFields::plastic_strain),
                             "(n,) 1, von Mises equivalent of the plastic strain the particle's intact rods hold, "
                             "computed at each access (a copy)");

  py::class_<RodsView>(m, "Rods", "The rods (each stored once): NumPy views, SI units.")
      .def("__len__", [](const RodsView& v) { return v.r().size(); })
      .def_property_readonly(
          "ends",
          [](py::object s) {
            auto& e = s.cast<RodsView&>().r().ends;
            return view(e.empty() ? nullptr : e[0].data(), e.size(), 2, sizeof(e[0]), s, false);
          },
          "(m, 2) particle indices i < j")
      .def_property_readonly(
          "intact", [](py::object s) { return scalars(s.cast<RodsView&>().r().intact, s, false); },
          "(m,) 1 intact, 0 broken (committed)")
      .def_property_readonly(
          "rest_length", [](py::object s) { return scalars(s.cast<RodsView&>().r().rest_length, s, false); }, "(m,) m")
      .def_property_readonly(
          "plastic_shift", [](py::object s) { return scalars(s.cast<RodsView&>().r().shift, s, false); },
          "(m,) committed plastic shift of the rod law, 1")
      .def_property_readonly(
          "stress", [](py::object s) { return scalars(s.cast<RodsView&>().r().stress, s, false); },
          "(m,) elastic-plastic stress of the last evaluation, Pa");

  py::class_<BodyView>(m, "Body", "A rigid body: its state (SI units, world frame) and its last wrench.")
      .def_property_readonly("name", [](const BodyView& v) { return v.owner->model().meshes[v.b().mesh].name; })
      .def_property_readonly(
          "mass", [](const BodyView& v) { return v.b().mass; }, "kg")
      .def_property_readonly(
          "inertia", [](const BodyView& v) { return vec3_copy(v.b().inertia); },
          "principal moments of inertia about the centre of mass, kg m^2")
      .def_property_readonly(
          "position", [](const BodyView& v) { return vec3_copy(v.b().state.position); },
          "centre of mass, m (a copy; set with Simulation.set_body_pose)")
      .def_property_readonly(
          "orientation",
          [](const BodyView& v) {
            const Quat& q = v.b().state.orientation;
            py::array_t<double> a(4);
            for (int c = 0; c < 4; ++c) a.mutable_at(c) = q[c];
            return a;
          },
          "unit quaternion (w, x, y, z), principal frame to world (a copy)")
      .def_property_readonly(
          "velocity",
          [](py::object s) {
            return view(s.cast<BodyView&>().b().state.velocity.data(), 3, 1, sizeof(double), s, true);
          },
          "m/s, writable in place (a held component moves at it)")
      .def_property_readonly(
          "omega",
          [](py::object s) { return view(s.cast<BodyView&>().b().state.omega.data(), 3, 1, sizeof(double), s, true); },
          "angular velocity, rad/s, writable in place")
      .def_property_readonly(
          "force", [](const BodyView& v) { return vec3_copy(v.b().force); },
          "total force of the last evaluation (contacts, loads, gravity), N")
      .def_property_readonly(
          "torque", [](const BodyView& v) { return vec3_copy(v.b().torque); }, "total torque, N m")
      .def_property_readonly(
          "contact_force", [](const BodyView& v) { return vec3_copy(v.b().contact_force); }, "force of the particles, N")
      .def_property_readonly(
          "contact_torque", [](const BodyView& v) { return vec3_copy(v.b().contact_torque); },
          "torque of the particles about the centre of mass, N m")
      .def_property_readonly(
          "constraint_force", [](const BodyView& v) { return vec3_copy(v.b().constraint_force()); },
          "force of the held components or the axle, N")
      .def_property_readonly(
          "kinetic_energy", [](const BodyView& v) { return v.b().kinetic_energy(); }, "J");

  py::class_<CouplingView>(m, "BodyCoupling",
                           "A held rigid body whose motion an outside (multibody) code owns: Simulation.couple_body.")
      .def(
          "advance",
          [](CouplingView& c, const py::object& position_end, double duration) {
            const Vec3 x = to_vec3(position_end, "advance: position_end");
            BodyExchange ex;
            {
              py::gil_scoped_release free;
              ex = c.coupling.advance(x, duration);
            }
            py::dict d;
            d["duration"] = ex.duration;
            d["steps"] = ex.steps;
            d["impulse"] = vec3_copy(ex.impulse);
            d["angular_impulse"] = vec3_copy(ex.angular_impulse);
            d["work"] = vec3_copy(ex.work);
            d["mean_force"] = vec3_copy(ex.mean_force());
            return d;
          },
          py::arg("position_end"), py::arg("duration"),
          "Moves the body's centre of mass to position_end (m) over duration (s) at the secant velocity, "
          "stepping the particles with it; returns the exchange: duration s, steps, impulse N s, "
          "angular_impulse N m s (about the centre of mass), work J (per component), mean_force N (to hold "
          "over the outside code's next step). docs/embedding.md says what holding costs.");

  py::class_<PySimulation>(m, "Simulation",
                           "A case built and ready to step: Simulation(case=None, text=None, set=[]). case: a "
                           "case file; text: TOML text; neither: the built-in default case.")
      .def(py::init([](const py::object& case_path, const py::object& text, const std::vector<std::string>& set) {
             return std::make_unique<PySimulation>(case_path.is_none() ? std::string() : std::string(py::str(case_path)),
                                                   text.is_none() ? std::string() : text.cast<std::string>(), set);
           }),
           py::arg("case") = py::none(), py::arg("text") = py::none(), py::arg("set") = std::vector<std::string>{})
      .def_static(
          "from_checkpoint",
          [](const py::object& path, const std::vector<std::string>& set) {
            return PySimulation::from_checkpoint(py::str(path), set);
          },
          py::arg("path"), py::arg("set") = std::vector<std::string>{},
          "The state of a checkpoint ('swarf run' or write_checkpoint), with its own case.")
      .def("step", &PySimulation::step, py::arg("max_dt") = std::numeric_limits<double>::infinity(),
           "One step (Newmark: of at most max_dt, s). Raises SimulationError when the state blows up.")
      .def("run", &PySimulation::run, py::arg("until") = std::numeric_limits<double>::infinity(),
           "Steps to 'until' (s; default the case's integrator.end_time) as 'swarf run' does.")
      .def(
          "add_listener",
          [](py::object self, py::object before, py::object after) {
            return self.cast<PySimulation&>().add_listener(std::move(before), std::move(after), self);
          },
          py::arg("before") = py::none(), py::arg("after") = py::none(),
          "Calls before(sim) and after(sim) around every accepted step; returns a handle. An exception "
          "raised in after() comes out of step() or run() with the step taken.")
      .def("remove_listener", &PySimulation::remove_listener, py::arg("handle"))
      .def(
          "set_positions",
          [](PySimulation& s, const py::array_t<double, py::array::c_style | py::array::forcecast>& x) {
            auto& p = s.model().particles.position;
            if (x.ndim() != 2 || x.shape(0) != static_cast<py::ssize_t>(p.size()) || x.shape(1) != 3)
              throw py::value_error("set_positions: expected an array of shape (" + std::to_string(p.size()) + ", 3)");
            auto r = x.unchecked<2>();
            for (py::ssize_t i = 0; i < r.shape(0); ++i)
              for (int c = 0; c < 3; ++c)
                if (!std::isfinite(r(i, c)))
                  throw py::value_error("set_positions: particle " + std::to_string(i) + " has a non-finite position");
            for (py::ssize_t i = 0; i < r.shape(0); ++i) p[i] = Vec3(r(i, 0), r(i, 1), r(i, 2));
          },
          py::arg("position"), "Sets every particle's position, m ((n, 3)), between steps.")
      .def(
          "set_body_pose",
          [](PySimulation& s, std::size_t b, const py::object& position, const py::object& orientation) {
            const RigidBody& rb = s.model().bodies.at(b);
            const Vec3 x = position.is_none() ? rb.state.position : to_vec3(position, "set_body_pose: position");
            Quat q = rb.state.orientation;
            if (!orientation.is_none()) {
              const auto a = orientation.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
              if (a.ndim() != 1 || a.shape(0) != 4) throw py::value_error("set_body_pose: orientation: 4 numbers");
              q = Quat(a.at(0), a.at(1), a.at(2), a.at(3));
            }
            s.sim().set_body_pose(b, x, q);
          },
          py::arg("body"), py::arg("position") = py::none(), py::arg("orientation") = py::none(),
          "Places body 'body' (index) at a centre of mass (m) and orientation (w, x, y, z).")
      .def(
          "couple_body",
          [](PySimulation& s, std::size_t b) {
            if (b >= s.model().bodies.size())
              throw py::index_error("body " + std::to_string(b) + " of " + std::to_string(s.model().bodies.size()));
            return CouplingView{&s, BodyCoupling(s.sim(), b)};
          },
          py::arg("body"), py::keep_alive<0, 1>(),
          "Couples held body 'body' (fixed = \"xyz\", rotation = \"prescribed\", not turning) to an outside code: "
          "returns a BodyCoupling.")
      .def("write_checkpoint", &PySimulation::write_checkpoint, py::arg("path"),
           "Writes the case and the step's state (Simulation.from_checkpoint continues it bit-identically).")
      .def_property_readonly(
          "particles", [](PySimulation& s) { return ParticlesView{&s}; }, py::keep_alive<0, 1>())
      .def_property_readonly(
          "rods", [](PySimulation& s) { return RodsView{&s}; }, py::keep_alive<0, 1>())
      .def_property_readonly(
          "bodies",
          [](py::object self) {
            auto& s = self.cast<PySimulation&>();
            py::list l;
            for (std::size_t b = 0; b < s.model().bodies.size(); ++b) {
              py::object o = py::cast(BodyView{&s, b});
              py::detail::keep_alive_impl(o, self);
              l.append(o);
            }
            return l;
          },
          "the rigid bodies ([[body]]; a compliant tool)")
      .def_property_readonly(
          "time", [](PySimulation& s) { return s.sim().time(); }, "s")
      .def_property_readonly("steps", [](PySimulation& s) { return s.sim().steps(); })
      .def_property_readonly(
          "dt", [](PySimulation& s) { return s.sim().dt(); }, "the next step's size, s")
      .def_property_readonly(
          "last_dt", [](PySimulation& s) { return s.sim().last_dt(); }, "s")
      .def_property_readonly("implicit", [](PySimulation& s) { return s.sim().implicit(); })
      .def_property_readonly(
          "end_time", [](PySimulation& s) { return s.model().settings.integrator.end_time; },
          "the case's integrator.end_time, s")
      .def_property_readonly(
          "workpiece_particles", [](PySimulation& s) { return s.model().lattice_particles; },
          "particles 0 .. this - 1 are the workpiece's")
      .def_property_readonly(
          "case_text", [](PySimulation& s) { return s.model().settings.effective_toml; },
          "the case as read, after the overrides (TOML)")
      .def_property_readonly("mesh_names",
                             [](PySimulation& s) {
                               std::vector<std::string> n;
                               for (const auto& mb : s.model().meshes) n.push_back(mb.name);
                               return n;
                             })
      .def_property_readonly("group_names",
                             [](PySimulation& s) {
                               std::vector<std::string> n;
                               for (const auto& g : s.model().groups) n.push_back(g.name);
                               return n;
                             })
      .def(
          "mesh_force",
          [](PySimulation& s, const py::object& k) {
            return vec3_copy(s.sim().mesh_force(index_of(s.model().meshes, k, "mesh")));
          },
          py::arg("mesh"), "Force of the particles on a mesh (index or name) in the last step, N.")
      .def(
          "group_reaction",
          [](PySimulation& s, const py::object& g) {
            return vec3_copy(s.sim().group_reaction(index_of(s.model().groups, g, "group")));
          },
          py::arg("group"), "Force a group's prescribed motion exerts on the rest (index or name), N.")
      .def_property_readonly("broken_rods", [](PySimulation& s) { return s.sim().broken_rods(); })
      .def(
          "energies",
          [](PySimulation& s) {
            const Simulation& sim = s.sim();
            const EnergyLedger& l = sim.ledger();
            py::dict d;
            d["kinetic_energy"] = sim.kinetic_energy();
            d["rotational_energy"] = sim.rotational_energy();
            d["elastic_energy"] = sim.elastic_energy();
            d["contact_energy"] = sim.contact_energy();
            d["potential_energy"] = sim.potential_energy();
            d["external_work"] = l.external_work;
            d["plastic_work"] = l.plastic_work;
            d["viscous_work"] = l.viscous_work;
            d["fracture_energy"] = l.fracture_energy;
            d["contact_work"] = l.contact_work;
            d["flow_energy"] = l.flow_energy;
            return d;
          },
          "The energies now and the ledger's sums, J (names as series.csv's columns).")
      .def(
          "stats",
          [](PySimulation& s) {
            const StepStats& st = s.sim().stats();
            py::dict d;
            d["accepted"] = st.accepted;
            d["rejected"] = st.rejected;
            d["iterations"] = st.iterations;
            d["force_evaluations"] = st.force_evaluations;
            d["max_iterations"] = st.max_iterations;
            return d;
          },
          "The step control's counters.")
      .def(
          "state_hash", [](PySimulation& s) { return s.sim().state_hash(); },
          "64-bit hash of every field the next step reads (equal hashes: the same state, bit for bit).");
}
