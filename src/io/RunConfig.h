#pragma once
// A run's configuration: one struct per TOML section, one field per key (docs/PHYSICS.md §13). The defaults
// here ARE the embedded default case of `wiggle run` (docs/CONFIG.md lists them with units).
// Parsing, validation, `--set` overrides and writing back to TOML live in io/Config.h.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "physics/ContactLaws.h"
#include "physics/ParticleStore.h"

namespace wiggle {

// The config's enumerated choices besides contact.law and grains.mass_model (physics/): their values'
// names, in the enums' order, are the config's (core/Choice.h).
enum class ShapeName : std::uint8_t { Disk, Square, RectNarrow, RectWide, Triangle, Polygon };  // intruder.shape
enum class MassRule : std::uint8_t { DiskArea, GluedDisk };      // intruder.mass_rule (docs/SHAPES.md, "Mass")
enum class IntruderSurface : std::uint8_t { Smooth, Glued, Lattice };  // intruder.surface (docs/SHAPES.md)
enum class ContactMass : std::uint8_t { Body, Atom };            // intruder.contact_mass (docs/PHYSICS.md §6)
enum class IntruderRotation : std::uint8_t { Locked, Free };     // intruder.rotation (docs/PHYSICS.md §6)
enum class DriveForm : std::uint8_t { Displacement, Velocity };  // drive.form (docs/PHYSICS.md §7)
enum class BedPour : std::uint8_t { Lattice, Random };           // bed.pour (docs/PHYSICS.md §8)
enum class BedCavity : std::uint8_t { Poured, Carved };          // bed.cavity (docs/PHYSICS.md §8)
template <>
struct ChoiceNames<ShapeName> {  // the paper's OS1..OS5 (docs/SHAPES.md), then a user's outline
  static constexpr std::array<std::string_view, 6> names{"disk",      "square",   "rect_narrow",
                                                         "rect_wide", "triangle", "polygon"};
};
template <>
struct ChoiceNames<MassRule> {
  static constexpr std::array<std::string_view, 2> names{"disk_area", "glued_disk"};
};
template <>
struct ChoiceNames<IntruderSurface> {
  static constexpr std::array<std::string_view, 3> names{"smooth", "glued", "lattice"};
};
template <>
struct ChoiceNames<ContactMass> {
  static constexpr std::array<std::string_view, 2> names{"body", "atom"};
};
template <>
struct ChoiceNames<IntruderRotation> {
  static constexpr std::array<std::string_view, 2> names{"locked", "free"};
};
template <>
struct ChoiceNames<DriveForm> {
  static constexpr std::array<std::string_view, 2> names{"displacement", "velocity"};
};
template <>
struct ChoiceNames<BedPour> {
  static constexpr std::array<std::string_view, 2> names{"lattice", "random"};
};
template <>
struct ChoiceNames<BedCavity> {
  static constexpr std::array<std::string_view, 2> names{"poured", "carved"};
};

struct BoxDef {
  double width = 60.0;        // box.width: W, periodic in x, a whole number [d]
  double bedHeight = 50.0;    // box.bed_height: target height of the free surface [d]
  std::uint64_t seed = 1;     // box.seed: seed of the grain diameters and pouring
};

struct GrainsDef {
  double dMin = 0.9;          // grains.d_min [d]
  double dMax = 1.1;          // grains.d_max [d]
  MassModel massModel = MassModel::Sphere;  // grains.mass_model: "sphere" | "disc"
};

struct IntruderDef {
  ShapeName shape = ShapeName::Disk;            // intruder.shape
  std::vector<std::array<double, 2>> vertices;  // intruder.vertices: outline for "polygon" [d]
  double angle = 0.0;          // intruder.angle: rotation, counter-clockwise [degrees]
  double y0 = 25.0;            // intruder.y0: centre height at t = 0 [d]; x0 is the box centre
  double mass = 0.0;           // intruder.mass: 0 means the rule intruder.mass_rule
  MassRule massRule = MassRule::DiskArea;             // intruder.mass_rule
  IntruderSurface surface = IntruderSurface::Smooth;  // intruder.surface
  ContactMass contactMass = ContactMass::Body;        // intruder.contact_mass
  IntruderRotation rotation = IntruderRotation::Locked;  // intruder.rotation
};

struct DriveDef {
  double amplitude = 3.0;      // drive.amplitude: A [d]
  double period = 5.0;         // drive.period: T [sqrt(d/g)]
  std::uint64_t rampPeriods = 0;  // drive.ramp_periods: A grows from 0 over n periods (0: none; docs/PHYSICS.md §7)
  DriveForm form = DriveForm::Displacement;  // drive.form: how A and T make x(t)
};

struct BedDef {
  double batchHeight = 20.0;   // bed.batch_height: height of each poured layer [d]
  BedPour pour = BedPour::Lattice;       // bed.pour: how a batch is placed
  BedCavity cavity = BedCavity::Poured;  // bed.cavity: how the intruder gets its place
  double pourFraction = 0.3;   // bed.pour_fraction: area fraction a random batch fills in its region (pour = random)
  double pourSpeed = 1.0;      // bed.pour_speed: initial downward speed of a random batch (pour = random) [sqrt(g d)]
  double settleSpeed = 0.05;   // bed.settle_speed: pour the next batch when the rms grain speed is below [sqrt(g d)]
  double restEnergy = 1e-6;    // bed.rest_energy: relax until kinetic energy per grain (1-time-unit mean) below [m g d]
  double relaxDamping = 0.0;   // bed.relax_damping: viscous damping rate of the grains while relaxing; 0 = none [sqrt(g/d)]
  double maxTime = 2000.0;     // bed.max_time: give up making the bed after this simulated time
  // bed.mu: the friction coefficient the bed is poured with, when it is not the run's contact.mu
  // (a friction study on one bed per seed); -1 = contact.mu (scenario/bed/BedMaker.h bedMakingConfig).
  double mu = -1.0;
  // bed.intruder_mass: the intruder mass the bed is poured around, when it is not the run's (a mass
  // study on one bed per seed and shape); 0 = the run's (scenario/bed/BedMaker.h bedMakingConfig).
  double intruderMass = 0.0;
  std::string cacheDir;        // bed.cache_dir: where beds are cached ("" = $WIGGLE_CACHE or ~/.cache/wiggle)
  std::string file;            // bed.file: run on the bed in this file instead of the config's own ("" = own)
  bool swapIntruder = false;   // bed.swap_intruder: bed.file's intruder replaced by this config's
  // bed.lammps_types: when bed.file is a LAMMPS data file, the role of each atom type; the default
  // is the types `wiggle export-lammps` writes (and tools/validation/lammps_fix_pour.py pours).
  std::string lammpsTypes = "1=grain 2=base 3=drop";
};

struct RunDef {
  double dt = 1e-4;                // run.dt [sqrt(d/g)]
  double duration = 100.0;         // run.duration: t_total [sqrt(d/g)]
  double sampleInterval = 0.05;    // run.sample_interval: trajectory sampling [sqrt(d/g)]
  double checkpointInterval = 300; // run.checkpoint_interval: wall-clock seconds between checkpoints
  double dumpInterval = 9.7;       // run.dump_interval: LAMMPS dump frames every ... (0 = none) [sqrt(d/g)]
  bool plot = true;                // run.plot: draw the run's figures at the end
  bool keepBedHistory = true;      // run.bed_history: start with the bed's tangential springs (false: unloaded)
  bool profile = false;            // run.profile: time the step's stages (summary.json's step_profile)
};

struct FieldsDef {
  bool enabled = true;                                  // fields.enabled
  std::vector<double> phases = {0, 5, 10, 15, 19};      // fields.phases: 10 phi / pi values
  double radius = 15.0;                                 // fields.radius: half-size of the grid [d]
  double spacing = 0.5;                                 // fields.spacing: grid spacing [d]
  double width = 1.0;                                   // fields.width: Gaussian w [d]
  bool kinetic = false;                                 // fields.kinetic: add the kinetic stress
};

struct EngineDef {
  double skin = 0.2;            // engine.skin: Verlet skin of the grain list [d]
  double intruderSkin = 1.0;    // engine.intruder_skin [d]
  std::uint64_t sortInterval = 2000;  // engine.sort_interval: steps between spatial re-sorts
};

struct RunConfig {
  BoxDef box;
  GrainsDef grains;
  ContactParams contact;
  IntruderDef intruder;
  DriveDef drive;
  BedDef bed;
  RunDef run;
  FieldsDef fields;
  EngineDef engine;
};

}  // namespace wiggle
