// io/FileLock: the sweep directory's lock, taken and probed (flock locks conflict between open
// files, also within one process, so one process can play both sides).
#include <gtest/gtest.h>

#include <string>

#include "core/Error.h"
#include "io/FileLock.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

TEST(FileLock, ProbeSeesOnlyAnExclusiveHolder) {
  const testing_support::ScratchDir dir("filelock");
  const std::string path = dir / ".sweep.lock";
  EXPECT_FALSE(FileLock::heldExclusivelyElsewhere(path));  // no file: nobody
  {
    const FileLock whole(path, /*shared=*/false, /*wait=*/false);
    EXPECT_TRUE(FileLock::heldExclusivelyElsewhere(path));
    const std::string refused = testing_support::errorOf([&] { FileLock second(path, true, false); });
    EXPECT_NE(refused.find("another wiggle sweep is running in"), std::string::npos) << refused;
  }
  EXPECT_FALSE(FileLock::heldExclusivelyElsewhere(path));  // released with its holder
  {
    const FileLock oneCase(path, /*shared=*/true, /*wait=*/false);
    const FileLock another(path, true, false);  // one-case runs share it
    EXPECT_FALSE(FileLock::heldExclusivelyElsewhere(path));
    EXPECT_NE(testing_support::errorOf([&] { FileLock whole(path, false, false); }), "(no error)");
  }
}

}  // namespace
}  // namespace wiggle
