// The `wiggle` command: parses the command line and hands each subcommand to its own file.
#include <csignal>
#include <cstdio>
#include <exception>

#include "Commands.h"
#include "core/Error.h"

int main(int argc, char** argv) {
  // Over a file-size limit (ulimit -f) write() then fails with EFBIG and is reported in one line
  // like a full disk, instead of SIGXFSZ killing the process without a word. Inherited by the
  // sweep's children across exec.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"wiggle: a horizontally wiggling intruder in a 2D bed of frictional grains"};
  app.set_version_flag("--version", std::string("wiggle ") + WIGGLE_VERSION);
  app.require_subcommand(1);
  wiggle::cli::addRunCommand(app);
  wiggle::cli::addSweepCommand(app);
  wiggle::cli::addModelCommand(app);
  wiggle::cli::addPlotCommand(app);
  wiggle::cli::addExportLammpsCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const wiggle::Error& e) {
    std::fprintf(stderr, "wiggle: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wiggle: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
