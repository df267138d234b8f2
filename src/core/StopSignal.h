#pragma once
// SIGINT and SIGTERM turned into a request to stop, which long loops (a run's steps, bed making)
// poll at the points where they can save their work first. While no StopSignalGuard is alive the
// signals keep their previous handling (by default they end the process).

namespace wiggle {

// Installs the handlers for its lifetime; restores the previous handlers when it goes, and the
// outermost guard then forgets the request. Guards may nest; make them on the main thread.
class StopSignalGuard {
 public:
  StopSignalGuard();
  ~StopSignalGuard();
  StopSignalGuard(const StopSignalGuard&) = delete;
  StopSignalGuard& operator=(const StopSignalGuard&) = delete;

 private:
  void (*previousInt_)(int);
  void (*previousTerm_)(int);
};

// The signal that asked to stop, or 0.
int stopSignalReceived();

}  // namespace wiggle
