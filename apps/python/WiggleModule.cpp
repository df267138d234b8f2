// `import wiggle`: the engine as a Python module (docs/PYTHON.md). A Case is the same case
// `wiggle run` makes from the same config (scenario/case/Case.h, scenario/run/Experiment.h startRun): the
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
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/RiseRate.h"
#include "core/Error.h"
#include "core/Format.h"
#include "core/Machine.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "physics/World.h"
#include "scenario/case/Case.h"
#include "scenario/lammps/LammpsDump.h"
#include "scenario/run/Checkpoint.h"
#include "scenario/run/Experiment.h"
#include "scenario/run/Remeasure.h"
#include "scenario/run/RunObservers.h"
#include "scenario/run/RunSummary.h"

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

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Rows visited by `forEach` as a dict of NumPy columns, each column's value of a row given by a getter.
template <class Row>
py::dict columnsOf(const std::function<void(const std::function<void(const Row&)>&)>& forEach,
                   const std::vector<std::pair<const char*, std::function<double(const Row&)>>>& columns) {
  std::vector<std::vector<double>> values(columns.size());
  forEach([&](const Row& row) {
    for (std::size_t k = 0; k < columns.size(); ++k) values[k].push_back(columns[k].second(row));
  });
  py::dict d;
  for (std::size_t k = 0; k < columns.size(); ++k)
    d[columns[k].first] = py::array_t<double>(values[k].size(), values[k].data());
  return d;
}

class PyCase {
 public:
  PyCase(const std::optional<std::string>& configPath, const py::dict& overrides, int threads,
         const std::optional<py::function>& drive, double peakSpeed)
      : run_(prepareCase(loadRunConfig(configPath, overridesOf(overrides)))),
        threads_(threadsFor(threads)),
        fields_(run_.config.fields, run_.config.box.width) {
    omp_set_num_threads(threads_);  // the bed, when it is made now, with the run's threads
    CachedBed bed = startRun(run_);
    bedPath_ = bed.path;
    record_.bedKey = bed.key;
    record_.bedFromCache = bed.fromCache;
    world_.emplace(std::move(bed.world));
    world_->enableStepProfile(run_.config.run.profile);  // as `wiggle run` does (run.profile)
    if (drive) installDrive(*drive, peakSpeed);
    world_->evaluateForces();  // the start's forces, as `wiggle run` evaluates them before its first step
    record_.sample(*world_);  // and its first sample, as `wiggle run` takes it
  }

  // A run directory's case, from its newest checkpoint (as `wiggle run --resume` takes it).
  static PyCase load(const std::string& dir, int threads) {
    const std::string configPath = dir + "/config.toml";
    if (!std::filesystem::exists(configPath)) throw Error("load: " + dir + " holds no run (no config.toml)");
    const std::string configToml = readFile(configPath);
    Case run = prepareCase(parseRunConfig(configToml, configPath), BedNeeded::No);  // the checkpoint holds the bed
    const std::string path = checkpointPath(dir);
    if (!std::filesystem::exists(path)) throw Error("load: " + dir + " holds no checkpoint.bin");
    Checkpoint checkpoint = parseCheckpoint(readFile(path), path, run.config, configToml);
    return PyCase(std::move(run), std::move(checkpoint), threads);
  }

  // The case as a run directory that `wiggle run --out DIR --resume` continues and Case.load reads:
  // its config.toml and the checkpoint `wiggle run` would have written at this step, field frames
  // included. The Python case writes no dump file, so a config with dumps is refused rather than
  // saved without its frames; a case with a Python drive cannot be saved (World::save).
  void save(const std::string& dir) const {
    const RunConfig& config = run_.config;
    if (run_.steps.dumpEvery)
      throw Error(
          "save: the Python case writes no dump frames, so a run continued from its checkpoint would miss "
          "them: make the case with run.dump_interval = 0 (case.frame() gives a frame whenever you ask)");
    const std::string configToml = toToml(config);
    // As `wiggle run --out DIR` starts one, holding the directory while the checkpoint is written.
    const FileLock writing = prepareRunDirectory(dir, config, configToml, /*resume=*/false);
    writeCheckpoint(dir, configToml, *world_, record_, fields_);
  }

