#pragma once
// The DEM engine: grains, a frozen base, an optional rigid intruder, and the step pipeline
// (ARCHITECTURE.md lists the stages). World owns all simulation state; observers read it through
// const accessors and never change it.
//
// Determinism: every force is a sum over a particle's contacts in the fixed order of the
// neighbour list, never an order that depends on threads, so results are bitwise identical for
// any thread count and across save/load.
#include <cstdint>
#include <string>
#include <vector>

#include "core/BinaryStream.h"
#include "physics/ContactLaws.h"
#include "physics/ForceKernels.h"
#include "physics/Intruder.h"
#include "physics/NeighbourList.h"
#include "physics/PairKernel.h"
#include "physics/ParticleStore.h"
#include "physics/StepProfile.h"
#include "physics/ThreadGovernor.h"

namespace wiggle {

struct PairOverlap;  // a pair's overlap against the health scan's bound (WorldChecks.cpp)

struct WorldDef {
  double boxWidth = 0.0;     // W: the box is periodic in x over [0, W) [d]
  double dt = 1e-4;          // time step [sqrt(d/g)]
  double gravity = 1.0;      // acceleration along -y [g]
  double density = 1.0;      // material density rho
  MassModel massModel = MassModel::Sphere;
  ContactParams contact;
  double skin = 0.2;          // Verlet skin of the grain list [d]
  double intruderSkin = 1.0;  // skin of the intruder-grain list [d]; larger, as the intruder is fast
  std::uint64_t sortInterval = 2000;   // steps between spatial re-sorts of the grains (at a rebuild)
  // The blow-up detector (docs/RELIABILITY.md, "The blow-up detector"): when to stop, never physics.
  std::uint64_t healthInterval = 100;  // steps between full scans (deep overlaps are also caught every step)
  double maxOverlapRatio = 1.0;        // blow-up: an overlap beyond this fraction of the radius of the grain that
                                       // reaches in (the smaller one of two grains); at 1 its centre is at the
                                       // other's surface or the intruder's outline
  double referenceImpactSpeed = 1.0;   // the fastest a grain moves without the drive (a fall from the top of the
                                       // pour) [sqrt(g d)]: the time-step check and the speed bound use it
  double maxSpeedFactor = 10.0;        // blow-up: a grain faster than this x max(referenceImpactSpeed, drive's peak)
  double minStepsPerContact = 5.0;     // refuse dt above (the law's contactTime, ContactLaws.h) / this
};

// What the blow-up detector has seen so far, at its full scans: the deepest overlap as a fraction of
// its bound and the fastest grain as a fraction of the speed bound (both 1 at a blow-up). Kept across
// save/load, so that a resumed run reports the same margins as an uninterrupted one.
struct HealthMargins {
  double overlap = 0.0;
  double speed = 0.0;
};

// Thrown when the simulation blows up; the message names the step, the particle and the quantity.
class SimulationError : public Error {
 public:
  using Error::Error;
};

// The intruder's pair forces (in its pair slots, ForceKernels::intruderPairForces) added to its
// grains (base particles get none) and summed into the clump's contact force, in list order.
void addIntruderPairForces(ParticleStore& s, ClumpState& state, const IntruderPairs& pairs);

// The intruder's part of the step's ContactForces and IntruderSums stages (ARCHITECTURE.md) alone:
// its pair forces in the default force kernels, then addIntruderPairForces; for the micro-benchmarks.
double addIntruderContactForces(ParticleStore& s, const ClumpDef& clump, ClumpState& state, IntruderPairs& pairs,
                                ContactParams params, double dt, double width, bool updateShear,
                                double overlapRatio);

class World {
 public:
  explicit World(const WorldDef& def);

