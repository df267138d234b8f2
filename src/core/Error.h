#pragma once
// The one exception type thrown at the edges (config, files, CLI, engine set-up). Its message is
// a single line that names the problem; the CLI prints it as "wiggle: <message>" and exits non-zero.
#include <stdexcept>
#include <string>

namespace wiggle {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// A run, bed or sweep stopped by SIGINT or SIGTERM after saving its work: not bad input, so the
// command exits 128 + the signal (130, 143), as a shell reports a process the signal ended, and
// scripts tell "resume me" (the same command, with --resume for a run) from "fix your input" (2).
class Interrupted : public Error {
 public:
  Interrupted(int signal, const std::string& message) : Error(message), signal_(signal) {}
  int exitStatus() const { return 128 + signal_; }

 private:
  int signal_;
};

}  // namespace wiggle
