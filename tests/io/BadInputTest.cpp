// The corpus of bad inputs in tests/data/bad_inputs: each file's first line says which words its
// one-line error must contain ("# expect: ..."); files without that line must be accepted.
// Every file goes through what `wiggle run` does before it makes a bed: parse, validate, build the
// intruder, check the geometry.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/Config.h"
#include "scenario/Experiment.h"
#include "scenario/Shape.h"

namespace wiggle {
namespace {

void checkCase(const std::string& text, const std::string& name) {
  const RunConfig config = parseRunConfig(text, name);
  checkGeometry(config, makeClump(config.intruder, config.grains.massModel, 1.0));
}

TEST(BadInput, EveryFileOfTheCorpusGetsItsOneLineError) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(WIGGLE_TEST_DATA) + "/bad_inputs")) {
    const std::string path = entry.path().string();
    const std::string text = readFile(path);
    const std::string firstLine = text.substr(0, text.find('\n'));
    const std::string marker = "# expect: ";
    ++files;
    if (text.empty()) {
      EXPECT_NO_THROW(checkCase(text, path)) << path << ": an empty file is the default case";
      continue;
    }
    try {
      checkCase(text, path);
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
  EXPECT_GE(files, 25);
}

}  // namespace
}  // namespace wiggle
