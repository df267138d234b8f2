#pragma once
// results.csv of a sweep directory (docs/OUTPUT-FORMATS.md, docs/SWEEPS.md): one row per case in
// case order, rewritten whole and atomically (temporary file + rename) after every change, so a
// reader never sees a torn file.
//
// Columns: the fixed ones before the parameters (case ... wall_s), one per parameter named by its
// config key (the keys that vary in the sweep, then intruder.shape, drive.amplitude, drive.period,
// contact.mu and box.seed when they do not vary, so the plots always find them), then the fixed ones
// after (n_grains ... warnings); the fixed ones are the table resultColumnsBeforeParameters /
// AfterParameters, which docs/results-schema.json repeats for the Python package.
// status: ok | failed | running | pending (not run yet, or interrupted: it resumes on a rerun).
// Numbers of a case that is not ok are empty cells. Cells holding a comma, quote or newline are
// quoted as RFC 4180 says.
#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Choice.h"
#include "io/SweepSpec.h"
#include "scenario/run/RunSummary.h"

namespace wiggle {

// Where a case of a sweep stands. Its word (ChoiceNames below) is what results.csv, `wiggle status
// --json` and the task protocol carry; code compares the enum, never the word.
enum class CaseStatus {
  Ok,       // its summary.json is written: its numbers are in the table
  Failed,   // it cannot run, or its run failed (error says why)
  Running,  // a process runs it now
  Pending,  // not run yet, or interrupted: it resumes on a rerun
};
template <>
struct ChoiceNames<CaseStatus> {
  static constexpr std::array<std::string_view, 4> names{"ok", "failed", "running", "pending"};
};

// A status word read from a file or a child's message; throws wiggle::Error naming `where` and the
// words it may be when it is none of them (a hand-edited or foreign file).
CaseStatus caseStatusNamed(std::string_view word, const std::string& where);

// What a case's run left, read from its summary.json (numbers) or its failure (error).
// A case as the sweep sees it: its status, and when ok the run's outcome as its summary.json holds
// it (one struct, the summary's: results.csv's columns, the task protocol and `wiggle status` all
// read it, none copies it field by field).
struct CaseResult {
  CaseStatus status = CaseStatus::Pending;
  std::string error;   // one line; empty unless failed (or interrupted)
  RunSummary summary;  // summary.json's (ok cases)

  // Particles x steps of the run phase (for the ETA); the grains' count for a summary written
  // before it recorded its particles.
  double particleSteps() const;
};

// The error column of a case the sweep's stop interrupted (pending, to resume): the child's own
// words when they already say so ("interrupted at t = 12.5"), else "interrupted: " and its words.
std::string interruptedError(const std::string& why);

// Whether the case in runDir is finished: its summary.json reads whole and says "ok". The one rule
// for every reader: the sweep skips such a case and reruns any other, and `wiggle status`,
// `wiggle report` and `wiggle plot` (python/wiggleplot/readers.py) count a case as done only when
// it holds, whatever a stale results.csv says.
bool caseFinished(const std::string& runDir);

// Reads <runDir>/summary.json into a CaseResult, Ok when the file says "ok". Throws
// wiggle::Error when the file is missing or unreadable.
CaseResult readCaseSummary(const std::string& runDir);

// The sweep's pace for its ETA [ns per particle-step]: the median over the finished cases of each
// one's stepping time per particle-step, or `fallback` (the cost model's) before any has finished.
// A median, not the total time over the total work: a case paused for hours (SIGSTOP while the
// machine does a benchmark) is one slow case and moves the pace by one place, not by its hours.
// With `only` (a `--case` task) only that case counts: the others may have run on other machines
// (a Slurm array's nodes, a study continued elsewhere), so until it finishes the pace is the cost
// model's, this machine's.
double sweepNsPerParticleStep(const std::vector<CaseResult>& results, std::optional<std::size_t> only,
                              double fallback);

// One row's inputs, which each fixed column reads its cell from.
struct ResultRow {
  const SweepCase& sweepCase;
  const std::string& runDir;
  const CaseResult& result;
};

// A column of results.csv that every sweep has (the parameters' columns vary with the sweep): the
// one table the header, the rows and docs/results-schema.json (which the Python package is checked
// against) are all made from.
struct ResultColumn {
  const char* name;
  const char* unit;     // "" for none
  const char* meaning;  // one line
  std::string (*cell)(const ResultRow&);
};
// The columns before the parameters' and after them.
const std::vector<ResultColumn>& resultColumnsBeforeParameters();
const std::vector<ResultColumn>& resultColumnsAfterParameters();

// The schema as JSON: {"before_parameters": [{"name", "unit", "meaning"}, ...], "parameters": "...",
// "after_parameters": [...]} (docs/results-schema.json).
nlohmann::json resultsSchema();

// The column names for a sweep (see the header comment).
std::vector<std::string> resultColumns(const SweepSpec& spec);

// The parameters' columns, by their keys: the keys that vary, then the ones the plots always look
// for (cells.csv has the same, less box.seed).
std::vector<std::string> resultParameterKeys(const SweepSpec& spec);
// A parameter key's column name: the key, except a [[case]] label's ("case"), which is case_label.
std::string resultParameterColumn(const std::string& key);
// A case's cell in a parameter's column.
std::string resultParameterValue(const SweepCase& sweepCase, const std::string& key);

// The whole file's text. `runDirs` are relative to the sweep directory, one per case.
std::string resultsCsv(const SweepSpec& spec, const std::vector<std::string>& runDirs,
                       const std::vector<CaseResult>& results);

// Warnings in one cell: " | " between them.
std::string joinedWarnings(const std::vector<std::string>& warnings);

// One CSV cell, quoted when it must be.
std::string csvCell(const std::string& text);
// One CSV row of such cells, with its newline.
std::string csvRow(const std::vector<std::string>& cells);

// The rows of a CSV text (RFC 4180: quoted cells may hold commas, quotes and newlines).
std::vector<std::vector<std::string>> parseCsv(const std::string& text);

// The cases that sweepDir/results.csv shows unfinished (failed, running or pending), by case name,
// with the status and error their row holds. A task of `sweep --case` writes its case's failure or
// interruption there and nowhere else, so another task rewriting the table takes these rows over.
// Empty when the file is missing or is not a results table that reads whole.
std::map<std::string, CaseResult> readUnfinishedRows(const std::string& sweepDir);

// Brings the vy_settled and t_settled cells of sweepDir/results.csv up to date with each ok case's
// summary.json (after `wiggle rate --write`), inserting the two columns after vy_slope in a file
// written before they existed; every other cell stays as it was. Written atomically.
void refreshSettledColumns(const std::string& sweepDir);

}  // namespace wiggle
