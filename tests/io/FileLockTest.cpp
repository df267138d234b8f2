// io/FileLock: the sweep directory's lock, taken and probed (flock locks conflict between open
// files, also within one process, so one process can play both sides).
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "core/Error.h"
#include "io/FileLock.h"
#include "support/TestSupport.h"

namespace wiggle {
namespace {

TEST(FileLock, ProbeTellsWhoHoldsIt) {
  using Holders = FileLock::Holders;
  const testing_support::ScratchDir dir("filelock");
  const std::string path = dir / ".sweep.lock";
  EXPECT_EQ(FileLock::holders(path), Holders::None);  // no file: nobody
  {
    const FileLock whole(path, /*shared=*/false, /*wait=*/false, "another sweep runs here");
    EXPECT_EQ(FileLock::holders(path), Holders::Exclusive);
    const std::string refused =
        testing_support::errorOf([&] { FileLock second(path, true, false, "another sweep runs here"); });
    EXPECT_EQ(refused, "another sweep runs here (" + path + " is locked)");
  }
  EXPECT_EQ(FileLock::holders(path), Holders::None);  // released with its holder
  {
    const FileLock oneCase(path, /*shared=*/true, /*wait=*/false, "");
    EXPECT_EQ(FileLock::holders(path), Holders::Shared);
    const FileLock another(path, true, false, "");  // one-case runs share it
    EXPECT_EQ(FileLock::holders(path), Holders::Shared);
    EXPECT_NE(testing_support::errorOf([&] { FileLock whole(path, false, false, "busy"); }), "(no error)");
  }
  EXPECT_EQ(FileLock::holders(path), Holders::None);  // the probes kept nothing
  const FileLock again(path, false, false, "busy");
}

TEST(FileLock, AMovedLockIsHeldOnceAndReleasedOnce) {
  const testing_support::ScratchDir dir("filelock-move");
  const std::string path = dir / "a.lock";
  {
    FileLock first(path, false, false, "busy");
    const FileLock moved(std::move(first));
    EXPECT_EQ(FileLock::holders(path), FileLock::Holders::Exclusive);
  }
  EXPECT_EQ(FileLock::holders(path), FileLock::Holders::None);
}

}  // namespace
}  // namespace wiggle