  void step(std::uint64_t n) {
    if (failed_) throw Error("this case stopped inside a step that failed (" + *failed_ + "): make a new Case");
    try {
      py::gil_scoped_release release;
      omp_set_num_threads(threads_);
      // Observed as `wiggle run` observes (its trajectory samples, phase bins and field frames); no
      // dump file. The observers hold references to members, so they are made per call (a PyCase moves).
      RunObservers observers(run_, record_, fields_, /*dumpPath=*/"");
      observers.stepTowards(*world_, world_->stepCount() + n);
    } catch (const py::error_already_set& e) {
      failed_ = "its drive raised " + std::string(e.what());
      throw;
    } catch (const std::exception& e) {
      failed_ = e.what();  // a step left half done (a drive's bad value, a blow-up): no step after it
      throw;
    }
  }

  // The intruder's x driven by a Python function from now on: drive(t) -> (dx, vx), the displacement
  // from the drive's centre x0 [d] and the velocity [sqrt(g d)], called once per step (serially,
  // with the GIL) before the forces; peak_speed bounds |vx| (the time-step check and the blow-up
  // detector use it, and a larger |vx| stops the step with an error). Its vertical motion stays as
  // it was (free in a run). The forces are evaluated afresh (the neighbour lists rebuilt), so a
  // drive set after the start is not bitwise the same case as one given to the constructor.
  void setDrive(const py::function& drive, double peakSpeed) {
    installDrive(drive, peakSpeed);
    world_->evaluateForces();
  }

  // Steps to the last step at or before time t (t on the step grid: t / dt rounded).
  void advance(double t) {
    const double target = std::round(t / world_->def().dt);  // a step number (NaN fails the test below)
    if (!(target >= static_cast<double>(world_->stepCount())))
      throw Error("advance: t = " + formatNumber(t) + " is before the current time " + formatNumber(world_->time()));
    step(static_cast<std::uint64_t>(target) - world_->stepCount());
  }

  // A read-only view of one of the store's arrays; `self` keeps the case alive while it exists.
  template <class T>
  py::array_t<T> view(const std::vector<T>& data, py::handle self) const {
    py::array_t<T> a({data.size()}, {sizeof(T)}, data.data(), self);
    a.attr("setflags")(py::arg("write") = false);
    return a;
  }

  // The run's own record so far (RunState: the trajectory samples and the phase bins, as `wiggle
  // run` keeps them) and the rise rate by its rules over the paper's window of the time stepped so
  // far, as if the run ended now (analysis/RiseRate.h).
  const RunState& record() const { return record_; }
  const FieldObserver& fields() const { return fields_; }
  py::dict riseRate() const {
    const auto [rate, settled] = measureRunRates(run_, record_.samples, paperWindow(world_->time()));
    py::dict d;
    d["vy"] = rate.vy;
    d["vy_slope"] = rate.slope;
    d["t_i"] = rate.tInitial;  // summary.json's names (docs/summary-schema.json)
    d["t_f"] = rate.tFinal;
    d["plateau"] = rate.plateau;
    d["vy_window_periods"] = rate.windowPeriods;
    d["vy_settled"] = settled.vy;
    d["t_settled"] = settled.tSettled;
    d["settled"] = settled.settled;
    return d;
  }

  const World& world() const { return *world_; }
  const Case& run() const { return run_; }
  const std::string& bedPath() const { return bedPath_; }

 private:
  PyCase(Case run, Checkpoint checkpoint, int threads)
      : run_(std::move(run)), threads_(threadsFor(threads)), fields_(std::move(checkpoint.fields)) {
    world_.emplace(std::move(checkpoint.world));
    world_->enableStepProfile(run_.config.run.profile);  // this process's stepping, as a resumed run
    record_ = std::move(checkpoint.state);
  }

  void installDrive(const py::function& drive, double peakSpeed) {
    wiggle::ClumpMotion motion = world_->intruderMotion();
    motion.kind = wiggle::HorizontalMotion::Prescribed;
    motion.peakSpeed = peakSpeed;
    // The function is kept alive by this Case (drive_), so the engine holds a borrowed pointer.
    motion.prescribed = [fn = drive.ptr()](double t) {
      py::gil_scoped_acquire gil;
      const auto r = py::reinterpret_borrow<py::function>(fn)(t).cast<std::pair<double, double>>();
      return wiggle::ClumpMotion::Position{r.first, r.second};
    };
    world_->setIntruderMotion(motion);  // checks peak_speed; places the intruder at the current t
    drive_ = drive;
  }

