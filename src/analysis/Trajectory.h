#pragma once
// The intruder's sampled trajectory and its file, trajectory.csv (docs/OUTPUT-FORMATS.md): written
// by a run, read back by `wiggle rate` to measure V_y over any window after the fact.
#include <string>
#include <vector>

namespace wiggle {

struct TrajectorySample {
  double t, x, y, vx, vy, fy;  // time, intruder centre, velocity, vertical contact force
};

// Columns t,x,y,vx,vy,fy with 10 significant digits (a round trip to about 1e-10), written atomically.
void writeTrajectoryCsv(const std::string& path, const std::vector<TrajectorySample>& samples);

// Reads a file written by writeTrajectoryCsv. Throws wiggle::Error naming the file and line when the
// header, a cell or the order of times is not what a run writes.
std::vector<TrajectorySample> readTrajectoryCsv(const std::string& path);

}  // namespace wiggle
