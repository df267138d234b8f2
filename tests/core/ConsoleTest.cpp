// What long work tells people (core/Console.h): the log's timestamped whole lines, and the progress
// line's periodic copies (to a log or, in a batch job, to stderr's lines).
#include "core/Console.h"

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "io/AtomicFile.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

using testing_support::ScratchDir;

TEST(Console, LogFileAppendsTimestampedWholeLines) {
  ScratchDir dir("console");
  const std::string path = dir / "log.txt";
  {
    LogFile log(path);
    log.line("first");
  }
  {
    LogFile log(path);  // a second process, or a resumed run: appended, nothing lost
    log.line("second, with more words");
  }
  const std::string text = readFile(path);
  const std::regex line(R"(\d{4}-\d\d-\d\d \d\d:\d\d:\d\d  (first|second, with more words)\n)");
  EXPECT_EQ(std::distance(std::sregex_iterator(text.begin(), text.end(), line), std::sregex_iterator()), 2) << text;
  EXPECT_LT(text.find("first"), text.find("second"));
}

TEST(Console, ProgressLineHandsTheSinkOneLineAPeriod) {
  std::vector<std::string> seen;
  // Not a terminal here (ctest's stderr is a pipe, and the line is disabled): only the sink.
  ProgressLine every(
      false, [&seen](const std::string& s) { seen.push_back(s); }, 0.0);
  EXPECT_FALSE(every.onTerminal());
  every.update("a");
  every.update("b");
  EXPECT_EQ(seen, (std::vector<std::string>{"a", "b"}));  // a period of 0: every update
  seen.clear();
  ProgressLine hourly(
      false, [&seen](const std::string& s) { seen.push_back(s); }, 3600.0);
  hourly.update("now");
  hourly.update("soon after");
  EXPECT_TRUE(seen.empty());  // the first period has not passed
  ProgressLine none(false, {}, 0.0);
  none.update("no sink: nothing to call");
  none.clear();
}

}  // namespace
}  // namespace wiggle
