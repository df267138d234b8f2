#pragma once
// The intruder's sampled trajectory and its file, trajectory.csv (docs/OUTPUT-FORMATS.md): written
// by a run, read back by `wiggle rate` to measure V_y over any window after the fact.
#include <string>
#include <vector>

namespace wiggle {

struct TrajectorySample {
  double t, x, y, vx, vy, fy;  // time, intruder centre, velocity, vertical contact force
};

// The turn of an intruder that may turn (intruder.rotation = "free") at a sample.
struct SpinSample {
  double angle, omega;  // turned since t = 0, counter-clockwise [rad]; angular velocity [sqrt(g/d)]
};

// Columns t,x,y,vx,vy,fy, then angle,omega when `spins` holds one per sample, with 10 significant
// digits (a round trip to about 1e-10), written atomically.
void writeTrajectoryCsv(const std::string& path, const std::vector<TrajectorySample>& samples,
                        const std::vector<SpinSample>& spins = {});

// Reads the six columns of a file written by writeTrajectoryCsv (columns after them are not read).
// Throws wiggle::Error naming the file and line when the header, a cell or the order of times is not
// what a run writes.
std::vector<TrajectorySample> readTrajectoryCsv(const std::string& path);

}  // namespace wiggle
