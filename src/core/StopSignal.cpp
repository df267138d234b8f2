#include "core/StopSignal.h"

#include <atomic>
#include <csignal>

namespace wiggle {

namespace {
std::atomic<int> gStopSignal{0};
int gGuards = 0;  // guards alive (they are made on the main thread only)
extern "C" void recordStopSignal(int sig) { gStopSignal = sig; }
}  // namespace

StopSignalGuard::StopSignalGuard() {
  ++gGuards;
  previousInt_ = std::signal(SIGINT, recordStopSignal);
  previousTerm_ = std::signal(SIGTERM, recordStopSignal);
}

StopSignalGuard::~StopSignalGuard() {
  std::signal(SIGINT, previousInt_);
  std::signal(SIGTERM, previousTerm_);
  if (--gGuards == 0) gStopSignal = 0;  // a request is for the guarded work only
}

int stopSignalReceived() { return gStopSignal.load(); }

}  // namespace wiggle
