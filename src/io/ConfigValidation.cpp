// validateRunConfig: the checks a whole config must pass before anything runs (each key's own range,
// the rules between keys that need no intruder outline, the schedule on whole steps, and bounded
// sizes), and wholeStepsIn, the one whole-steps rule.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/Error.h"
#include "io/Config.h"
#include "io/ConfigKeys.h"

namespace wiggle {

using namespace config_keys;

std::uint64_t wholeStepsIn(double interval, double dt) {
  const double steps = interval / dt;
  const double n = std::round(steps);
  // Past 2^63 steps no count fits (and converting would be undefined): not a usable interval.
  if (!(n >= 1 && n < 9.2e18)) return 0;
  return std::fabs(steps - n) <= 1e-9 * steps ? static_cast<std::uint64_t>(n) : 0;
}

namespace {

// Each key's own range, from the table (the same check applySetting makes).
void checkKeyRanges(const RunConfig& c) {
  for (const KeyInfo& k : keyTable()) {
    auto fail = [&](const std::string& problem) {
      throw Error(std::string(k.name) + " = " + valueText(k, c, true) + ": " + problem);
    };
    RunConfig& m = mut(c);
    switch (k.kind) {
      case Kind::Number:
        if (const std::string p = rangeProblem(k.number(m), k.lower, k.upper); !p.empty()) fail(p);
        break;
      case Kind::Integer: {
        const std::uint64_t v = k.integer(m);
        if (v > maxTomlInteger) fail("must be <= " + std::to_string(maxTomlInteger));
        if (const std::string p = rangeProblem(static_cast<double>(v), k.lower, k.upper); !p.empty()) fail(p);
        break;
      }
      case Kind::Choice: {
        const std::string v = chosen(k, c);
        if (std::find(k.choices.begin(), k.choices.end(), v) == k.choices.end()) {
          fail("must be one of " + joinedNames(k.choices));
        }
        break;
      }
      case Kind::NumberList: {
        const auto& v = k.numberList(m);
        for (std::size_t i = 0; i < v.size(); ++i) {
          if (const std::string p = rangeProblem(v[i], k.lower, k.upper); !p.empty()) {
            fail("element " + std::to_string(i + 1) + " " + p);
          }
        }
        break;
      }
      case Kind::PointList:
        for (const auto& p : k.pointList(m)) {
          if (!std::isfinite(p[0]) || !std::isfinite(p[1])) fail("every coordinate must be finite");
        }
        break;
      case Kind::Boolean:
      case Kind::Text: break;
    }
  }

}

std::string num(double v) { return roundTripText(v, false); }

// The rules between the box, the grains and the intruder that need no outline (scenario/case/Case
// checks those that do).
void checkShapeKeys(const RunConfig& c) {
  if (c.box.width != std::floor(c.box.width)) {
    throw Error("box.width = " + num(c.box.width) + ": must be a whole number (the base is a row of "
                "unit spheres spaced 1 apart)");
  }
  if (c.grains.dMax < c.grains.dMin) {
    throw Error("grains.d_max = " + num(c.grains.dMax) + ": must be >= grains.d_min (" +
                num(c.grains.dMin) + ")");
  }
  const bool polygon = c.intruder.shape == ShapeName::Polygon;
  if (polygon && c.intruder.vertices.size() < 3) {
    throw Error("intruder.vertices: shape = \"polygon\" needs at least 3 [x, y] pairs, got " +
                std::to_string(c.intruder.vertices.size()));
  }
  if (!polygon && !c.intruder.vertices.empty()) {
    throw Error("intruder.vertices: only used with shape = \"polygon\", but shape = \"" +
                std::string(choiceName(c.intruder.shape)) + "\" (remove the vertices or set the shape to \"polygon\")");
  }
  if (c.intruder.y0 >= c.box.bedHeight) {
    throw Error("intruder.y0 = " + num(c.intruder.y0) + ": must be < box.bed_height (" +
                num(c.box.bedHeight) + ")");
  }
  lammpsTypeRoles(c.bed.lammpsTypes);  // its syntax, whether bed.file is a LAMMPS data file or not
  if (c.bed.mu != -1.0 && c.bed.mu < 0.0)
    throw Error("bed.mu = " + num(c.bed.mu) + ": must be -1 (the bed of contact.mu) or a friction coefficient >= 0");
  if (c.bed.mu >= 0.0 && !c.bed.file.empty())
    throw Error("bed.mu = " + num(c.bed.mu) +
                ": the bed is bed.file's, poured with whatever friction it was; "
                "set one of the two");
  if (c.bed.swapIntruder && c.bed.file.empty())
    throw Error("bed.swap_intruder = true: it replaces the intruder of bed.file's bed, and bed.file is not set");
  if (c.bed.intruderMass > 0.0 && !c.bed.file.empty())
    throw Error("bed.intruder_mass = " + num(c.bed.intruderMass) +
                ": the bed is bed.file's, poured around whatever intruder mass it was; set one of the two");
  if (c.drive.form == DriveForm::Velocity && c.drive.rampPeriods > 0) {
    throw Error("drive.ramp_periods = " + std::to_string(c.drive.rampPeriods) +
                ": only with drive.form = \"displacement\" (the velocity form starts from rest already)");
  }
}

}  // namespace

std::map<int, LammpsRole> lammpsTypeRoles(const std::string& text) {
  const std::string what = "bed.lammps_types = \"" + text + "\": ";
  std::map<int, LammpsRole> roles;
  std::istringstream in(text);
  for (std::string item; in >> item;) {
    const std::size_t eq = item.find('=');
    const std::string type = item.substr(0, eq == std::string::npos ? item.size() : eq);
    const std::string role = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (type.empty() || type.size() > 9 || type.find_first_not_of("0123456789") != std::string::npos ||
        std::stoi(type) < 1)
      throw Error(what + "\"" + item + "\" is not TYPE=ROLE with TYPE a LAMMPS atom type (1, 2, ...)");
    static const std::map<std::string, LammpsRole> kRoles = {
        {"grain", LammpsRole::Grain}, {"base", LammpsRole::Base}, {"drop", LammpsRole::Drop}};
    const auto r = kRoles.find(role);
    if (r == kRoles.end()) throw Error(what + "\"" + item + "\": the role must be grain, base or drop");
    if (!roles.emplace(std::stoi(type), r->second).second) throw Error(what + "type " + type + " is given twice");
  }
  if (roles.empty()) throw Error(what + "no types given (e.g. \"1=grain 2=base 3=drop\")");
  return roles;
}

namespace {

void requireWholeSteps(const char* key, double interval, double dt, const char* must) {
  if (!wholeStepsIn(interval, dt))
    throw Error(std::string(key) + " = " + num(interval) + ": must be " + must + " run.dt steps (" + num(interval) +
                " / " + num(dt) + " = " + num(interval / dt) + ")");
}

// Every interval falls on a step.
void checkSchedule(const RunConfig& c) {
  requireWholeSteps("drive.period", c.drive.period, c.run.dt, "a whole number of");
  if (c.run.duration < c.run.dt) {
    throw Error("run.duration = " + num(c.run.duration) + ": must be >= run.dt (" + num(c.run.dt) + ")");
  }
  requireWholeSteps("run.duration", c.run.duration, c.run.dt, "a whole number of");
  requireWholeSteps("run.sample_interval", c.run.sampleInterval, c.run.dt, "a whole number of");
  // The rise rate needs three samples (t = 0 and two more); refused here, not after the run.
  if (c.run.duration < 2.0 * c.run.sampleInterval * (1.0 - 1e-12)) {
    throw Error("run.duration = " + num(c.run.duration) + ": shorter than two run.sample_interval (" +
                num(c.run.sampleInterval) + "), too few trajectory samples to measure a rise rate");
  }
  if (c.run.dumpInterval > 0) requireWholeSteps("run.dump_interval", c.run.dumpInterval, c.run.dt, "0 or a whole number of");
}

// Absurd sizes are refused here, before anything is allocated or run: the step counter, the
// trajectory kept in memory and the field sums (one grid of 7 doubles per phase) stay bounded.
void checkSizes(const RunConfig& c) {
  constexpr double kMaxSteps = 1e12, kMaxSamples = 1e8, kMaxFieldBytes = 4e9;
  if (c.run.duration / c.run.dt > kMaxSteps) {
    throw Error("run.duration = " + num(c.run.duration) + ": " + num(c.run.duration / c.run.dt) +
                " time steps of run.dt = " + num(c.run.dt) + ", more than the 1e12 wiggle accepts");
  }
  if (c.run.duration / c.run.sampleInterval > kMaxSamples) {
    throw Error("run.sample_interval = " + num(c.run.sampleInterval) + ": " +
                num(c.run.duration / c.run.sampleInterval) +
                " trajectory samples over run.duration, more than the 1e8 wiggle keeps");
  }
  if (c.fields.enabled) {
    const double side = std::floor(2.0 * c.fields.radius / c.fields.spacing + 1e-9) + 1.0;
    const double bytes = 7.0 * 8.0 * side * side * static_cast<double>(c.fields.phases.size());
    if (bytes > kMaxFieldBytes) {
      throw Error("fields: " + std::to_string(c.fields.phases.size()) + " fields.phases on a grid of " + num(side) +
                  " x " + num(side) + " points (fields.radius / fields.spacing) need " + num(bytes / 1e9) +
                  " GB, more than the 4 GB wiggle accepts");
    }
  }
}

}  // namespace

void validateRunConfig(const RunConfig& c) {
  checkKeyRanges(c);
  checkShapeKeys(c);
  checkSizes(c);  // first: a run too long for any step count gets its own message
  checkSchedule(c);
}

}  // namespace wiggle
