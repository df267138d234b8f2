#include "sweep/TaskRunner.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <omp.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/Console.h"
#include "core/Error.h"
#include "core/StopSignal.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/case/Case.h"
#include "scenario/run/Experiment.h"


namespace wiggle {

namespace fs = std::filesystem;

double monotonicSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::int64_t SweepTask::encode() const {
  const auto i = static_cast<std::int64_t>(caseIndex);
  return kind == Kind::Case ? i : -(i + 1);
}

SweepTask SweepTask::decode(std::int64_t code) {
  SweepTask t;
  t.kind = code >= 0 ? Kind::Case : Kind::Bed;
  t.caseIndex = static_cast<std::size_t>(code >= 0 ? code : -code - 1);
  return t;
}

std::string TaskOutcome::toJson() const {
  nlohmann::json j;
  j["task"] = task.encode();
  j["ok"] = ok;
  j["error"] = error;
  j["task_wall_s"] = wallSeconds;
  j["pid"] = pid;
  j["status"] = choiceName(result.status);
  j["summary"] = wiggle::toJson(result.summary);
  j["result_error"] = result.error;
  return j.dump();
}

TaskOutcome TaskOutcome::fromJson(const std::string& text) {
  const auto j = nlohmann::json::parse(text);
  TaskOutcome o;
  o.task = SweepTask::decode(j.at("task").get<std::int64_t>());
  o.ok = j.at("ok").get<bool>();
  o.error = j.at("error").get<std::string>();
  o.wallSeconds = j.at("task_wall_s").get<double>();
  o.pid = j.at("pid").get<int>();
  o.result.status = caseStatusNamed(j.at("status").get<std::string>(), "a task's outcome");
  o.result.summary = summaryFromJson(j.at("summary"));
  o.result.error = j.at("result_error").get<std::string>();
  return o;
}

std::string failureLine(const std::string& logTail) {
  std::string lastError, lastLine;
  std::size_t begin = 0;
  while (begin < logTail.size()) {
    std::size_t end = logTail.find('\n', begin);
    if (end == std::string::npos) end = logTail.size();
    std::string line = logTail.substr(begin, end - begin);
    // A progress line rewritten with carriage returns: keep its last state.
    if (const std::size_t cr = line.rfind('\r'); cr != std::string::npos) line = line.substr(cr + 1);
    begin = end + 1;
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    lastLine = line;
    if (line.rfind("wiggle: ", 0) == 0 && line.rfind("wiggle: warning:", 0) != 0) lastError = line.substr(8);
  }
  return lastError.empty() ? lastLine : lastError;
}

TaskRunner::TaskRunner(const SweepSpec& spec, std::string outDir, std::string executable, int threads)
    : spec_(spec), outDir_(std::move(outDir)), executable_(std::move(executable)), threads_(std::max(1, threads)) {}

TaskRunner::~TaskRunner() {
  if (children_.empty()) return;
  signalAll(SIGTERM);
  for (const Child& c : children_) ::waitpid(c.pid, nullptr, 0);
}

void TaskRunner::signalAll(int signal) {
  for (const Child& c : children_) ::kill(c.pid, signal);
}

pid_t TaskRunner::start(const SweepTask& task) {
  if (task.caseIndex >= spec_.cases.size()) throw Error("sweep: task for case " + std::to_string(task.caseIndex) + " out of range");
  const SweepCase& sc = spec_.cases[task.caseIndex];
  std::vector<std::string> args;
  std::string logPath;
  std::error_code ec;
  if (task.kind == SweepTask::Kind::Case) {
    const std::string dir = outDir_ + "/cases/" + sc.name;
    fs::create_directories(dir, ec);
    if (ec) throw Error("cannot create " + dir + ": " + ec.message());
    // The case's config for the child to read. The plan has checked that a run already there is this
    // config or one it continues (a longer run.duration: the run is extended from its checkpoint).
    writeFileAtomically(dir + "/config.toml", toToml(sc.config));
    logPath = dir + "/sweep-child.log";
    args = {executable_, "sweep", kCaseTaskFlag, dir + "/config.toml", "--out", dir, "--threads",
            std::to_string(threads_)};
  } else {
    const std::string base = outDir_ + "/beds/bed-" + bedKey(sc.config, prepareCase(sc.config).clump);
    fs::create_directories(outDir_ + "/beds", ec);
    if (ec) throw Error("cannot create " + outDir_ + "/beds: " + ec.message());
    writeFileAtomically(base + ".toml", toToml(sc.config));
    logPath = base + ".log";
    args = {executable_, "sweep", kBedTaskFlag, base + ".toml", "--threads", std::to_string(threads_)};
  }

  // Everything the child needs is made before fork(): after it, only async-signal-safe calls.
  const int logFd = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (logFd < 0) throw Error("cannot write " + logPath + ": " + std::strerror(errno));
  struct stat st {};
  ::fstat(logFd, &st);
  const auto offset = static_cast<std::uintmax_t>(st.st_size);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();

  const pid_t pid = ::fork();
  if (pid < 0) {
    const std::string why = std::strerror(errno);
    ::close(logFd);
    throw Error("cannot start a process for case " + sc.name + ": " + why);
  }
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(120);  // the parent died before prctl took effect
    // Own process group: a Ctrl-C at the terminal reaches the sweep, which stops its children
    // in order, rather than every child at once.
    ::setpgid(0, 0);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    const int devNull = ::open("/dev/null", O_RDONLY);
    if (devNull >= 0) ::dup2(devNull, 0);
    ::dup2(logFd, 1);
    ::dup2(logFd, 2);
    ::execv(argv[0], argv.data());
    const char message[] = "wiggle: the sweep cannot start the wiggle binary (exec failed)\n";
    [[maybe_unused]] const auto n = ::write(2, message, sizeof message - 1);
    ::_exit(127);
  }
  ::close(logFd);
  children_.push_back({pid, task, logPath, offset, monotonicSeconds()});
  return pid;
}

