#include "scenario/cost/CostModel.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/Error.h"
#include "io/Config.h"
#include "scenario/bed/BedMaker.h"
#include "scenario/case/Case.h"
#include "scenario/cost/SpeedRecord.h"

namespace wiggle {

extern const char* const kCostTableCsv;  // the build's copy of bench/costs.csv (cmake/CostTable.cpp.in)

namespace {

// The fields of one CSV line: commas separate, double quotes enclose a field that holds commas.
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (const char ch : line) {
    if (ch == '"')
      quoted = !quoted;
    else if (ch == ',' && !quoted)
      fields.emplace_back();
    else
      fields.back() += ch;
  }
  return fields;
}

}  // namespace

CostTable parseCostTable(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> head = csvFields(line);
  const auto column = [&head](const std::string& name) {
    const auto it = std::find(head.begin(), head.end(), name);
    if (it == head.end()) throw Error("cost table: no column " + name);
    return static_cast<std::size_t>(it - head.begin());
  };
  const std::size_t particles = column("particles"), threads = column("threads"), code = column("code"),
                    ns = column("ns_per_particle_step"), machine = column("machine"), source = column("source");
  CostTable table;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> f = csvFields(line);
    if (f.size() != head.size())
      throw Error("cost table: line " + std::to_string(number) + " has " + std::to_string(f.size()) + " fields, not " +
                  std::to_string(head.size()));
    if (f[code] != "wiggle") continue;
    CostTable::Row row;
    try {
      row.particles = std::stod(f[particles]);
      row.nsPerParticleStep = std::stod(f[ns]);
    } catch (const std::exception&) {
      throw Error("cost table: line " + std::to_string(number) + ": particles or ns_per_particle_step is not a number");
    }
    if (!(row.particles > 0.0) || !(row.nsPerParticleStep > 0.0))
      throw Error("cost table: line " + std::to_string(number) + ": particles and ns_per_particle_step must be > 0");
    int count = 0;
    try {
      count = std::stoi(f[threads]);
    } catch (const std::exception&) {
    }
    if (count < 1) throw Error("cost table: line " + std::to_string(number) + ": threads is not a count");
    (count == 1 ? table.rows : table.rowsAtThreads[count]).push_back(row);
    table.machine = f[machine];
    table.source = f[source];
  }
  if (table.rows.empty()) throw Error("cost table: no row of wiggle at one thread");
  const auto byParticles = [](const CostTable::Row& a, const CostTable::Row& b) { return a.particles < b.particles; };
  std::sort(table.rows.begin(), table.rows.end(), byParticles);
  for (auto& [count, rows] : table.rowsAtThreads) std::sort(rows.begin(), rows.end(), byParticles);
  return table;
}

namespace {
// Linear between the rows' beds (sorted by particles), the end rows' figures beyond them.
double interpolated(const std::vector<CostTable::Row>& rows, double particles) {
  if (particles <= rows.front().particles) return rows.front().nsPerParticleStep;
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (particles <= rows[i].particles) {
      const CostTable::Row &a = rows[i - 1], &b = rows[i];
      return a.nsPerParticleStep +
             (b.nsPerParticleStep - a.nsPerParticleStep) * (particles - a.particles) / (b.particles - a.particles);
    }
  return rows.back().nsPerParticleStep;
}
}  // namespace

double CostTable::nsPerParticleStep(double particles) const { return interpolated(rows, particles); }

int CostTable::measuredThreads(int threads) const {
  int measured = 1;
  for (const auto& [count, rowsOfCount] : rowsAtThreads)
    if (count <= threads) measured = count;
  return measured;
}

double CostTable::speedUp(double particles, int threads) const {
  const int measured = measuredThreads(threads);
  if (measured == 1) return 1.0;
  return nsPerParticleStep(particles) / interpolated(rowsAtThreads.at(measured), particles);
}

const CostTable& committedCostTable() {
  static const CostTable table = parseCostTable(kCostTableCsv);
  return table;
}

