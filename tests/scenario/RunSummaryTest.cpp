// summary.json's one table (scenario/run/RunSummary.h): it writes and reads the file, and it is the
// schema the documents and the Python package use.
#include <gtest/gtest.h>

#include "core/Error.h"
#include "scenario/run/RunSummary.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

using testing_support::sourceFile;

TEST(RunSummary, ReadsBackWhatItWrites) {
  RunSummary s;
  s.vy = 0.0886;
  s.plateau = true;
  s.warnings = {"one", "two"};
  s.steps = 1000000;
  s.stateHash = "6308a1dc6fb47752";
  s.fieldFrames = {3, 4};
  const nlohmann::json j = toJson(s);
  EXPECT_EQ(j["vy"], 0.0886);
  EXPECT_EQ(j["state_hash"], "6308a1dc6fb47752");
  EXPECT_EQ(j["status"], "ok");  // the word from the choice table, not the enum's number
  EXPECT_EQ(toJson(summaryFromJson(j)), j);
}

TEST(RunSummary, MissingKeysKeepTheirDefaultsAndWrongTypesAreNamed) {
  const RunSummary old = summaryFromJson(nlohmann::json{{"vy", 0.5}, {"status", "ok"}});
  EXPECT_EQ(old.vy, 0.5);
  EXPECT_EQ(old.status, RunStatus::Ok);
  EXPECT_TRUE(old.warnings.empty());
  try {
    summaryFromJson(nlohmann::json{{"steps", "many"}});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'steps'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(summaryFromJson(nlohmann::json::array()), Error);
  try {
    summaryFromJson(nlohmann::json{{"status", "done"}});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'status' is 'done', none of ok, stopped"), std::string::npos) << e.what();
  }
}

// The schema file the Python package reads is this table; on a change, replace
// docs/summary-schema.json by the text this test prints.
TEST(RunSummary, SchemaFileIsTheTable) {
  const std::string expected = summarySchema().dump(2) + "\n";
  EXPECT_EQ(sourceFile("docs/summary-schema.json"), expected) << "docs/summary-schema.json should be:\n" << expected;
}

// docs/OUTPUT-FORMATS.md names every key of summary.json.
TEST(RunSummary, EveryKeyIsDocumented) {
  const std::string doc = sourceFile("docs/OUTPUT-FORMATS.md");
  const auto begin = doc.find("### `summary.json`");
  ASSERT_NE(begin, std::string::npos);
  const std::string section = doc.substr(begin, doc.find("\n### ", begin + 1) - begin);
  for (const SummaryField& f : summaryFields())
    EXPECT_NE(section.find(std::string("`") + f.name + "`"), std::string::npos) << f.name;
}

// A run that shed threads says so (log and terminal) with the share of its stepping, from
// threads_used; one that kept them, or had one, says nothing.
TEST(RunSummary, SaysWhenTheRunShedThreads) {
  RunSummary summary;
  summary.threads = 2;
  EXPECT_EQ(threadsShedWarning(summary), "");
  summary.threadsUsed = {{"2", 10.0}};
  EXPECT_EQ(threadsShedWarning(summary), "");
  summary.threadsUsed = {{"2", 1.0}, {"1", 3.0}};
  EXPECT_EQ(threadsShedWarning(summary),
            "another process took a core: ran on 1 thread (of 2) for 75 % of this process's stepping "
            "(summary.json threads_used; the result is the same)");
  summary.threads = 8;
  summary.threadsUsed = {{"8", 3.0}, {"7", 0.5}, {"6", 0.5}};
  EXPECT_NE(threadsShedWarning(summary).find("ran on as few as 6 threads (of 8) for 25 %"), std::string::npos);
  EXPECT_EQ(toJson(summary)["threads_used"]["6"], 0.5);
  EXPECT_EQ(summaryFromJson(toJson(summary)).threadsUsed, summary.threadsUsed);
}

}  // namespace
}  // namespace wiggle
