// trajectory.csv (docs/OUTPUT-FORMATS.md): its columns, with and without the intruder's turn, read back.
#include "analysis/Trajectory.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

const std::vector<TrajectorySample> kSamples = {{0.0, 30.0, 10.0, 0.0, 0.0, 12.5}, {0.05, 30.5, 10.01, 1.5, 0.2, 11.0}};

TEST(Trajectory, ATurningIntruderAddsItsAngleAndSpinAndReadsBackTheSame) {
  const testing_support::ScratchDir dir("trajectory-test");
  const std::string locked = dir / "locked.csv", turning = dir / "turning.csv";
  writeTrajectoryCsv(locked, kSamples);
  writeTrajectoryCsv(turning, kSamples, {{0.0, 0.0}, {-0.25, 1.75}});
  const std::string text = readFile(turning);
  EXPECT_EQ(readFile(locked).substr(0, readFile(locked).find('\n')), "t,x,y,vx,vy,fy");
  EXPECT_EQ(text.substr(0, text.find('\n')), "t,x,y,vx,vy,fy,angle,omega");
  EXPECT_NE(text.find("\n0.05,30.5,10.01,1.5,0.2,11,-0.25,1.75\n"), std::string::npos) << text;
  for (const std::string& path : {locked, turning}) {
    const std::vector<TrajectorySample> back = readTrajectoryCsv(path);
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[1].t, 0.05);
    EXPECT_EQ(back[1].y, 10.01);
    EXPECT_EQ(back[1].fy, 11.0);
  }
  // A turn for some samples only is refused, not written as a column with holes.
  EXPECT_THROW(writeTrajectoryCsv(dir / "holes.csv", kSamples, {{0.0, 0.0}}), Error);
}

TEST(Trajectory, AFileThatIsNotATrajectoryIsNamedByItsLine) {
  const testing_support::ScratchDir dir("trajectory-test-bad");
  const std::string wrongHeader = dir / "a.csv", shortLine = dir / "b.csv", glued = dir / "c.csv";
  std::ofstream(wrongHeader) << "t,x,y,vx,vy,fyz\n0,1,2,3,4,5\n";
  std::ofstream(shortLine) << "t,x,y,vx,vy,fy,angle,omega\n0,1,2,3,4,5,6,7\n0.1,1,2,3,4\n";
  std::ofstream(glued) << "t,x,y,vx,vy,fy\n0,1,2,3,4,5x\n";
  EXPECT_NE(testing_support::errorOf([&] { readTrajectoryCsv(wrongHeader); }).find("not a trajectory.csv"),
            std::string::npos);
  EXPECT_NE(testing_support::errorOf([&] { readTrajectoryCsv(shortLine); }).find("b.csv: line 3"), std::string::npos);
  EXPECT_NE(testing_support::errorOf([&] { readTrajectoryCsv(glued); }).find("c.csv: line 2"), std::string::npos);
}

}  // namespace
}  // namespace wiggle