SpeedBasis speedBasis(const RunConfig& config) {
  SpeedBasis basis;
  const double particles = estimatedParticles(config);
  const CostTable& table = committedCostTable();
  const auto nsOfSize = [&table](double n) { return table.nsPerParticleStep(n); };
  if (const std::optional<MeasuredSpeed> m = measuredSpeed(config, particles, nsOfSize)) {
    basis.ns = m->nsPerParticleStep;
    basis.source = "the median of this machine's last " + std::to_string(m->runs) + " one-thread run" +
                   (m->runs == 1 ? "" : "s") + " of a " + m->buildKind + " build" +
                   (m->sameSize ? " on beds of this size"
                                : " (none yet on a bed of this size; a run of a known size counts scaled to it by bench/costs.csv's size dependence)") +
                   " (" + m->path + ")";
  } else {
    basis.ns = table.nsPerParticleStep(particles);
    basis.source = "no one-thread run of a " + speedBuildKind() +
                   " build recorded on this machine yet, so the committed cost table's figure for a bed of this "
                   "size (bench/costs.csv: " + table.machine.substr(0, table.machine.find(',')) + "; docs/PERFORMANCE.md)";
  }
  return basis;
}

ThreadScaling threadScaling(double particles, int threads) {
  const CostTable& table = committedCostTable();
  ThreadScaling s;
  s.speedUp = table.speedUp(particles, threads);
  if (threads <= 1) return s;
  const int measured = table.measuredThreads(threads);
  s.words = measured == 1 ? "bench/costs.csv measured no thread count above one: counted as one thread"
                          : formatNumber(s.speedUp, 3) + " x one thread at " + std::to_string(measured) +
                                " threads on a bed of this size, as bench/costs.csv measured it" +
                                (measured < threads ? " (more threads not measured: counted as " +
                                                          std::to_string(measured) + ")"
                                                    : "");
  return s;
}

double estimatedParticles(const RunConfig& config) { return estimatedGrains(config) + config.box.width; }

double estimatedRunSeconds(const RunConfig& config, double nsPerParticleStep) {
  const double steps = static_cast<double>(wholeStepsIn(config.run.duration, config.run.dt));
  return 1e-9 * nsPerParticleStep * estimatedParticles(config) * steps;
}

double estimatedBedTime(const RunConfig& config, bool withBase) {
  // Pouring b nominal batches in r batches, the bed holds on average (r + 1) / (2 r) of its final
  // grains (each batch is there from its drop on); then the whole bed relaxes.
  const CostModel::Pour pour = CostModel::pour(config.bed.pour);
  const double nominal = config.box.bedHeight / config.bed.batchHeight;
  const double batches = std::max(1.0, nominal * pour.batchesPerNominalBatch);
  const double pourTime = nominal * pour.timePerNominalBatch * (batches + 1.0) / (2.0 * batches);
  const bool carved = config.bed.cavity == BedCavity::Carved;
  const double area = config.box.width * config.box.bedHeight;
  const double relaxTime = config.bed.relaxDamping > 0 ? CostModel::dampedRelaxTime
                           : carved                    ? CostModel::carvedRelaxTime
                                                       : CostModel::relaxTimePerArea * area;
  return relaxTime + (carved && !withBase ? 0.0 : pourTime);
}

double estimatedBedSeconds(const RunConfig& config, double nsPerParticleStep, bool withBase) {
  return 1e-9 * nsPerParticleStep * estimatedParticles(config) * estimatedBedTime(config, withBase) / config.run.dt;
}

BedPlan planBed(const RunConfig& config, const ClumpDef& clump) {
  BedPlan plan;
  if (!config.bed.file.empty()) {
    plan.source = BedPlan::Source::File;
    plan.path = config.bed.file;
    return plan;
  }
  plan.key = bedKey(config, clump);
  plan.path = bedCachePath(config, plan.key);
  if (std::filesystem::exists(plan.path)) {
    plan.source = BedPlan::Source::Cached;
  } else if (config.bed.cavity == BedCavity::Carved) {
    plan.source = BedPlan::Source::Carve;
    plan.baseKey = baseBedKey(config);
    plan.baseCached = std::filesystem::exists(bedCachePath(config, plan.baseKey));
  }
  return plan;
}

}  // namespace wiggle
