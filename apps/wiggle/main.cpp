// The `wiggle` command: parses the command line and hands each subcommand to its own file.
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "Commands.h"
#include "core/Error.h"
#include "core/Version.h"

namespace {

// The one line `wiggle: ...` for a command-line error caught by CLI11 (unknown command or option,
// bad value, missing argument): CLI11's own text, which names the option, with the subcommand it
// was given to in front, the arguments of "not expected" in command-line order (CLI11 lists them
// reversed) and a pointer to the help.
std::string parseErrorLine(const CLI::App& app, const CLI::ParseError& e) {
  const CLI::App* context = &app;
  for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) context = sub = sub->get_subcommands().back();
  std::string commands;
  for (const CLI::App* sub : app.get_subcommands({})) commands += (commands.empty() ? "" : ", ") + sub->get_name();
  if (context == &app && dynamic_cast<const CLI::RequiredError*>(&e) && app.get_subcommands().empty()) {
    // `wiggle rn`, `wiggle --bogus`: CLI11 says only "A subcommand is required".
    std::string given, extras;
    for (const std::string& a : app.remaining()) {
      if (given.empty() && !a.empty() && a[0] != '-') given = a;
      extras += " " + a;
    }
    const std::string what = !given.empty()   ? "unknown command '" + given + "'"
                             : extras.empty() ? std::string("no command given")
                                              : "no command given; not expected:" + extras;
    return "wiggle: " + what + " (commands: " + commands + "; see wiggle --help)";
  }
  std::string message = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {  // get_name() is the app's name here
    std::vector<std::string> extras = app.remaining();
    if (!extras.empty()) context = &app;  // `wiggle --bogus run`: given to wiggle itself
    else if (context != &app) extras = context->remaining();
    if (!extras.empty()) {
      message = extras.size() > 1 ? "The following arguments were not expected:"
                                  : "The following argument was not expected:";
      for (const std::string& a : extras) message += " " + a;
    }
  }
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  const std::string where = context == &app ? "" : context->get_name();
  const std::string prefix = where.empty() ? "" : where + " ";
  return "wiggle: " + (where.empty() ? "" : where + ": ") + message + " (see wiggle " + prefix + "--help)";
}

}  // namespace

int main(int argc, char** argv) {
  // Over a file-size limit (ulimit -f) write() then fails with EFBIG and is reported in one line
  // like a full disk, instead of SIGXFSZ killing the process without a word. Inherited by the
  // sweep's children across exec.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"wiggle: a horizontally wiggling intruder in a 2D bed of frictional grains"};
  app.set_version_flag("--version", "wiggle " + wiggle::versionText());
  app.require_subcommand(1);
  app.footer(
      "Environment:\n"
      "  WIGGLE_CACHE     directory of cached beds (default ~/.cache/wiggle; a config's bed.cache_dir wins)\n"
      "  WIGGLE_PYTHON    the python3 that `wiggle plot` and `report` run (default /usr/bin/python3; it needs\n"
      "                   matplotlib and numpy); WIGGLE_PYTHONPATH: where its wiggleplot package is\n"
      "  WIGGLE_SIMD      cap the force kernels' instruction set: scalar, avx2 or avx512 (default: the widest\n"
      "                   the CPU runs; every one gives the same bits, docs/PERFORMANCE.md)\n"
      "  OMP_WAIT_POLICY  passive: OpenMP threads sleep instead of spinning at barriers (slower on a quiet\n"
      "                   machine, and beside other work too: a run sheds the threads that wait instead,\n"
      "                   docs/PERFORMANCE.md)");
  wiggle::cli::addRunCommand(app);
  wiggle::cli::addSweepCommand(app);
  wiggle::cli::addModelCommand(app);
  wiggle::cli::addPlotCommand(app);
  wiggle::cli::addExportLammpsCommand(app);
  wiggle::cli::addStatusCommand(app);
  wiggle::cli::addReportCommand(app);
  wiggle::cli::addRateCommand(app);
  wiggle::cli::addBoundaryCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version print and exit 0; a CLI::RuntimeError carries the status of a command
    // that has already said why (the plotter); every other parse error is bad input: one line, 2.
    if (dynamic_cast<const CLI::RuntimeError*>(&e)) return e.get_exit_code();
    if (dynamic_cast<const CLI::Success*>(&e)) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "%s\n", parseErrorLine(app, e).c_str());
    return 2;
  } catch (const wiggle::Interrupted& e) {
    std::fprintf(stderr, "wiggle: %s\n", e.what());
    return e.exitStatus();
  } catch (const wiggle::Error& e) {
    std::fprintf(stderr, "wiggle: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wiggle: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
