#include "io/ConfigKeys.h"

#include <algorithm>

namespace wiggle::config_keys {

std::string chosen(const KeyInfo& k, const RunConfig& c) { return k.getChoice(c); }
void choose(const KeyInfo& k, RunConfig& c, const std::string& v) { k.setChoice(c, v); }

namespace {

KeyInfo number(std::string_view name, double& (*f)(RunConfig&), Bound lo, Bound hi,
               std::string_view unit, std::string_view help) {
  KeyInfo k{name, Kind::Number, unit, help, lo, hi, {}};
  k.number = f;
  return k;
}
KeyInfo integer(std::string_view name, std::uint64_t& (*f)(RunConfig&), Bound lo,
                std::string_view unit, std::string_view help) {
  KeyInfo k{name, Kind::Integer, unit, help, lo, noBound, {}};
  k.integer = f;
  return k;
}
KeyInfo boolean(std::string_view name, bool& (*f)(RunConfig&), std::string_view help) {
  KeyInfo k{name, Kind::Boolean, "", help, noBound, noBound, {}};
  k.boolean = f;
  return k;
}
KeyInfo text(std::string_view name, std::string& (*f)(RunConfig&), std::string_view help) {
  KeyInfo k{name, Kind::Text, "", help, noBound, noBound, {}};
  k.text = f;
  return k;
}
KeyInfo choice(std::string_view name, std::vector<std::string_view> choices,
               std::string (*get)(const RunConfig&), void (*set)(RunConfig&, const std::string&),
               std::string_view help) {
  KeyInfo k{name, Kind::Choice, "", help, noBound, noBound, std::move(choices)};
  k.getChoice = get;
  k.setChoice = set;
  return k;
}
KeyInfo numberList(std::string_view name, std::vector<double>& (*f)(RunConfig&), Bound lo,
                   Bound hi, std::string_view unit, std::string_view help) {
  KeyInfo k{name, Kind::NumberList, unit, help, lo, hi, {}};
  k.numberList = f;
  return k;
}
KeyInfo pointList(std::string_view name, Points& (*f)(RunConfig&), std::string_view unit,
                  std::string_view help) {
  KeyInfo k{name, Kind::PointList, unit, help, noBound, noBound, {}};
  k.pointList = f;
  return k;
}

// A key the bed depends on: a new value makes a new bed (scenario/bed/BedMaker's bed key hashes every
// such key, and no other: BedMakerTest checks the two against each other).
KeyInfo shapesBed(KeyInfo k) {
  k.bed = BedRole::Shapes;
  return k;
}

// contact.law's help: what each law is, as the law types say (physics/ContactLaws.h).
std::string contactLawHelp() {
  std::string help = "the force law of every contact (docs/PHYSICS.md section 4): ";
  for (const ContactLawTraits& law : contactLawList())
    help += (&law == contactLawList().data() ? "" : "; ") + std::string(law.name) + " = " + std::string(law.summary);
  return help;
}

// A stiffness's help, naming its unit under each law whose unit is not the default law's (the key's
// unit column).
std::string stiffnessHelp(std::string_view what) {
  std::string others;
  for (const ContactLawTraits& law : contactLawList())
    if (law.stiffnessUnit != contactLawList().front().stiffnessUnit)
      others += (others.empty() ? "" : "; ") + std::string("contact.law = \"") + std::string(law.name) +
                "\": " + std::string(law.stiffnessUnit);
  return std::string(what) + (others.empty() ? "" : " (with " + others + ")");
}

}  // namespace

using C = RunConfig;

const std::vector<KeyInfo>& keyTable() {
  // The table holds views of its texts: the ones made here live as long as it does.
  static const std::string lawHelp = contactLawHelp();
  static const std::string knHelp = stiffnessHelp("normal stiffness K_n");
  static const std::string ktHelp = stiffnessHelp("tangential stiffness K_t");
  const std::string_view stiffnessUnit = contactLawList().front().stiffnessUnit;
  static const std::vector<KeyInfo> table = {
      // [box]
      shapesBed(number("box.width", [](C& c) -> double& { return c.box.width; }, above(0), noBound, "d",
                       "box width W, periodic in x; a whole number")),
      shapesBed(number("box.bed_height", [](C& c) -> double& { return c.box.bedHeight; }, above(0), noBound,
                       "d", "target height of the bed's free surface")),
      shapesBed(integer("box.seed", [](C& c) -> std::uint64_t& { return c.box.seed; }, atLeast(0), "",
                        "seed of the grain diameters and the pouring (same seed, same bed)")),
      // [grains]
      shapesBed(number("grains.d_min", [](C& c) -> double& { return c.grains.dMin; }, above(0), noBound, "d",
                       "smallest grain diameter (diameters are uniform in [d_min, d_max])")),
      shapesBed(number("grains.d_max", [](C& c) -> double& { return c.grains.dMax; }, above(0), noBound, "d",
                       "largest grain diameter; >= d_min")),
      shapesBed(choice(
                    "grains.mass_model", choiceNameList<MassModel>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.grains.massModel)); },
                    [](C& c, const std::string& v) { c.grains.massModel = *choiceNamed<MassModel>(v); },
                    "grain mass and inertia: sphere m = (4/3) pi r^3, I = (2/5) m r^2; "
                    "disc m = pi r^2, I = (1/2) m r^2")),
      // [contact]
      shapesBed(choice(
                    "contact.law", choiceNameList<ContactLaw>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.contact.law)); },
                    [](C& c, const std::string& v) { c.contact.law = *choiceNamed<ContactLaw>(v); },
                    lawHelp)),
      shapesBed(number("contact.kn", [](C& c) -> double& { return c.contact.kn; }, above(0), noBound,
                       stiffnessUnit, knHelp)),
      shapesBed(number("contact.kt", [](C& c) -> double& { return c.contact.kt; }, above(0), noBound,
                       stiffnessUnit, ktHelp)),
      shapesBed(number("contact.gamma_n", [](C& c) -> double& { return c.contact.gammaN; }, atLeast(0),
                       noBound, "1/(d sqrt(d/g))", "normal viscoelastic damping gamma_n")),
      shapesBed(number("contact.gamma_t", [](C& c) -> double& { return c.contact.gammaT; }, atLeast(0),
                       noBound, "1/(d sqrt(d/g))", "tangential viscoelastic damping gamma_t")),
      shapesBed(number("contact.mu", [](C& c) -> double& { return c.contact.mu; }, atLeast(0), noBound, "",
                       "Coulomb friction coefficient")),
      // [intruder]
      shapesBed(choice(
                    "intruder.shape", choiceNameList<ShapeName>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.intruder.shape)); },
                    [](C& c, const std::string& v) { c.intruder.shape = *choiceNamed<ShapeName>(v); },
                    "outline: the paper's OS1..OS5 (docs/SHAPES.md) or \"polygon\" given by intruder.vertices")),
      shapesBed(pointList("intruder.vertices", [](C& c) -> Points& { return c.intruder.vertices; }, "d",
                          "outer outline for shape = \"polygon\": at least 3 [x, y] pairs; "
                          "empty for the other shapes")),
      shapesBed(number("intruder.angle", [](C& c) -> double& { return c.intruder.angle; }, noBound, noBound,
                       "degrees", "rotation of the outline, counter-clockwise")),
      shapesBed(number("intruder.y0", [](C& c) -> double& { return c.intruder.y0; }, above(0), noBound, "d",
                       "centre height at t = 0 (x0 is the box centre); < box.bed_height")),
      shapesBed(number("intruder.mass", [](C& c) -> double& { return c.intruder.mass; }, atLeast(0), noBound,
                       "rho d^3", "intruder mass; 0 = the one intruder.mass_rule gives")),
      shapesBed(choice(
                    "intruder.mass_rule", choiceNameList<MassRule>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.intruder.massRule)); },
                    [](C& c, const std::string& v) { c.intruder.massRule = *choiceNamed<MassRule>(v); },
                    "the mass when intruder.mass = 0, the same for every shape: disk_area = the disk outline's area x "
                    "the grains' mass per area (docs/PHYSICS.md, section 6); glued_disk = the disk built of touching "
                    "0.5 d spheres at grain density (docs/SHAPES.md)")),
      shapesBed(choice(
                    "intruder.surface", choiceNameList<IntruderSurface>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.intruder.surface)); },
                    [](C& c, const std::string& v) { c.intruder.surface = *choiceNamed<IntruderSurface>(v); },
                    "the clump's atoms: smooth = a shell along the outline, neighbours at most 0.35 d apart; glued = "
                    "the same shell with touching atoms (0.5 d apart), a rough surface like the paper's glued spheres; "
                    "lattice = the outline filled with touching 0.5 d spheres on a square lattice (LAMMPS's lattice "
                    "sq), cut by the outline, so slant faces are staircases (docs/SHAPES.md)")),
      shapesBed(choice(
                    "intruder.contact_mass", choiceNameList<ContactMass>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.intruder.contactMass)); },
                    [](C& c, const std::string& v) { c.intruder.contactMass = *choiceNamed<ContactMass>(v); },
                    "the intruder's mass in the damping of its contacts (meff = m M' / (m + M')): body = M' the whole "
                    "mass (LAMMPS's fix rigid); atom = M' the mass of one of the n glued 0.5 d spheres that fill its "
                    "outline, M / n (LAMMPS's fix move with the atoms' own masses; docs/PHYSICS.md, section 6). The "
                    "body moves with M either way")),
      choice("intruder.rotation", choiceNameList<IntruderRotation>(),
             [](const C& c) -> std::string { return std::string(choiceName(c.intruder.rotation)); },
             [](C& c, const std::string& v) { c.intruder.rotation = *choiceNamed<IntruderRotation>(v); },
             "locked = the intruder never turns (the paper's model); free = it turns about its centre under the "
             "contact torques while it is driven, with the moment of inertia of the glued spheres it is built of "
             "(docs/PHYSICS.md, section 6); held still while the bed is made either way"),
      // [drive]
      number("drive.amplitude", [](C& c) -> double& { return c.drive.amplitude; }, atLeast(0),
             noBound, "d",
             "A in x(t) = x0 + A sin(2 pi t / T); with drive.form = \"velocity\" a speed [sqrt(g d)]: "
             "vx(t) = A sin(2 pi t / T)"),
      number("drive.period", [](C& c) -> double& { return c.drive.period; }, above(0), noBound,
             "sqrt(d/g)", "T in x(t) = x0 + A sin(2 pi t / T); a whole number of run.dt steps"),
      integer("drive.ramp_periods", [](C& c) -> std::uint64_t& { return c.drive.rampPeriods; }, atLeast(0), "",
              "periods over which the amplitude grows linearly from 0 to A, so the drive starts from rest "
              "(0 = no ramp: x0 + A sin(2 pi t / T) from t = 0, at full speed; docs/PHYSICS.md, section 7)"),
      choice(
          "drive.form", choiceNameList<DriveForm>(),
          [](const C& c) -> std::string { return std::string(choiceName(c.drive.form)); },
          [](C& c, const std::string& v) { c.drive.form = *choiceNamed<DriveForm>(v); },
          "how the paper's drive is read (docs/PHYSICS.md, section 7): displacement = x(t) = x0 + A sin(2 pi t / T); "
          "velocity = vx(t) = A sin(2 pi t / T), the paper's formula read as a velocity: x(t) = x0 + (A T / 2 pi)"
          "(1 - cos(2 pi t / T)), from rest, swinging A T / pi to one side"),
      // [bed]
      shapesBed(number("bed.mu", [](C& c) -> double& { return c.bed.mu; }, atLeast(-1), noBound, "",
                       "the friction coefficient the bed is poured with, when it is not the run's contact.mu: the "
                       "bed of that friction, run with contact.mu (a friction study on the same beds); -1 = "
                       "contact.mu")),
      shapesBed(number("bed.intruder_mass", [](C& c) -> double& { return c.bed.intruderMass; }, atLeast(0),
                       noBound, "rho d^3",
                       "the intruder mass the bed is poured around, when it is not the run's: the bed of that "
                       "mass, run with the run's intruder mass (a mass study on the same beds); 0 = the run's")),
      shapesBed(number("bed.batch_height", [](C& c) -> double& { return c.bed.batchHeight; }, above(0),
                       noBound, "d", "height of each poured layer")),
      shapesBed(choice(
                    "bed.pour", choiceNameList<BedPour>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.bed.pour)); },
                    [](C& c, const std::string& v) { c.bed.pour = *choiceNamed<BedPour>(v); },
                    "how each batch is placed (docs/PHYSICS.md, section 8): lattice = a loose lattice with small random "
                    "velocities; random = grains at random non-overlapping positions, as LAMMPS's fix pour")),
      shapesBed(choice(
                    "bed.cavity", choiceNameList<BedCavity>(),
                    [](const C& c) -> std::string { return std::string(choiceName(c.bed.cavity)); },
                    [](C& c, const std::string& v) { c.bed.cavity = *choiceNamed<BedCavity>(v); },
                    "how the intruder gets its place in the bed (docs/PHYSICS.md, section 8): poured = the grains are poured "
                    "around the held intruder; carved = the seed's bed is poured once without an intruder (shared by every "
                    "shape and y0), the grains the intruder overlaps are removed and the bed relaxes to rest around it")),
      shapesBed(number("bed.pour_fraction", [](C& c) -> double& { return c.bed.pourFraction; }, above(0), atMost(0.6),
                       "", "pour = \"random\" only: area fraction of grains a batch fills in its insertion region "
                       "(box.width x bed.batch_height, one d_max above the highest grain; fix pour's vol)")),
      shapesBed(number("bed.pour_speed", [](C& c) -> double& { return c.bed.pourSpeed; }, atLeast(0), noBound,
                       "sqrt(g d)", "pour = \"random\" only: downward speed at the top of the insertion region; a grain "
                       "lower in it starts as if it had fallen from there (fix pour's vel; vx = 0)")),
      shapesBed(number("bed.settle_speed", [](C& c) -> double& { return c.bed.settleSpeed; }, above(0),
                       noBound, "sqrt(g d)", "the next batch is poured when the rms grain speed is below this")),
      shapesBed(number("bed.rest_energy", [](C& c) -> double& { return c.bed.restEnergy; }, above(0), noBound,
                       "m g d", "final relaxation ends when the kinetic energy per grain, averaged over one time unit, is below this")),
      shapesBed(number("bed.relax_damping", [](C& c) -> double& { return c.bed.relaxDamping; }, atLeast(0), atMost(100),
                       "sqrt(g/d)", "while the levelled bed relaxes, its grains' velocities decay as exp(-rate t) besides the "
                       "contacts' own damping (applied every 1000 steps), so it comes to rest sooner; 0 = off")),
      number("bed.max_time", [](C& c) -> double& { return c.bed.maxTime; }, above(0), noBound,
             "sqrt(d/g)", "give up making the bed after this much simulated time"),
      text("bed.file", [](C& c) -> std::string& { return c.bed.file; },
           "run on the bed in this file (a cached bed-KEY.bin) instead of the config's own, e.g. one bed for a whole "
           "friction or time-step study; it must have this box width, mass model and intruder (clump, mass, y0); "
           "contact, run.dt and engine keys are this config's (\"\" = the config's own bed). Or a LAMMPS data file "
           "(atom_style sphere, as write_data and wiggle export-lammps write it; bed.lammps_types): its grains and base "
           "with this config's intruder at the box centre and intruder.y0, no contact history (docs/PHYSICS.md, "
           "section 8)"),
      boolean("bed.swap_intruder", [](C& c) -> bool& { return c.bed.swapIntruder; },
              "with bed.file a wiggle bed: its intruder's atoms replaced by this config's, held where the file's was "
              "(the same intruder.y0), the contacts with the old atoms forgotten, e.g. another surface of the same "
              "outline on the same bed; refused when a grain overlaps the new atoms by more than 0.1 d"),
      text("bed.lammps_types", [](C& c) -> std::string& { return c.bed.lammpsTypes; },
           "when bed.file is a LAMMPS data file: what each atom type is, as TYPE=ROLE items (grain = a grain, "
           "base = a frozen base particle, drop = left out: the intruder's atoms, replaced by this config's "
           "intruder); a type not listed is refused. The default is the types wiggle export-lammps writes"),
      text("bed.cache_dir", [](C& c) -> std::string& { return c.bed.cacheDir; },
           "directory of cached beds (\"\" = $WIGGLE_CACHE or ~/.cache/wiggle)"),
      // [run]
      shapesBed(number("run.dt", [](C& c) -> double& { return c.run.dt; }, above(0), noBound, "sqrt(d/g)",
                       "time step")),
      number("run.duration", [](C& c) -> double& { return c.run.duration; }, above(0), noBound,
             "sqrt(d/g)", "simulated time t_total of the run; >= run.dt and >= 2 x run.sample_interval"),
      number("run.sample_interval", [](C& c) -> double& { return c.run.sampleInterval; }, above(0),
             noBound, "sqrt(d/g)", "trajectory sampling interval; a whole number of run.dt steps"),
      number("run.checkpoint_interval", [](C& c) -> double& { return c.run.checkpointInterval; },
             above(0), noBound, "s", "wall-clock time between checkpoints (of the run, and of a bed being made)"),
      number("run.dump_interval", [](C& c) -> double& { return c.run.dumpInterval; }, atLeast(0),
             noBound, "sqrt(d/g)",
             "interval of LAMMPS text dump frames (0 = none); a whole number of run.dt steps. The default 9.7 "
             "is no whole number of any period from 0.25 to 8, so the frames catch the drive at different "
             "phases (a multiple of T would show the intruder at the same place in every frame)"),
      boolean("run.plot", [](C& c) -> bool& { return c.run.plot; },
              "draw the run's figures at the end"),
      boolean("run.bed_history", [](C& c) -> bool& { return c.run.keepBedHistory; },
              "start from the bed's contact history (false: every tangential spring unloaded, as an exported "
              "LAMMPS deck starts; for comparisons with LAMMPS)"),
      boolean("run.profile", [](C& c) -> bool& { return c.run.profile; },
              "time each stage of the step, and each thread's work and wait in its parallel regions: "
              "summary.json's step_profile (docs/PERFORMANCE.md, \"The step's profile\"); the same bits, and "
              "a clock read per stage per step"),
      // [fields]
      boolean("fields.enabled", [](C& c) -> bool& { return c.fields.enabled; },
              "measure the coarse-grained fields (area fraction, velocity, stress)"),
      numberList("fields.phases", [](C& c) -> std::vector<double>& { return c.fields.phases; },
                 atLeast(0), below(20), "10 phi / pi",
                 "drive phases at which fields are averaged, each in [0, 20)"),
      number("fields.radius", [](C& c) -> double& { return c.fields.radius; }, above(0), noBound,
             "d", "half-size of the field grid around the intruder centre"),
      number("fields.spacing", [](C& c) -> double& { return c.fields.spacing; }, above(0), noBound,
             "d", "field grid spacing"),
      number("fields.width", [](C& c) -> double& { return c.fields.width; }, above(0), noBound, "d",
             "width w of the Gaussian coarse-graining function"),
      boolean("fields.kinetic", [](C& c) -> bool& { return c.fields.kinetic; },
              "add the kinetic stress to the contact stress"),
      // [engine]
      shapesBed(number("engine.skin", [](C& c) -> double& { return c.engine.skin; }, above(0), noBound, "d",
                       "Verlet skin of the grain neighbour list")),
      shapesBed(number("engine.intruder_skin", [](C& c) -> double& { return c.engine.intruderSkin; },
                       above(0), noBound, "d", "Verlet skin of the intruder's neighbour list")),
      shapesBed(integer("engine.sort_interval", [](C& c) -> std::uint64_t& { return c.engine.sortInterval; },
                        atLeast(1), "steps", "steps between spatial re-sorts of the grains")),
  };
  return table;
}

const KeyInfo* findKey(std::string_view key) {
  for (const KeyInfo& k : keyTable()) {
    if (k.name == key) return &k;
  }
  return nullptr;
}

std::vector<std::string_view> sectionNames() {
  std::vector<std::string_view> out;
  for (const KeyInfo& k : keyTable()) {
    if (std::find(out.begin(), out.end(), k.section()) == out.end()) out.push_back(k.section());
  }
  return out;
}

bool isSection(std::string_view name) {
  const auto s = sectionNames();
  return std::find(s.begin(), s.end(), name) != s.end();
}

}  // namespace wiggle::config_keys
