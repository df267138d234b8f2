// What MpiQueue decides before MPI is started (sweep/MpiQueue.h): whether a launcher started this
// process as one of several, read from each launcher's environment variable, and a build without MPI
// refusing to start it. The messages themselves travel in the `mpi` test (two ranks).
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/Error.h"
#include "sweep/MpiQueue.h"

namespace wiggle {
namespace {

constexpr const char* kLauncherVariables[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"};
constexpr const char* kRankVariables[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID"};

void clearLauncherVariables() {
  for (const char* name : kLauncherVariables) ::unsetenv(name);
  for (const char* name : kRankVariables) ::unsetenv(name);
}

TEST(MpiQueue, ALauncherOfMoreThanOneProcessIsRecognisedByItsVariable) {
  clearLauncherVariables();
  EXPECT_FALSE(MpiQueue::launchedAsMultipleProcesses());
  for (const char* name : kLauncherVariables) {
    clearLauncherVariables();
    ::setenv(name, "1", 1);  // a job of one process is not a sweep over ranks
    EXPECT_FALSE(MpiQueue::launchedAsMultipleProcesses()) << name;
    ::setenv(name, "4", 1);
    EXPECT_TRUE(MpiQueue::launchedAsMultipleProcesses()) << name;
  }
  clearLauncherVariables();
}

TEST(MpiQueue, TheLaunchersRankIsReadOnlyUnderALauncherOfSeveral) {
  clearLauncherVariables();
  EXPECT_EQ(MpiQueue::launcherRank(), 0);
  for (const char* name : kRankVariables) {
    clearLauncherVariables();
    ::setenv(name, "2", 1);
    EXPECT_EQ(MpiQueue::launcherRank(), 0) << name << " alone (a Slurm job step of one task sets SLURM_PROCID too)";
    ::setenv("PMI_SIZE", "3", 1);
    EXPECT_EQ(MpiQueue::launcherRank(), 2) << name;
  }
  clearLauncherVariables();
}

TEST(MpiQueue, ABuildWithoutMpiRefusesToStartIt) {
#ifdef WIGGLE_HAVE_MPI
  EXPECT_TRUE(MpiQueue::available());
#else
  EXPECT_FALSE(MpiQueue::available());
  EXPECT_THROW(MpiQueue{}, Error);
#endif
}

}  // namespace
}  // namespace wiggle