std::vector<TaskOutcome> TaskRunner::poll() {
  std::vector<TaskOutcome> done;
  for (std::size_t i = 0; i < children_.size();) {
    int status = 0;
    const pid_t r = ::waitpid(children_[i].pid, &status, WNOHANG);
    if (r == children_[i].pid || (r < 0 && errno == ECHILD)) {
      done.push_back(finish(children_[i], r < 0 ? -1 : status));
      children_.erase(children_.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      ++i;
    }
  }
  return done;
}

TaskOutcome TaskRunner::finish(const Child& child, int waitStatus) {
  TaskOutcome out;
  out.task = child.task;
  out.pid = child.pid;
  out.wallSeconds = monotonicSeconds() - child.startSeconds;
  const bool exitedOk = waitStatus >= 0 && WIFEXITED(waitStatus) && WEXITSTATUS(waitStatus) == 0;
  if (exitedOk) {
    out.ok = true;
    if (child.task.kind == SweepTask::Kind::Case) {
      const std::string dir = outDir_ + "/cases/" + spec_.cases[child.task.caseIndex].name;
      try {
        out.result = readCaseSummary(dir);
        if (out.result.status != CaseStatus::Ok) {
          out.ok = false;
          out.error = out.result.error;
        }
      } catch (const Error& e) {
        out.ok = false;
        out.error = std::string("the run ended without a usable summary: ") + e.what();
      }
    }
  } else {
    std::string tail;
    {
      std::ifstream in(child.logPath, std::ios::binary);
      in.seekg(static_cast<std::streamoff>(child.logOffset));
      tail.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    if (waitStatus >= 0 && WIFSIGNALED(waitStatus)) {
      const int sig = WTERMSIG(waitStatus);
      out.error = "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
    } else {
      out.error = failureLine(tail);
      if (out.error.empty())
        out.error = waitStatus < 0 ? std::string("the process vanished (not our child?)")
                                   : "exited with status " + std::to_string(WEXITSTATUS(waitStatus)) + " and no message";
    }
  }
  if (!out.ok) {
    for (char& ch : out.error)
      if (ch == '\n' || ch == '\r') ch = ' ';
    out.result.status = CaseStatus::Failed;
    out.result.error = out.error;
  }
  return out;
}

// ---- the child side of the protocol: what `wiggle sweep --make-bed / --run-case` run

void makeSweepBed(const std::string& configPath, int threads) {
  if (threads > 0) omp_set_num_threads(threads);
  const RunConfig config = parseRunConfig(readFile(configPath), configPath);
  const ClumpDef clump = prepareCase(config).clump;
  const StopSignalGuard stopOnSignal;  // the sweep's SIGTERM: save the bed in the making, then stop
  // The bed task's log (beds/bed-KEY.log) gets the status every minute: a deep bed takes an hour.
  ProgressLine progress(false, [](const std::string& text) { std::printf("%s\n", text.c_str()); std::fflush(stdout); }, 60.0);
  const CachedBed bed = obtainBed(config, clump, [&](const BedStatus& s) { progress.update(bedStatusLine(s, config.box.bedHeight)); });
  if (!bed.note.empty()) std::fprintf(stderr, "wiggle: warning: %s\n", bed.note.c_str());
  std::printf("%s\n", bedTaskDoneLine(bed.key, bed.fromCache, bed.world.grainCount()).c_str());
}

std::string bedTaskDoneLine(const std::string& key, bool fromCache, std::uint32_t grains) {
  return "bed " + key + (fromCache ? " was cached (" : " made and cached (") + std::to_string(grains) + " grains)";
}

bool isBedTaskDoneLine(const std::string& line, const std::string& key) {
  const std::string start = "bed " + key + " ";
  return line.rfind(start + "was cached (", 0) == 0 || line.rfind(start + "made and cached (", 0) == 0;
}

void runSweepCase(const std::string& configPath, const std::string& runDir, int threads) {
  const RunConfig config = parseRunConfig(readFile(configPath), configPath);
  RunOptions options;
  options.outDir = runDir;
  options.threads = threads;
  options.resume = true;
  options.progressLine = false;
  const RunOutcome outcome = runExperiment(prepareCase(config), options);
  std::printf("%s\n", outcome.resultLine().c_str());
  for (const std::string& w : outcome.summary.warnings) std::fprintf(stderr, "wiggle: warning: %s\n", w.c_str());
}

}  // namespace wiggle
