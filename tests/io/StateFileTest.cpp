// State-file framing (io/StateFile.h): every truncation and every single-bit flip of a file is
// refused with a one-line error naming the file, as are foreign kinds and other format versions.
// FNV-1a 64 steps are bijections of the state for a given byte, so a change confined to one byte
// always changes the sum: the single-bit sweep below is exhaustive, not a sample.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "core/Error.h"
#include "core/Hash.h"
#include "io/AtomicFile.h"
#include "io/StateFile.h"

namespace wiggle {
namespace {

std::string sampleFile() {
  const std::string path = (std::filesystem::temp_directory_path() / ("wiggle-statefile-" + std::to_string(::getpid()))).string();
  std::string payload;
  for (int i = 0; i < 200; ++i) payload += static_cast<char>(i * 37 + 11);
  writeStateFile(path, "checkpoint", payload);
  std::string file = readFile(path);
  std::filesystem::remove(path);
  return file;
}

// The error for these bytes, or "" when they are accepted.
std::string refusal(const std::string& file, const std::string& kind = "checkpoint") {
  try {
    parseStateFile(file, "f.bin", kind);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(StateFile, RoundTripsItsPayload) {
  const std::string file = sampleFile();
  const StatePayload payload = parseStateFile(file, "f.bin", "checkpoint");
  EXPECT_EQ(payload.bytes.size(), 200u);
  EXPECT_EQ(payload.version, kStateFormatVersion);
  EXPECT_EQ(refusal(file), "");
}

TEST(StateFile, EveryTruncationIsRefused) {
  const std::string file = sampleFile();
  for (std::size_t n = 0; n < file.size(); ++n) {
    const std::string message = refusal(file.substr(0, n));
    ASSERT_NE(message, "") << "accepted after truncation to " << n << " bytes";
    EXPECT_EQ(message.find('\n'), std::string::npos);
    EXPECT_EQ(message.rfind("f.bin", 0), 0u) << message;
  }
  EXPECT_NE(refusal(file + "x").find("trailing bytes"), std::string::npos);
}

TEST(StateFile, EverySingleBitFlipIsRefused) {
  const std::string file = sampleFile();
  int flips = 0;
  for (std::size_t byte = 0; byte < file.size(); ++byte)
    for (int bit = 0; bit < 8; ++bit) {
      std::string bad = file;
      bad[byte] = static_cast<char>(bad[byte] ^ (1 << bit));
      ASSERT_NE(refusal(bad), "") << "accepted with byte " << byte << " bit " << bit << " flipped";
      ++flips;
    }
  EXPECT_EQ(flips, static_cast<int>(8 * file.size()));
}

// The file with another format version written in, and its checksum made right again.
std::string withVersion(std::string file, std::uint32_t version) {
  std::memcpy(file.data() + 24, &version, sizeof version);
  Hasher h;
  h.addBytes(file.data(), file.size() - 8);
  const std::uint64_t sum = h.value();
  std::memcpy(file.data() + file.size() - 8, &sum, sizeof sum);
  return file;
}

TEST(StateFile, ForeignKindsAndOtherVersionsAreRefused) {
  const std::string file = sampleFile();
  EXPECT_NE(refusal(file, "bed").find("not a wiggle bed file"), std::string::npos);
  EXPECT_NE(refusal("#!/bin/sh\necho hello\n").find("not a wiggle state file"), std::string::npos);
  // Versions outside the range read, with a correct checksum: refused by version, not by checksum.
  for (const std::uint32_t version : {kStateFormatVersion + 1, kOldestStateFormatVersion - 1}) {
    const std::string other = withVersion(file, version);
    EXPECT_NE(refusal(other).find("was written by state format version " + std::to_string(version)), std::string::npos)
        << refusal(other);
  }
}

TEST(StateFile, OlderVersionsStillReadAreReadWithTheirVersion) {
  for (std::uint32_t version = kOldestStateFormatVersion; version <= kStateFormatVersion; ++version) {
    const StatePayload payload = parseStateFile(withVersion(sampleFile(), version), "f.bin", "checkpoint");
    EXPECT_EQ(payload.version, version);
    EXPECT_EQ(payload.bytes.size(), 200u);
  }
}

}  // namespace
}  // namespace wiggle