  // --- set-up (throws wiggle::Error on bad input) ---
  std::uint32_t addGrain(double x, double y, double radius, double vx = 0.0, double vy = 0.0,
                         double omega = 0.0);
  void addFrozen(double x, double y, double radius);
  void setIntruder(const ClumpDef& clump, double x, double y);
  void setIntruderMotion(const ClumpMotion& motion);
  // For a bed read from a file that names its particles (a LAMMPS data file's atom ids): `tags` (one
  // per particle, in store order, unique) become the particles' ids, and the particles keep the
  // order they were added in until the first scheduled re-sort, as the bed the file was written from
  // keeps its own (a new world otherwise re-sorts at its first list build). So a bed written out and
  // read back runs to the same bits as the bed itself. Call it after the last add.
  void adoptParticleIds(const std::vector<std::uint32_t>& tags);
  // Removes the grains whose index is flagged; contact history of the others is kept.
  void removeGrains(const std::vector<bool>& remove);
  // Time and step count back to zero: t = 0 of the drive. Forces are recomputed at the next step.
  void resetClock();
  // Every contact's tangential spring unloaded (the history a LAMMPS data file cannot carry).
  void clearContactHistory();
  // New engine parameters for the same particles (a bed made with other contact constants, time step
  // or engine settings, run with these): the box width, mass model and density must be the ones
  // the particles were made with. The lists are rebuilt and the forces evaluated afresh.
  void setParameters(const WorldDef& def);
  // Another mass for the same intruder atoms (a bed poured around a held intruder of one mass, or
  // with one contact mass, run with another: ClumpDef::mass, massShares and inertia); the forces are
  // evaluated afresh, since the mass enters the contacts' meff.
  void setIntruderMass(double mass, std::uint32_t massShares, double inertia);
  // The turning clump's angular velocity now [sqrt(g/d)] (a spin given before its first step).
  void setIntruderSpin(double omega);
  // Every grain's velocity and spin multiplied by `factor` (bed making's damped relaxation); the
  // forces are evaluated afresh before the next step, as after any change of the state.
  void scaleGrainVelocities(double factor);
  // The force kernels' instruction set (ForceKernels.h; default: the widest the CPU runs). Every
  // level gives the same bits; only the speed differs. Throws if the CPU lacks it.
  void useSimdLevel(SimdLevel level) { kernels_ = &forceKernels(level, def_.contact.law); }
  // The step's profile (physics/StepProfile.h): on from zero, or off. Not saved, never in the hash:
  // it reads clocks only.
  void enableStepProfile(bool on = true);
  const StepProfile& stepProfile() const { return profile_; }
  // How many of the run's threads (omp_get_max_threads(), the ceiling) each step uses: shed while
  // another process holds a core (physics/ThreadGovernor.h). Not saved, never in the hash.
  ThreadGovernor& threadGovernor() { return governor_; }
  const ThreadGovernor& threadGovernor() const { return governor_; }
  // The force stage's load imbalance at `threads` threads on the current list: the heaviest
  // thread's pairs over the mean (NeighbourList::stripImbalance, the intruder's pairs on the first
  // thread). A prediction for any thread count, whatever this machine has.
  double stripImbalance(std::uint32_t threads) const;

  // --- stepping ---
  void step();
  void run(std::uint64_t steps);
  // run(steps), calling afterEach(intruder, step count, time) after every step. Between two steps
  // of a run the grains may already be half a step into the next one (World::advance), so the
  // callback gets only what is whole after every step: the intruder's state, the step and time.
  template <class AfterEach>
  void runWatchingIntruder(std::uint64_t steps, AfterEach&& afterEach) {
    for (std::uint64_t s = 0; s < steps; ++s) {
      advance(s + 1 < steps);
      afterEach(static_cast<const ClumpState&>(clumpState_), step_, time());
    }
  }
  // The forces of the current state, evaluated now if a change since the last step left them stale
  // (set-up, resetClock, setParameters, ...), exactly as the next step would first do itself: so
  // calling it changes no result. For observers that read forces before the first step (the dump's
  // frame at step 0). Pair forces are not saved (World::save): after load they are zero until the
  // next step, while the grains' totals (fx, fy, torque) are the saved step's.
  void evaluateForces() {
    if (!prepared_) prepare();
  }

  // --- state (read-only) ---
  const WorldDef& def() const { return def_; }
  const ParticleStore& particles() const { return store_; }
  std::uint32_t grainCount() const { return store_.grainCount; }
  bool hasIntruder() const { return hasIntruder_; }
  const ClumpDef& clump() const { return clump_; }
  const ClumpState& intruder() const { return clumpState_; }
  const ClumpSpin& intruderSpin() const { return spin_; }  // its turn, when it may turn
  const ClumpMotion& intruderMotion() const { return motion_; }
  std::uint64_t stepCount() const { return step_; }
  double time() const { return static_cast<double>(step_) * def_.dt; }
  std::uint64_t rebuildCount() const { return rebuilds_; }
  const NeighbourList& neighbours() const { return list_; }
  const IntruderPairs& intruderPairs() const { return intruderPairs_; }
  const ForceKernels& kernels() const { return *kernels_; }
  double kineticEnergy() const;   // translational + rotational, grains only
  // Listed grain pairs that overlap now: the pairs whose contact force the last step evaluated as
  // non-zero. From the positions, not from the pair forces, so that it holds after a load too
  // (pair forces are not saved).
  std::uint64_t touchingPairs() const;
  const HealthMargins& healthMargins() const { return margins_; }
  double peakDriveSpeed() const;  // largest |vx| the intruder's prescribed motion reaches [sqrt(g d)]
  double speedBound() const;      // a grain faster than this is a blow-up [sqrt(g d)]
  // Bytes of the simulation state's arrays, by their lengths (deterministic, unlike their
  // allocations, which differ after a load).
  std::size_t stateBytes() const;
  std::string stateHash() const;  // hash of the bits of the whole dynamic state

