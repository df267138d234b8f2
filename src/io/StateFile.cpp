#include "io/StateFile.h"

#include <cstring>

#include "core/Error.h"
#include "core/Hash.h"
#include "io/AtomicFile.h"
#include "core/BinaryStream.h"

namespace wiggle {

namespace {
constexpr char kMagic[8] = {'W', 'I', 'G', 'G', 'L', 'E', '\x1a', '\n'};
constexpr std::size_t kKindSize = 16;
constexpr std::size_t kHeaderSize = sizeof kMagic + kKindSize + sizeof(std::uint32_t) + sizeof(std::uint64_t);

std::string paddedKind(const std::string& kind) {
  std::string k = kind.substr(0, kKindSize);
  k.resize(kKindSize, '\0');
  return k;
}
}  // namespace

void writeStateFile(const std::string& path, const std::string& kind, const std::string& payload) {
  BinaryWriter out;
  out.bytes().append(kMagic, sizeof kMagic);
  out.bytes().append(paddedKind(kind));
  out.value(kStateFormatVersion);
  out.value<std::uint64_t>(payload.size());
  out.bytes().append(payload);
  Hasher h;
  h.addBytes(out.bytes().data(), out.bytes().size());
  out.value(h.value());
  writeFileAtomically(path, out.bytes());
}

StatePayload readStateFile(const std::string& path, const std::string& kind) {
  return parseStateFile(readFile(path), path, kind);
}

bool isStateFile(const std::string& file) {
  return file.size() >= sizeof kMagic && std::memcmp(file.data(), kMagic, sizeof kMagic) == 0;
}

StatePayload parseStateFile(const std::string& file, const std::string& path, const std::string& kind) {
  if (!isStateFile(file)) throw Error(path + ": not a wiggle state file");
  if (file.size() < kHeaderSize + sizeof(std::uint64_t)) throw Error(path + " is truncated");
  if (file.compare(sizeof kMagic, kKindSize, paddedKind(kind)) != 0)
    throw Error(path + ": not a wiggle " + kind + " file");
  BinaryReader in(file.data() + sizeof kMagic + kKindSize, file.size() - sizeof kMagic - kKindSize, path);
  const auto version = in.value<std::uint32_t>();
  const auto size = in.value<std::uint64_t>();
  if (size != file.size() - kHeaderSize - sizeof(std::uint64_t)) throw Error(path + " is truncated or has trailing bytes");
  std::uint64_t stored;
  std::memcpy(&stored, file.data() + file.size() - sizeof stored, sizeof stored);
  Hasher h;
  h.addBytes(file.data(), file.size() - sizeof stored);
  if (h.value() != stored) throw Error(path + " fails its checksum (corrupt)");
  if (version < kOldestStateFormatVersion || version > kStateFormatVersion)
    throw Error(path + " was written by state format version " + std::to_string(version) + ", this wiggle reads " +
                std::to_string(kOldestStateFormatVersion) + " to " + std::to_string(kStateFormatVersion));
  return {file.substr(kHeaderSize, size), version};
}

}  // namespace wiggle
