#include "scenario/run/RunSummary.h"

#include <algorithm>
#include <optional>

#include "core/Error.h"
#include "core/Format.h"
#include "physics/StepProfile.h"
#include "physics/World.h"

namespace wiggle {

namespace {
using S = RunSummary;
}  // namespace

const std::vector<SummaryField>& summaryFields() {
  static const std::vector<SummaryField> fields = {
      {"vy", "sqrt(g d)", "the paper's rate (y_f - y_i) / (t_f - t_i)", &S::vy},
      {"vy_slope", "sqrt(g d)", "least-squares slope of y(t) over [t_i, t_f]", &S::vySlope},
      {"vy_rule", "", "the rule that chose t_i and t_f, in words", &S::vyRule},
      {"plateau", "", "true when t_f is the start of a plateau at the free surface", &S::plateau},
      {"t_i", "sqrt(d/g)", "start of the rate's window: 0.1 t_total", &S::tInitial},
      {"t_f", "sqrt(d/g)", "end of the rate's window", &S::tFinal},
      {"y_initial", "d", "intruder centre height at t_i", &S::yInitial},
      {"y_final", "d", "intruder centre height at t_f", &S::yFinal},
      {"y_start", "d", "intruder centre height at t = 0", &S::yStart},
      {"angle_end", "rad", "how far the intruder turned by the end, counter-clockwise (0 unless intruder.rotation = free)",
       &S::angleEnd},
      {"vy_window_periods", "", "(t_f - t_i) / T: the drive periods V_y is measured over", &S::vyWindowPeriods},
      {"vy_settled", "sqrt(g d)",
       "the rate by the paper's t_f rule: (y(t_settled) - y_i) / (t_settled - t_i); vy when the intruder never settled",
       &S::vySettled},
      {"t_settled", "sqrt(d/g)",
       "the paper's t_f: when the intruder came within settle_band of its final level to stay; t_f when it never "
       "settled",
       &S::tSettled},
      {"settled", "", "true when the intruder reached a final level before the end (docs/PHYSICS.md, section 9)",
       &S::settled},
      {"settle_band", "d", "the settle rule's band: how close to its final level the intruder stays", &S::settleBand},
      {"averaged_from_t", "sqrt(d/g)", "where the phase rates and fields begin to average", &S::averagedFromT},
      {"warnings", "", "what makes the result less than it seems; empty when nothing is amiss", &S::warnings},
      {"overlap_margin", "", "deepest overlap seen, as a fraction of the blow-up bound", &S::overlapMargin},
      {"speed_margin", "", "fastest grain seen, as a fraction of the blow-up bound", &S::speedMargin},
      {"status", "", "ok", &S::status},
      {"n_grains", "", "grains in the bed", &S::grains},
      {"n_particles", "", "grains and frozen base particles", &S::particles},
      {"steps", "", "time steps of the run", &S::steps},
      {"threads", "", "OpenMP threads of the last stretch run", &S::threads},
      {"simd", "",
       "instruction set of the force kernels of the last stretch run: scalar, avx2 or avx512 (the same bits; only the "
       "speed differs)",
       &S::simd},
      {"wall_s", "s", "wall time: run and bed", &S::wallSeconds},
      {"run_wall_s", "s", "wall time of the run phase", &S::runWallSeconds},
      {"bed_wall_s", "s", "wall time spent obtaining the bed (made or loaded)", &S::bedWallSeconds},
      {"bed_from_cache", "", "true when the bed was loaded from the cache", &S::bedFromCache},
      {"bed_key", "", "hex key of the bed's parameters", &S::bedKey},
      {"ns_per_particle_step", "ns", "run-phase wall time per particle per step", &S::nsPerParticleStep},
      {"state_hash", "", "hash of the final state's bits", &S::stateHash},
      {"neighbour_pairs", "", "pairs in the grain list at the end (skin included)", &S::neighbourPairs},
      {"contacts", "", "listed pairs that touch at the last step", &S::contacts},
      {"intruder_pairs", "", "grain-atom pairs listed for the intruder at the end", &S::intruderPairs},
      {"state_bytes_per_grain", "B", "the simulation state's arrays per grain", &S::stateBytesPerGrain},
      {"step_profile", "",
       "only with run.profile: the step's wall time by stage, this process's stepping (docs/OUTPUT-FORMATS.md)",
       &S::stepProfile},
      {"threads_used", "s",
       "wall seconds this process stepped at each thread count, by count ({\"2\": 812.5, \"1\": 95.0}): fewer "
       "than `threads` while another process held a core (docs/PERFORMANCE.md); absent at one thread",
       &S::threadsUsed},
      {"shape", "", "intruder.shape", &S::shape},
      {"amplitude", "d", "drive.amplitude", &S::amplitude},
      {"period", "sqrt(d/g)", "drive.period", &S::period},
      {"mu", "", "contact.mu", &S::mu},
      {"field_frames", "", "frames averaged per fields.phases entry", &S::fieldFrames},
      {"version", "", "version and git revision of the wiggle that wrote the file: 0.1.0 (git a1b2c3d4e5f6)",
       &S::version},
  };
  return fields;
}

nlohmann::json toJson(const RunSummary& summary) {
  nlohmann::json j = nlohmann::json::object();
  for (const SummaryField& f : summaryFields())
    std::visit(
        [&](auto member) {
          if constexpr (std::is_same_v<decltype(member), RunStatus S::*>)
            j[f.name] = choiceName(summary.*member);  // the word, never the enum's number
          else if constexpr (std::is_same_v<decltype(member), nlohmann::json S::*>) {
            if (!(summary.*member).is_null()) j[f.name] = summary.*member;  // an optional object: absent when off
          } else
            j[f.name] = summary.*member;
        },
        f.member);
  return j;
}

RunSummary summaryFromJson(const nlohmann::json& json) {
  if (!json.is_object()) throw Error("summary: expected a JSON object");
  RunSummary summary;
  for (const SummaryField& f : summaryFields()) {
    const auto it = json.find(f.name);
    if (it == json.end()) continue;
    std::visit(
        [&](auto member) {
          try {
            if constexpr (std::is_same_v<decltype(member), RunStatus S::*>) {
              const std::string word = it->get<std::string>();
              const std::optional<RunStatus> status = choiceNamed<RunStatus>(word);
              if (!status)
                throw Error(std::string("summary: key '") + f.name + "' is '" + word + "', none of " +
                            joinedNames(choiceNameList<RunStatus>()));
              summary.*member = *status;
            } else if constexpr (std::is_same_v<decltype(member), nlohmann::json S::*>) {
              if (!it->is_object() && !it->is_null())
                throw Error(std::string("summary: key '") + f.name + "' has the wrong type");
              summary.*member = *it;
            } else {
              it->get_to(summary.*member);
            }
          } catch (const nlohmann::json::exception&) {
            throw Error(std::string("summary: key '") + f.name + "' has the wrong type");
          }
        },
        f.member);
  }
  return summary;
}

nlohmann::json threadsUsedJson(const World& world) {
  const std::vector<double> seconds = world.threadGovernor().secondsAt();
  nlohmann::json used;  // null until a count has a window
  for (std::size_t n = seconds.size(); n-- > 1;)
    if (seconds[n] > 0) used[std::to_string(n)] = seconds[n];
  return used;
}

std::string threadsShedWarning(const RunSummary& summary) {
  const nlohmann::json& threadsUsed = summary.threadsUsed;
  const int ceiling = static_cast<int>(summary.threads);
  if (!threadsUsed.is_object()) return "";
  double total = 0.0, shed = 0.0;
  int fewest = ceiling;
  for (const auto& [count, seconds] : threadsUsed.items()) {
    const int n = std::stoi(count);
    total += seconds.get<double>();
    if (n < ceiling) {
      shed += seconds.get<double>();
      fewest = std::min(fewest, n);
    }
  }
  if (!(shed > 0)) return "";
  const std::string on = fewest == 1 ? "1 thread" : "as few as " + std::to_string(fewest) + " threads";
  return "another process took a core: ran on " + on + " (of " + std::to_string(ceiling) + ") for " +
         formatNumber(100.0 * shed / total, 2) + " % of this process's stepping (summary.json threads_used; the result "
         "is the same)";
}

nlohmann::json stepProfileJson(const World& world) {
  const StepProfile& profile = world.stepProfile();
  const double step = profile.stepSeconds();
  auto share = [step](double seconds) { return step > 0 ? seconds / step : 0.0; };
  nlohmann::json stages = nlohmann::json::object();
  for (std::size_t k = 0; k < StepProfile::kStages; ++k) {
    const auto stage = static_cast<StepStage>(k);
    const StepProfile::StageTotals& t = profile.stage(stage);
    const StageInfo& info = stageInfo(stage);
    nlohmann::json entry = {
        {"kind", stageKindName(info.kind)}, {"s", t.seconds}, {"share", share(t.seconds)}, {"calls", t.calls}};
    if (info.kind == StageKind::Parallel) {
      entry["work_s"] = t.workSeconds;
      entry["wait_s"] = t.waitSeconds;
      entry["wait_share"] = t.threadSeconds > 0 ? t.waitSeconds / t.threadSeconds : 0.0;
    }
    stages[std::string(info.name)] = entry;
  }
  nlohmann::json imbalance = nlohmann::json::object();
  for (std::uint32_t threads : {2u, 4u, 8u, 16u, 32u}) imbalance[std::to_string(threads)] = world.stripImbalance(threads);
  const double serial = profile.serialShare(), wait = profile.waitShare();
  return {{"threads", profile.threads()},
          {"steps", profile.steps()},
          {"step_s", step},
          {"serial_share", serial},
          {"wait_share", wait},
          {"serial_and_wait_share", serial + wait},
          {"stages", stages},
          {"strip_imbalance", imbalance}};
}

nlohmann::json summarySchema() {
  nlohmann::json schema = nlohmann::json::array();
  for (const SummaryField& f : summaryFields()) {
    const char* type = std::visit(
        [](auto member) -> const char* {
          using T = std::remove_reference_t<decltype(RunSummary{}.*member)>;
          if constexpr (std::is_same_v<T, double>) return "number";
          else if constexpr (std::is_same_v<T, bool>) return "boolean";
          else if constexpr (std::is_same_v<T, std::uint64_t>) return "integer";
          else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, RunStatus>) return "string";
          else if constexpr (std::is_same_v<T, std::vector<std::string>>) return "list of strings";
          else if constexpr (std::is_same_v<T, nlohmann::json>)
            return "object";
          else return "list of integers";
        },
        f.member);
    schema.push_back({{"name", f.name}, {"type", type}, {"unit", f.unit}, {"meaning", f.meaning}});
  }
  return schema;
}

}  // namespace wiggle
