#include "model/PaperTable1.h"

#include <nlohmann/json.hpp>

namespace wiggle {

extern const char* const kPaperTable1Json;  // the build's copy of docs/paper-table1.json (cmake/PaperTable1.cpp.in)

const std::vector<PaperTable1Row>& paperTable1() {
  static const std::vector<PaperTable1Row> rows = [] {
    std::vector<PaperTable1Row> parsed;
    // Held in a variable: a range-for over a member of the temporary parse() returns would dangle.
    const nlohmann::json table = nlohmann::json::parse(kPaperTable1Json);
    for (const nlohmann::json& row : table.at("rows")) {
      const nlohmann::json& observed = row.at("T_rising_observed");
      parsed.push_back({row.at("shape").get<std::string>(), row.at("l").get<double>(), row.at("T_rise").get<double>(),
                        observed.at(0).get<double>(), observed.at(1).get<double>()});
    }
    return parsed;
  }();
  return rows;
}

const PaperTable1Row* paperTable1Row(std::string_view shape) {
  for (const PaperTable1Row& row : paperTable1())
    if (row.shape == shape) return &row;
  return nullptr;
}

}  // namespace wiggle
