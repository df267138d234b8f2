#pragma once
// The few MPI calls the sweep needs, behind a small interface so that nothing else includes
// <mpi.h> and a build without MPI (WIGGLE_HAVE_MPI undefined) still compiles and runs locally.
//
// Protocol (rank 0 coordinates; every rank expands the same sweep file, so tasks travel as one
// integer, SweepTask::encode):
//   worker -> 0  Request  "<pid> <host>"    it has a free slot (at most one request outstanding)
//   worker -> 0  Result   TaskOutcome JSON  a task it ran has ended
//   0 -> worker  Task     the encoded task
//   0 -> worker  Stop     no more work: finish what runs, report, leave
//   0 -> worker  Round    (`wiggle boundary`, between its rounds) a round's sweep file is written:
//                         read it and serve that sweep; a Stop between rounds ends the study
// Rank 0 polls with MPI_Iprobe and sleeps between polls: Open MPI's blocking receive spins, and the
// coordinator would otherwise take a whole core from the cases.
#include <optional>
#include <string>

namespace wiggle {

enum class MpiTag : int { Request = 1, Result = 2, Task = 3, Stop = 4, Round = 5 };

struct MpiMessage {
  int source = 0;
  MpiTag tag = MpiTag::Request;
  std::string text;
};

class MpiQueue {
 public:
  // True when this process was started by an MPI launcher (mpirun/mpiexec of Open MPI or MPICH,
  // srun with PMI/PMIx) for a job of more than one process: it reads the launcher's environment
  // variables only, so it is safe to call before deciding to initialise MPI.
  static bool launchedAsMultipleProcesses();
  // This process's rank as its launcher numbered it (from the same variables), 0 when none did: what
  // runs before MPI starts (a dry run) prints from rank 0 only.
  static int launcherRank();
  // Whether this binary was built with MPI.
  static bool available();

  MpiQueue();   // MPI_Init; throws wiggle::Error when built without MPI
  ~MpiQueue();  // MPI_Finalize
  MpiQueue(const MpiQueue&) = delete;
  MpiQueue& operator=(const MpiQueue&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  void send(int destination, MpiTag tag, const std::string& text);
  // A waiting message from any rank, or nothing (non-blocking).
  std::optional<MpiMessage> poll();
  // Ends every process of the job (a rank that cannot go on).
  [[noreturn]] void abort(int code);

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace wiggle
