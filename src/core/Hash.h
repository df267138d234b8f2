#pragma once
// 64-bit FNV-1a over raw bytes: the state hash of a run (summary.json "state_hash") and the
// checksum of checkpoint and bed files. Bit-exact by construction: it reads the doubles' bits.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace wiggle {

class Hasher {
 public:
  void addBytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      state_ ^= bytes[i];
      state_ *= 1099511628211ULL;
    }
  }
  template <class T>
  void add(const std::vector<T>& values) {
    addBytes(values.data(), values.size() * sizeof(T));
  }
  template <class T>
  void addValue(const T& value) {
    addBytes(&value, sizeof(T));
  }
  std::uint64_t value() const { return state_; }
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
    return text;
  }

 private:
  std::uint64_t state_ = 14695981039346656037ULL;
};

}  // namespace wiggle
