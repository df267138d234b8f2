#include "sweep/MpiQueue.h"

#include <cstdlib>
#include <string_view>

#include "core/Error.h"

#ifdef WIGGLE_HAVE_MPI
// The C API only: the deprecated C++ bindings in Open MPI's header do not compile warning-free.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace wiggle {

bool MpiQueue::launchedAsMultipleProcesses() {
  // Open MPI, MPICH/Hydra and Slurm's PMI-2 / PMIx each publish the job size.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"}) {
    if (const char* v = std::getenv(name); v && std::atoi(v) > 1) return true;
  }
  return false;
}

int MpiQueue::launcherRank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID"}) {
    if (const char* v = std::getenv(name); v && launchedAsMultipleProcesses()) return std::atoi(v);
  }
  return 0;
}

#ifdef WIGGLE_HAVE_MPI

bool MpiQueue::available() { return true; }

MpiQueue::MpiQueue() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised && MPI_Init(nullptr, nullptr) != MPI_SUCCESS) throw Error("sweep: MPI_Init failed");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiQueue::~MpiQueue() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (!finalised) MPI_Finalize();
}

void MpiQueue::send(int destination, MpiTag tag, const std::string& text) {
  // Messages are a few hundred bytes: Open MPI sends them eagerly, so this returns at once.
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, destination, static_cast<int>(tag), MPI_COMM_WORLD);
}

std::optional<MpiMessage> MpiQueue::poll() {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  MpiMessage m;
  m.source = status.MPI_SOURCE;
  m.tag = static_cast<MpiTag>(status.MPI_TAG);
  m.text.resize(static_cast<std::size_t>(count));
  MPI_Recv(m.text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return m;
}

void MpiQueue::abort(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();
}

#else

bool MpiQueue::available() { return false; }

MpiQueue::MpiQueue() {
  throw Error("sweep: this wiggle was built without MPI (install libopenmpi-dev and rebuild), so it cannot run under "
              "mpirun; run `wiggle sweep` without mpirun to use the local cores");
}
MpiQueue::~MpiQueue() = default;
void MpiQueue::send(int, MpiTag, const std::string&) {}
std::optional<MpiMessage> MpiQueue::poll() { return std::nullopt; }
void MpiQueue::abort(int) { std::abort(); }

#endif

}  // namespace wiggle
