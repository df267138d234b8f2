// The text of configuration values (io/ConfigText.cpp, through the key table's header): numbers
// written so that they read back to the same double and read well, TOML quoting, range words.
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <string>

#include "io/ConfigKeys.h"

namespace wiggle::config_keys {
namespace {

TEST(ConfigText, NumbersReadBackToTheSameDoubleAndReadWell) {
  EXPECT_EQ(roundTripText(2000000.0, false), "2000000");  // not 2e+06
  EXPECT_EQ(roundTripText(5.0, true), "5.0");             // a TOML float stays a float
  EXPECT_EQ(roundTripText(0.0001, false), "0.0001");      // fixed while short
  EXPECT_EQ(roundTripText(1e-8, false), "1e-08");         // scientific when fixed would be long
  EXPECT_EQ(roundTripText(0.1, false), "0.1");
  for (const double v : {0.1 + 0.2, 1.0 / 3.0, 2.5e-5, 123456.789, -0.0625})
    EXPECT_EQ(std::strtod(roundTripText(v, true).c_str(), nullptr), v) << roundTripText(v, true);
}

TEST(ConfigText, StringsAreQuotedAsTomlBasicStrings) {
  EXPECT_EQ(quoteToml("disk"), "\"disk\"");
  EXPECT_EQ(quoteToml("a \"b\" c"), "\"a \\\"b\\\" c\"");
  EXPECT_EQ(quoteToml("back\\slash"), "\"back\\\\slash\"");
  EXPECT_EQ(quoteToml("two\nlines\x01"), "\"two\\nlines\\u0001\"");  // control characters escaped
}

TEST(ConfigText, RangesAreSaidInWords) {
  EXPECT_EQ(boundText(above(0), noBound), "> 0");
  EXPECT_EQ(boundText(atLeast(0), atMost(0.6)), ">= 0 and <= 0.6");
  EXPECT_EQ(boundText(noBound, below(20)), "< 20");
  EXPECT_EQ(rangeProblem(0.5, above(0), noBound), "");
  EXPECT_EQ(rangeProblem(0.0, above(0), noBound), "must be > 0");
  EXPECT_EQ(rangeProblem(0.7, atLeast(0), atMost(0.6)), "must be >= 0 and <= 0.6");
  EXPECT_EQ(rangeProblem(0.6, atLeast(0), atMost(0.6)), "");  // inclusive bounds include themselves
  EXPECT_EQ(rangeProblem(20.0, noBound, below(20)), "must be < 20");
  EXPECT_EQ(rangeProblem(std::numeric_limits<double>::infinity(), noBound, noBound), "must be a finite number");
}

}  // namespace
}  // namespace wiggle::config_keys
