#pragma once
// What long work tells people while it runs: a log file of timestamped lines, and a progress line
// on stderr. One implementation for runs, bed making in the export, and sweeps.
#include <fstream>
#include <functional>
#include <string>

namespace wiggle {

// Appends "YYYY-MM-DD HH:MM:SS  text" lines to a file, flushed line by line (a run's log.txt, a
// sweep's sweep.log): what a killed process leaves is whole lines.
class LogFile {
 public:
  explicit LogFile(const std::string& path) : out_(path, std::ios::app) {}
  void line(const std::string& text);

 private:
  std::ofstream out_;
};

// A progress line: rewritten in place on stderr when stderr is a terminal (at most twice a second),
// and handed to `periodic` every `periodSeconds` either way (a log file; or stderr lines for a
// script or a batch job, which has no terminal to rewrite).
class ProgressLine {
 public:
  using Sink = std::function<void(const std::string&)>;
  ProgressLine(bool enabled, Sink periodic, double periodSeconds);
  bool onTerminal() const { return terminal_; }
  void update(const std::string& text, bool force = false);
  // Erases the rewritten line (before other output, and when the work ends).
  void clear();

 private:
  bool terminal_;
  Sink periodic_;
  double period_;
  double start_, lastDraw_ = -1e9, lastPeriodic_ = 0.0;
  std::string shown_;
};

}  // namespace wiggle
