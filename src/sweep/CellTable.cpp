#include "sweep/CellTable.h"

#include <cmath>

#include "core/Error.h"
#include "core/Format.h"

namespace wiggle {

CellStats cellStats(const std::vector<double>& vy) {
  CellStats s;
  s.n = vy.size();
  if (s.n == 0) return s;
  double sum = 0.0;
  for (const double v : vy) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n < kCellMinBeds) return s;  // one bed: no scatter of its own, so no verdict
  double squares = 0.0;
  for (const double v : vy) squares += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(squares / static_cast<double>(s.n - 1));
  s.se = s.sd / std::sqrt(static_cast<double>(s.n));
  if (s.mean != 0.0 && std::fabs(s.mean) >= kCellResolvedStandardErrors * s.se)
    s.verdict = s.mean > 0.0 ? CellVerdict::Rises : CellVerdict::Sinks;
  return s;
}

CellState cellState(std::size_t n, std::size_t beds) {
  return n == 0 ? CellState::NotRun : n >= beds ? CellState::Done : CellState::PartRun;
}

std::string cellInWords(const CellStats& s, std::size_t beds) {
  auto signedNumber = [](double v) {
    std::string text = v >= 0 ? "+" : "";
    return text += formatNumber(v, 3);
  };
  const std::string run =
      s.n < beds ? "part-run: " + std::to_string(s.n) + " of its " + std::to_string(beds) + " beds" : std::string();
  if (s.n == 0) return "no bed run yet (of " + std::to_string(beds) + ")";
  if (s.n == 1)
    return signedNumber(s.mean) + " (one bed: its sign is not a verdict" + (run.empty() ? "" : "; " + run) + ")";
  return signedNumber(s.mean) + " +- " + formatNumber(s.se, 2) + " (" + std::to_string(s.n) + " beds" +
         (run.empty() ? "" : "; " + run) + "): " + std::string(choiceName(s.verdict));
}

const std::vector<std::string>& cellColumnsAfterParameters() {
  static const std::vector<std::string> columns = {"state", "beds",  "n",       "vy_mean",
                                                   "vy_sd", "vy_se", "verdict", "verdict_rule"};
  return columns;
}

std::string cellsCsv(const SweepSpec& spec, const std::vector<CaseResult>& results) {
  if (results.size() != spec.cases.size()) throw Error("cells.csv: internal error: one result per case expected");
  std::vector<std::string> keys;
  for (const std::string& k : resultParameterKeys(spec))
    if (k != kBedKey) keys.push_back(k);
  std::vector<std::string> header = {"cell"};
  for (const std::string& k : keys) header.push_back(resultParameterColumn(k));
  for (const std::string& c : cellColumnsAfterParameters()) header.push_back(c);

  std::string out = csvRow(header);
  for (const SweepCell& cell : spec.cells) {
    std::vector<double> vy;
    for (const std::size_t c : cell.cases)
      if (results[c].status == CaseStatus::Ok) vy.push_back(results[c].summary.vy);
    const CellStats s = cellStats(vy);
    std::vector<std::string> row = {cell.name};
    for (const std::string& k : keys) row.push_back(resultParameterValue(spec.cases[cell.cases.front()], k));
    auto number = [](bool present, double v) { return present ? formatNumber(v, 10) : std::string(); };
    row.push_back(std::string(choiceName(cellState(s.n, cell.cases.size()))));
    row.push_back(std::to_string(cell.cases.size()));
    row.push_back(std::to_string(s.n));
    row.push_back(number(s.n >= 1, s.mean));
    row.push_back(number(s.n >= kCellMinBeds, s.sd));
    row.push_back(number(s.n >= kCellMinBeds, s.se));
    row.push_back(std::string(choiceName(s.verdict)));
    row.push_back(kCellVerdictRule);
    out += csvRow(row);
  }
  return out;
}

}  // namespace wiggle
