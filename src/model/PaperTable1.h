#pragma once
// The paper's Table 1 (A = 5 d), as the paper prints it: per shape, the cavity model's columns and the
// T_rising range its simulations observed. One copy, docs/paper-table1.json, compiled in at build time
// (CMakeLists.txt) and read there by study/tools/vy_tables.py too. Shown beside wiggle's own values
// (`wiggle model`), never used to compute them.
#include <string>
#include <string_view>
#include <vector>

namespace wiggle {

struct PaperTable1Row {
  std::string shape;         // the shape's name (intruder.shape)
  double l = 0.0;            // the model's l [d], truncated to two decimals as printed
  double tRise = 0.0;        // the model's T_rise [sqrt(d/g)], truncated as printed
  double observedLow = 0.0;  // the T_rising range the paper's simulations observed [sqrt(d/g)]
  double observedHigh = 0.0;
};

// The rows in the paper's order.
const std::vector<PaperTable1Row>& paperTable1();

// The row of a shape, or nullptr for a shape the paper's table does not hold.
const PaperTable1Row* paperTable1Row(std::string_view shape);

}  // namespace wiggle
