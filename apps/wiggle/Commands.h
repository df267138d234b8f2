#pragma once
// One registration function per subcommand, each in its own file. A command's callback throws
// wiggle::Error on bad input; main() turns that into a one-line message and exit status 2.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace wiggle::cli {

void addRunCommand(CLI::App& app);
void addSweepCommand(CLI::App& app);
void addModelCommand(CLI::App& app);
void addPlotCommand(CLI::App& app);
void addExportLammpsCommand(CLI::App& app);
void addStatusCommand(CLI::App& app);
void addReportCommand(CLI::App& app);
void addRateCommand(CLI::App& app);
void addBoundaryCommand(CLI::App& app);

// Runs the plotting package (`/usr/bin/python3 -m wiggleplot ARGS...`, PlotCommand.cpp) and returns
// its exit status.
int runPlotter(const std::vector<std::string>& args);

}  // namespace wiggle::cli