  // --- persistence: the full state, so that a loaded world continues bit for bit ---
  void save(BinaryWriter& out) const;
  static World load(BinaryReader& in);

 private:
  void prepare();                 // first force evaluation (history not advanced), as LAMMPS's setup
  void advance(bool startNextStep);  // one step; see World.cpp
  void startGrains();             // every grain's first half kick and drift; tracks max displacement
  // What a pass over the grains does to each, in this order: the cross pairs' forces and gravity
  // (finishForces), the step's second half kick (kick), the next step's first half kick and drift
  // (start), then recording the new kinematics and the squared displacement since the last list
  // build (track, with start; not when the structure changed and the indices moved: the rebuild
  // that follows in the step refreshes both). Returns the largest such displacement when it tracks,
  // else 0.
  struct GrainPass {
    bool finishForces = false, kick = false, start = false, track = false;
  };
  double passOverGrains(GrainPass pass);
  void kickIntruder();            // the free intruder's half kick in y
  void kickIntruderSpin();        // the turning intruder's half kick of its angular velocity
  void turnIntruder();            // its atoms' offsets at its angle
  void startIntruder();           // the intruder's first half kick and drift in y, when it is free
  void placeIntruder();           // prescribed x, vx at the current time
  void rebuildNeighbours();       // wrap, maybe re-sort, rebuild both lists carrying history
  void rebuildIntruderPairs(const std::vector<std::uint32_t>& newToOld);
  bool intruderPairsStale() const;
  std::uint32_t firstThreadPairs() const;  // the intruder's pairs, which the first thread evaluates
  void computeContactForces(bool updateShear);  // contacts only: grains' sums are completed by...
  // ...cross pairs and gravity, then the second half kick; with startNextStep also the next step's
  // first half kick and drift of the grains.
  void completeForces(bool kick, bool startNextStep = false);
  void refreshKinematics();       // every particle's Kinematics record from the store
  void checkHealth();
  void checkHealthInOrder() const;  // after a failed checkHealth: throws for the first offender
  PairOverlap grainPairOverlap(std::uint32_t k) const;     // list pair k, for the health scans
  PairOverlap intruderPairOverlap(std::uint32_t p) const;  // intruder pair p, for the health scans
  void checkTimeStep() const;
  void invalidate();              // structure changed: rebuild and re-prepare before the next step

  WorldDef def_;
  const ForceKernels* kernels_;
  ParticleStore store_;
  std::vector<Kinematics> kinematics_;  // mirror of the store's x, y, vx, vy
  NeighbourList list_;
  NeighbourList spareList_;  // the list before the last rebuild: the next one is built into its memory
  IntruderPairs intruderPairs_;
  bool hasIntruder_ = false;
  ClumpDef clump_;
  ClumpState clumpState_;
  ClumpMotion motion_;
  // A turning clump (motion_.rotationFree): its turn, and its atoms' offsets at angle 0 (clump_'s
  // offsets are those at spin_.angle, which every reader of the atoms sees).
  ClumpSpin spin_;
  std::vector<double> bodyOffsetX_, bodyOffsetY_;

  std::uint64_t step_ = 0;
  std::uint64_t rebuilds_ = 0;
  std::uint64_t lastSortStep_ = 0;
  std::uint32_t nextTag_ = 0;
  // adoptParticleIds: no re-sort at the first list build. Not saved (World::save): a run builds its
  // lists at t = 0, before its first checkpoint, and a saved world that has built them never re-sorts
  // at its first build after loading anyway (rebuilds_ > 0).
  bool keepOrderAtFirstBuild_ = false;
  bool prepared_ = false;
  bool listsStale_ = true;
  bool grainsStarted_ = false;  // inside run(): this step's first half kick and drift are done already
  bool overlapAlarm_ = false;  // the last force evaluation saw an overlap beyond the detector's bound
  HealthMargins margins_;
  StepProfile profile_;  // off unless enableStepProfile
  ThreadGovernor governor_;
  // Neighbour-list validity: positions at the last build, the largest squared displacement since.
  std::vector<double> xAtBuild_, yAtBuild_;
  double maxDisplacementSq_ = 0.0;
  // Intruder list validity: clump position at its build and the grains' displacement bound then.
  double clumpXAtBuild_ = 0.0, clumpYAtBuild_ = 0.0, grainDisplacementAtIntruderBuild_ = 0.0;
  double clumpAngleAtBuild_ = 0.0;  // a turning clump's angle then
  // Old-index map for structural changes between prepare() calls (identity when empty).
  std::vector<std::uint32_t> pendingNewToOld_;
};

}  // namespace wiggle
