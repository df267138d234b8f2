// `import wiggle`: the engine as a Python module (docs/PYTHON.md). A Case is the same case
// `wiggle run` makes from the same config (scenario/Case.h, scenario/Experiment.h startRun): the
// same bed from the same cache, the same start, the same steps, so the same state hash after the
// same number of steps, however they are split between step() calls.
//
// Arrays are views of the engine's own memory (no copy), read-only, valid until the next step:
// every re-sort of the grains may move them, so take them again after stepping.
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Format.h"
#include "io/Config.h"
#include "physics/World.h"
#include "scenario/Case.h"
#include "scenario/Experiment.h"

namespace py = pybind11;

namespace wiggle {
namespace {

// A dict {"drive.period": 2.0, "intruder.shape": "triangle"} as `--set` assignments.
std::vector<std::string> overridesOf(const py::dict& overrides) {
  std::vector<std::string> sets;
  for (const auto& [key, value] : overrides) {
    const std::string k = py::str(key);
    std::string v;
    if (py::isinstance<py::bool_>(value))
      v = value.cast<bool>() ? "true" : "false";
    else if (py::isinstance<py::str>(value))
      v = "\"" + value.cast<std::string>() + "\"";
    else
      v = py::str(py::repr(value));  // numbers; lists of numbers print as TOML arrays
    sets.push_back(k + "=" + v);
  }
  return sets;
}

class PyCase {
 public:
  PyCase(const std::optional<std::string>& configPath, const py::dict& overrides, int threads)
      : run_(prepareCase(loadRunConfig(configPath, overridesOf(overrides)))), threads_(threads) {
    CachedBed bed = startRun(run_);
    bedPath_ = bed.path;
    world_.emplace(std::move(bed.world));
    world_->evaluateForces();  // the start's forces, as `wiggle run` evaluates them before its first step
  }

  void step(std::uint64_t n) {
    py::gil_scoped_release release;
    if (threads_ > 0) omp_set_num_threads(threads_);
    world_->run(n);
  }

  // Steps to the last step at or before time t (t on the step grid: t / dt rounded).
  void advance(double t) {
    const double target = std::round(t / world_->def().dt);  // a step number (NaN fails the test below)
    if (!(target >= static_cast<double>(world_->stepCount())))
      throw Error("advance: t = " + formatNumber(t) + " is before the current time " + formatNumber(world_->time()));
    step(static_cast<std::uint64_t>(target) - world_->stepCount());
  }

  // A read-only view of one of the store's arrays; `self` keeps the case alive while it exists.
  py::array_t<double> view(const std::vector<double>& data, py::handle self) const {
    py::array_t<double> a({data.size()}, {sizeof(double)}, data.data(), self);
    a.attr("setflags")(py::arg("write") = false);
    return a;
  }

  const World& world() const { return *world_; }
  const Case& run() const { return run_; }
  const std::string& bedPath() const { return bedPath_; }

 private:
  Case run_;
  int threads_;
  std::optional<World> world_;
  std::string bedPath_;
};

}  // namespace
}  // namespace wiggle

PYBIND11_MODULE(wiggle, m) {
  using wiggle::PyCase;
  m.doc() = "The wiggle engine: a rigid intruder wiggling in a 2D bed of frictional grains (docs/PYTHON.md).";
  static py::exception<wiggle::Error> error(m, "Error");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const wiggle::Error& e) {
      error(e.what());
    }
  });
  m.attr("__version__") = WIGGLE_VERSION;

  py::class_<PyCase> cls(m, "Case",
                         "One case, as `wiggle run` makes it: its bed (cached or made), the drive on, t = 0.");
  cls.def(py::init<const std::optional<std::string>&, const py::dict&, int>(), py::arg("config_path") = py::none(),
          py::arg("overrides") = py::dict(), py::arg("threads") = 0,
          "config_path: a run config (None: the defaults); overrides: {\"drive.period\": 2.0, ...} as --set; "
          "threads: OpenMP threads while stepping (0: as the environment says)")
      .def("step", &PyCase::step, py::arg("n") = 1, "Advance n steps (the GIL is released meanwhile)")
      .def("advance", &PyCase::advance, py::arg("t"), "Step to time t [sqrt(d/g)]")
      .def(
          "state_hash", [](const PyCase& c) { return c.world().stateHash(); },
          "The hash of the whole dynamic state, as summary.json's state_hash")
      .def_property_readonly(
          "t", [](const PyCase& c) { return c.world().time(); }, "Time [sqrt(d/g)]")
      .def_property_readonly(
          "steps", [](const PyCase& c) { return c.world().stepCount(); }, "Steps made")
      .def_property_readonly(
          "dt", [](const PyCase& c) { return c.world().def().dt; }, "Time step [sqrt(d/g)]")
      .def_property_readonly(
          "grain_count", [](const PyCase& c) { return c.world().grainCount(); },
          "Mobile grains: the arrays' first grain_count entries; the frozen base follows")
      .def_property_readonly("particle_count", [](const PyCase& c) { return c.world().particles().size(); })
      .def_property_readonly(
          "config", [](const PyCase& c) { return wiggle::toToml(c.run().config); },
          "The resolved config as TOML (what config.toml of a run holds)")
      .def_property_readonly("bed_path", &PyCase::bedPath, "The cache file of its bed")
      .def_property_readonly(
          "intruder",
          [](const PyCase& c) {
            const wiggle::ClumpState& s = c.world().intruder();
            py::dict d;
            d["x"] = s.x;
            d["y"] = s.y;
            d["vx"] = s.vx;
            d["vy"] = s.vy;
            d["fy"] = s.contactFy;
            return d;
          },
          "The intruder's centre, velocity and the grains' vertical force on it [d, sqrt(g d), m g]");
  // The particle arrays (grains, then the frozen base): read-only views of the engine's memory.
  const auto array = [&cls](const char* name, std::vector<double> wiggle::ParticleStore::*member, const char* doc) {
    cls.def_property_readonly(
        name,
        [member](py::object self) {
          const PyCase& c = self.cast<const PyCase&>();
          return c.view(c.world().particles().*member, self);
        },
        doc);
  };
  array("x", &wiggle::ParticleStore::x, "Centres' x [d] (wrapped into [0, W) at neighbour rebuilds)");
  array("y", &wiggle::ParticleStore::y, "Centres' y [d]");
  array("vx", &wiggle::ParticleStore::vx, "Velocities' x [sqrt(g d)]");
  array("vy", &wiggle::ParticleStore::vy, "Velocities' y [sqrt(g d)]");
  array("omega", &wiggle::ParticleStore::omega, "Spins [sqrt(g/d)]");
  array("fx", &wiggle::ParticleStore::fx, "Forces' x, contacts and gravity [m g]");
  array("fy", &wiggle::ParticleStore::fy, "Forces' y, contacts and gravity [m g]");
  array("radius", &wiggle::ParticleStore::radius, "Radii [d]");
}
