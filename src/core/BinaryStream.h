#pragma once
// Little helpers to serialise engine state into a byte buffer and read it back with bounds checks.
// Used by checkpoints and the bed cache; the file framing (magic, version, checksum) is in
// io/StateFile.h. Reading past the end throws wiggle::Error, so a truncated file is never trusted.
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "core/Error.h"

namespace wiggle {

class BinaryWriter {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&v);
    buffer_.append(p, sizeof(T));
  }
  template <class T>
  void array(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    value<std::uint64_t>(values.size());
    buffer_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  void string(const std::string& s) {
    value<std::uint64_t>(s.size());
    buffer_.append(s);
  }
  const std::string& bytes() const { return buffer_; }
  std::string& bytes() { return buffer_; }

 private:
  std::string buffer_;
};

class BinaryReader {
 public:
  // formatVersion: the layout version of the bytes, for readers of files whose layout grew
  // (io/StateFile.h); kLatestFormat when they are in the layout this program writes.
  static constexpr std::uint32_t kLatestFormat = 0xffffffffu;
  BinaryReader(const char* data, std::size_t size, std::string what, std::uint32_t formatVersion = kLatestFormat)
      : data_(data), size_(size), what_(std::move(what)), formatVersion_(formatVersion) {}

  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    need(sizeof(T));
    std::memcpy(&v, data_ + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  template <class T>
  std::vector<T> array(std::uint64_t maxCount = (1ULL << 34)) {
    const auto count = value<std::uint64_t>();
    if (count > maxCount || count > (size_ - pos_) / (sizeof(T) ? sizeof(T) : 1))
      throw Error(what_ + " is corrupt: an array length of " + std::to_string(count) +
                  " exceeds the file");
    std::vector<T> values(count);
    need(count * sizeof(T));
    if (count) std::memcpy(values.data(), data_ + pos_, count * sizeof(T));
    pos_ += count * sizeof(T);
    return values;
  }
  std::string string() {
    const auto count = value<std::uint64_t>();
    need(count);
    std::string s(data_ + pos_, count);
    pos_ += count;
    return s;
  }
  bool atEnd() const { return pos_ == size_; }
  const std::string& what() const { return what_; }
  std::uint32_t formatVersion() const { return formatVersion_; }

 private:
  void need(std::uint64_t n) const {
    if (n > size_ - pos_) throw Error(what_ + " is truncated");
  }
  const char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string what_;
  std::uint32_t formatVersion_;
};

}  // namespace wiggle
