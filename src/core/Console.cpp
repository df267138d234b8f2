#include "core/Console.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <ctime>

namespace wiggle {

namespace {
double monotonicNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

void LogFile::line(const std::string& text) {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  out_ << stamp << "  " << text << '\n';
  out_.flush();
}

ProgressLine::ProgressLine(bool enabled, Sink periodic, double periodSeconds)
    : terminal_(enabled && ::isatty(STDERR_FILENO)),
      periodic_(std::move(periodic)),
      period_(periodSeconds),
      start_(monotonicNow()) {}

void ProgressLine::update(const std::string& text, bool force) {
  const double now = monotonicNow() - start_;
  if (terminal_ && (force || now - lastDraw_ >= 0.5) && text != shown_) {
    std::fprintf(stderr, "\r\033[K%s", text.c_str());
    std::fflush(stderr);
    lastDraw_ = now;
    shown_ = text;
  }
  if (periodic_ && now - lastPeriodic_ >= period_) {
    periodic_(text);
    lastPeriodic_ = now;
  }
}

void ProgressLine::clear() {
  if (terminal_ && !shown_.empty()) std::fprintf(stderr, "\r\033[K");
  shown_.clear();
}

}  // namespace wiggle