  Case run_;
  // 0 asks for `wiggle run`'s default: the cores the load leaves idle (core/Machine.h), decided
  // once, as a run decides it at its start. Not OpenMP's default of every core: on a busy machine
  // threads that must wait for each other at every step's barriers crawl.
  static int threadsFor(int asked) { return asked > 0 ? asked : idleCores(); }
  int threads_;
  std::optional<World> world_;
  std::string bedPath_;
  RunState record_;                    // what `wiggle run` records of the intruder (recordStep)
  FieldObserver fields_;               // and its field frames (fields.enabled)
  py::object drive_;                   // a Python drive (setDrive), alive as long as the world calls it
  std::optional<std::string> failed_;  // why the last step failed
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
  cls.def(py::init<const std::optional<std::string>&, const py::dict&, int, const std::optional<py::function>&,
                   double>(),
          py::arg("config_path") = py::none(), py::arg("overrides") = py::dict(), py::arg("threads") = 0,
          py::arg("drive") = py::none(), py::arg("peak_speed") = 0.0,
          "config_path: a run config (None: the defaults); overrides: {\"drive.period\": 2.0, ...} as --set; "
          "threads: OpenMP threads while stepping (0: as `wiggle run` chooses, the cores the load leaves idle); drive, "
          "peak_speed: the "
          "intruder's x driven by drive(t) -> (dx, vx) from t = 0 instead of the config's drive (see set_drive)")
      .def_static("load", &PyCase::load, py::arg("dir"), py::arg("threads") = 0,
                  "The case of a run directory, from its newest checkpoint, as `wiggle run --out DIR --resume` "
                  "continues it (the same bits)")
      .def("save", &PyCase::save, py::arg("dir"),
           "Write the case as a run directory (config.toml and the checkpoint `wiggle run` writes at this step): "
           "`wiggle run --out DIR --resume` finishes it, Case.load(DIR) continues it. Needs run.dump_interval = 0 "
           "and the config's drive")
      .def("step", &PyCase::step, py::arg("n") = 1, "Advance n steps (the GIL is released meanwhile)")
      .def("advance", &PyCase::advance, py::arg("t"), "Step to time t [sqrt(d/g)]")
      .def("set_drive", &PyCase::setDrive, py::arg("drive"), py::arg("peak_speed"),
           "Drive the intruder's x by drive(t) -> (dx, vx) from now on (dx from the drive's centre [d], vx "
           "[sqrt(g d)]), called once per step; peak_speed [sqrt(g d)] bounds |vx|. A case with such a drive "
           "cannot be checkpointed.")
      .def(
          "state_hash", [](const PyCase& c) { return c.world().stateHash(); },
          "The hash of the whole dynamic state, as summary.json's state_hash")
      .def("rise_rate", &PyCase::riseRate,
           "V_y by wiggle run's rules over t = 0.1 t to t, t the time stepped so far: what summary.json would say "
           "had the run ended now, by its names (vy, vy_slope, t_i, t_f, plateau, vy_window_periods, vy_settled, "
           "t_settled, settled)")
      .def_property_readonly(
          "trajectory",
          [](const PyCase& c) {
            using Sample = wiggle::TrajectorySample;
            using Spin = wiggle::SpinSample;
            py::dict columns = wiggle::columnsOf<Sample>(
                [&c](const std::function<void(const Sample&)>& visit) {
                  for (const Sample& s : c.record().samples) visit(s);
                },
                {{"t", [](const Sample& s) { return s.t; }},
                 {"x", [](const Sample& s) { return s.x; }},
                 {"y", [](const Sample& s) { return s.y; }},
                 {"vx", [](const Sample& s) { return s.vx; }},
                 {"vy", [](const Sample& s) { return s.vy; }},
                 {"fy", [](const Sample& s) { return s.fy; }}});
            if (c.record().spins.empty()) return columns;
            const py::dict turns = wiggle::columnsOf<Spin>(
                [&c](const std::function<void(const Spin&)>& visit) {
                  for (const Spin& s : c.record().spins) visit(s);
                },
                {{"angle", [](const Spin& s) { return s.angle; }}, {"omega", [](const Spin& s) { return s.omega; }}});
            for (const auto& [name, column] : turns) columns[name] = column;
            return columns;
          },
          "The intruder's samples so far, every run.sample_interval from t = 0, as trajectory.csv's columns "
          "t, x, y, vx, vy, fy, and angle, omega when it may turn (copies)")
      .def_property_readonly(
          "phase_rates",
          [](const PyCase& c) {
            const wiggle::RunState& r = c.record();
            py::array_t<double> centre(wiggle::kPhaseBins), mean(wiggle::kPhaseBins);
            py::array_t<std::uint64_t> bin(wiggle::kPhaseBins), count(wiggle::kPhaseBins);
            for (int k = 0; k < wiggle::kPhaseBins; ++k) {
              bin.mutable_at(k) = static_cast<std::uint64_t>(k);
              centre.mutable_at(k) = k + 0.5;
              count.mutable_at(k) = r.phaseCount[k];
              mean.mutable_at(k) =
                  r.phaseCount[k] ? r.phaseSum[k] / static_cast<double>(r.phaseCount[k]) : std::nan("");
            }
            py::dict d;
            d["bin"] = bin;
            d["phase_center"] = centre;
            d["vy_mean"] = mean;
            d["samples"] = count;
            return d;
          },
          "Mean v_y of the intruder per phase bin (10 phi / pi, 20 bins) over the steps after t_i = 0.1 "
          "run.duration, as phase_rates.csv's columns bin, phase_center, vy_mean, samples")
      .def_property_readonly(
          "fields",
          [](const PyCase& c) -> py::object {
            if (!c.run().config.fields.enabled) return py::none();
            return wiggle::columnsOf<wiggle::FieldObserver::Row>(
                [&c](const std::function<void(const wiggle::FieldObserver::Row&)>& visit) {
                  c.fields().forEachRow(visit);
                },
                {{"phase", [](const auto& r) { return r.phase; }},
                 {"x", [](const auto& r) { return r.x; }},
                 {"y", [](const auto& r) { return r.y; }},
                 {"phi", [](const auto& r) { return r.sample ? r.sample->phi : wiggle::kNaN; }},
                 {"vx", [](const auto& r) { return r.sample ? r.sample->vx : wiggle::kNaN; }},
                 {"vy", [](const auto& r) { return r.sample ? r.sample->vy : wiggle::kNaN; }},
                 {"sxx", [](const auto& r) { return r.sample ? r.sample->sxx : wiggle::kNaN; }},
                 {"sxy", [](const auto& r) { return r.sample ? r.sample->symmetricShear() : wiggle::kNaN; }},
                 {"syy", [](const auto& r) { return r.sample ? r.sample->syy : wiggle::kNaN; }},
                 {"pressure", [](const auto& r) { return r.sample ? r.sample->pressure : wiggle::kNaN; }},
                 {"frames", [](const auto& r) { return static_cast<double>(r.frames); }}});
          },
          "The field maps so far (fields.enabled; else None): fields.csv's columns phase, x, y, phi, vx, vy, sxx, "
          "sxy, syy, pressure, frames, NaN where fields.csv leaves a cell empty (copies)")
      .def(
          "frame",
          [](const PyCase& c) {
            const wiggle::ParticleFrame f = wiggle::particleFrame(c.world());
            py::dict d;
            d["step"] = f.step;
            d["t"] = f.time;
            d["box"] = py::make_tuple(py::make_tuple(0.0, f.boxWidth), py::make_tuple(f.yLo, f.yHi),
                                      py::make_tuple(-0.5, 0.5));
            d["intruder"] = py::make_tuple(c.world().intruder().x, c.world().intruder().y);
            d["id"] = py::array_t<std::uint64_t>(f.id.size(), f.id.data());
            d["type"] = py::array_t<int>(f.type.size(), f.type.data());
            const std::pair<const char*, const std::vector<double>*> columns[] = {
                {"x", &f.x},   {"y", &f.y},   {"radius", &f.radius}, {"vx", &f.vx},
                {"vy", &f.vy}, {"fx", &f.fx}, {"fy", &f.fy},         {"tqz", &f.tqz}};
            for (const auto& [name, column] : columns) d[name] = py::array_t<double>(column->size(), column->data());
            return d;
          },
          "The current step as a dump frame: step, t, box, intruder (its centre) and the columns id, type (1 grain, 2 "
          "base, 3 intruder "
          "atom), x, y, radius, vx, vy, fx, fy, tqz, as dump.lammpstrj holds them at full precision (copies)")
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
          "step_profile",
          [](const PyCase& c) -> py::object {
            if (!c.world().stepProfile().on()) return py::none();
            return py::module_::import("json").attr("loads")(wiggle::stepProfileJson(c.world()).dump());
          },
          "With run.profile = true: where the steps' wall time went so far, summary.json's step_profile "
          "(a dict); else None")
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
  const auto array = [&cls]<class T>(const char* name, std::vector<T> wiggle::ParticleStore::*member, const char* doc) {
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
  array("tag", &wiggle::ParticleStore::tag,
        "Each particle's own number (uint32; the dump's id is tag + 1): an array index changes when the engine "
        "re-sorts the grains, a tag never");
}
