#pragma once
// Framing of binary state files (checkpoints, cached beds): a versioned header and a checksum, so
// that a truncated, bit-flipped or foreign file is detected and never loaded.
//
// Layout: magic "WIGGLE\x1a\n" (8 bytes) | kind (16 bytes, NUL padded, e.g. "checkpoint", "bed") |
// format version (u32) | payload size (u64) | payload | FNV-1a 64 of everything before (u64).
#include <cstdint>
#include <string>

namespace wiggle {

// Bump when the payload layout of any state file changes. Files from kOldestStateFormatVersion on
// are read (the readers ask BinaryReader::formatVersion() what the layout holds); older ones are
// refused. Version 3 added the contact law (World's parameters); version 2 files are Hertz. Version 4
// added the intruder's mass shares (its contact mass); earlier files have 1 share (the body's mass).
// Version 5 added whether the intruder may turn, and its turn; earlier files hold intruders that do not.
// Version 6 added a checkpoint's turn at each trajectory sample (RunState::spins).
constexpr std::uint32_t kStateFormatVersion = 6;
constexpr std::uint32_t kOldestStateFormatVersion = 2;

// A state file's payload and the format version it was written in.
struct StatePayload {
  std::string bytes;
  std::uint32_t version;
};

void writeStateFile(const std::string& path, const std::string& kind, const std::string& payload);
// The payload; throws wiggle::Error ("<path>: not a wiggle <kind> file", "... is truncated",
// "... fails its checksum", "... was written by format version N, this wiggle reads M to K").
StatePayload readStateFile(const std::string& path, const std::string& kind);
// Whether a file's bytes start as a wiggle state file does (its magic): to tell one from another format.
bool isStateFile(const std::string& file);
// The same checks on a file's bytes already in memory; `name` starts every error message.
StatePayload parseStateFile(const std::string& file, const std::string& name, const std::string& kind);

}  // namespace wiggle
