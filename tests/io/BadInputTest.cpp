// The corpora of bad inputs in tests/data/bad_inputs (run configs) and tests/data/bad_sweeps (sweep
// files): each file's first line says which words its one-line error must contain
// ("# expect: ..."); an empty file must be accepted (it is the default case). Every file goes
// through what `wiggle run` / `wiggle sweep` do before a bed is made: parse, validate, build the
// intruder, check the geometry (for a sweep, of every case). None may crash, hang or allocate
// without bound; the ASan+UBSan build (CI) and the fuzz targets (tools/fuzz.sh) watch for that.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "io/SweepSpec.h"
#include "scenario/run/Experiment.h"

namespace wiggle {
namespace {

// Returns the number of files checked.
int checkCorpus(const std::string& dir, const std::function<void(const std::string&, const std::string&)>& check) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(WIGGLE_TEST_DATA) + "/" + dir)) {
    const std::string path = entry.path().string();
    const std::string text = readFile(path);
    const std::string firstLine = text.substr(0, text.find('\n'));
    const std::string marker = "# expect: ";
    ++files;
    if (text.empty()) {
      EXPECT_NO_THROW(check(text, path)) << path << ": an empty file is the default case";
      continue;
    }
    try {
      check(text, path);
      ADD_FAILURE() << path << " was accepted";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << path << ": not one line: " << message;
      if (firstLine.rfind(marker, 0) == 0) {
        EXPECT_NE(message.find(firstLine.substr(marker.size())), std::string::npos)
            << path << ": got '" << message << "'";
      }
    }
  }
  return files;
}

TEST(BadInput, EveryRunConfigOfTheCorpusGetsItsOneLineError) {
  const int files = checkCorpus("bad_inputs", [](const std::string& text, const std::string& path) {
    prepareCase(parseRunConfig(text, path)).clump;
  });
  EXPECT_GE(files, 50);
}

TEST(BadInput, EverySweepFileOfTheCorpusGetsItsOneLineError) {
  const int files = checkCorpus("bad_sweeps", [](const std::string& text, const std::string& path) {
    const SweepSpec spec = parseSweepSpec(text, path);
    // `wiggle sweep` records a case failing these checks as failed in results.csv, with this message.
    for (const SweepCase& c : spec.cases) prepareCase(c.config).clump;
  });
  EXPECT_GE(files, 24);
}

}  // namespace
}  // namespace wiggle
