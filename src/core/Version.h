#pragma once
// What built this program: the release version (CMake's project version) and the git revision of
// the source tree it was built from, for --version, log.txt and summary.json.
#include <string>

namespace wiggle {

// "a1b2c3d4e5f6", with "-dirty" when the tree had uncommitted changes; "unknown" when it was not
// built from a git checkout. Defined in a file generated at build time (cmake/GitRevision.cmake).
const char* gitRevision();

// "0.1.0 (git a1b2c3d4e5f6)".
inline std::string versionText() { return std::string(WIGGLE_VERSION) + " (git " + gitRevision() + ")"; }

}  // namespace wiggle
