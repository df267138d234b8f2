// The core's small pure helpers against independent references: FNV-1a 64's published test
// vectors, SplitMix64's published first output, and the text formats the messages and CSV cells use.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "core/Format.h"
#include "core/Hash.h"
#include "core/Rng.h"

namespace wiggle {
namespace {

std::string fnv1a(const std::string& text) {
  Hasher h;
  h.addBytes(text.data(), text.size());
  return h.hex();
}

TEST(Hash, IsFnv1a64OnItsPublishedVectors) {
  EXPECT_EQ(fnv1a(""), "cbf29ce484222325");  // the offset basis
  EXPECT_EQ(fnv1a("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(fnv1a("foobar"), "85944171f73967e8");
}

TEST(Hash, ReadsTheBitsOfWhatItIsGiven) {
  Hasher a, b, c;
  a.addValue(0.0);
  b.addValue(-0.0);  // equal as numbers, other bits: another hash
  c.addValue(0.0);
  EXPECT_NE(a.value(), b.value());
  EXPECT_EQ(a.value(), c.value());
  Hasher v;
  v.add(std::vector<double>{1.0, 2.0});
  Hasher w;
  w.addValue(1.0);
  w.addValue(2.0);
  EXPECT_EQ(v.hex(), w.hex());  // an array is its elements' bytes in order
}

TEST(Rng, MixerIsSplitMix64) {
  // SplitMix64 seeded with 0 returns 0xe220a8397b1dcdaf first: the finaliser of 0 + the golden gamma.
  EXPECT_EQ(mix64(0), 0xe220a8397b1dcdafULL);
}

TEST(Rng, DrawsAreAPureFunctionOfTheirKeysAndUniform) {
  EXPECT_EQ(uniform01(7, RngStream::GrainDiameter, 123, 1), uniform01(7, RngStream::GrainDiameter, 123, 1));
  std::set<double> differ = {uniform01(7, RngStream::GrainDiameter, 123), uniform01(8, RngStream::GrainDiameter, 123),
                             uniform01(7, RngStream::PourPosition, 123), uniform01(7, RngStream::GrainDiameter, 124),
                             uniform01(7, RngStream::GrainDiameter, 123, 1)};
  EXPECT_EQ(differ.size(), 5u);  // each key changes the draw
  const int n = 100000;
  double sum = 0.0, sumSq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = uniform01(1, RngStream::PourVelocity, static_cast<std::uint64_t>(i));
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sumSq += u * u;
  }
  // Mean 1/2 and variance 1/12, each to 5 standard errors of n draws.
  EXPECT_NEAR(sum / n, 0.5, 5 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(sumSq / n - (sum / n) * (sum / n), 1.0 / 12.0, 5 * std::sqrt(1.0 / 180.0 / n));
}

TEST(Format, NumbersAsPrintfG) {
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(1e-5), "1e-05");
  EXPECT_EQ(formatNumber(2000000.0), "2e+06");
  EXPECT_EQ(formatNumber(1.0 / 3.0, 10), "0.3333333333");
  const double x = 0.1 + 0.2;
  EXPECT_EQ(std::stod(formatNumber(x, 17)), x);  // 17 digits keep the bits
}

TEST(Format, DurationsForPeople) {
  EXPECT_EQ(formatDuration(42.4), "42s");
  EXPECT_EQ(formatDuration(185.0), "3m05s");
  EXPECT_EQ(formatDuration(3720.0), "1h02m");
  EXPECT_EQ(formatDuration(2 * 86400.0 + 3 * 3600.0), "2d03h");
  EXPECT_EQ(formatDuration(-1.0), "?");
  EXPECT_EQ(formatDuration(std::numeric_limits<double>::quiet_NaN()), "?");
}

}  // namespace
}  // namespace wiggle
