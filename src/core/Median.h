#pragma once
// The median of a list of numbers: the middle one, or the mean of the two middle ones.
#include <algorithm>
#include <vector>

#include "core/Assert.h"

namespace wiggle {

inline double median(std::vector<double> values) {
  WIGGLE_ASSERT(!values.empty());
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace wiggle
