#pragma once
// The binary form of a long run's checkpoint (experiments/run_checkpoint.hpp): numbers
// written as their exact bytes (little-endian machines, as every build of crux targets),
// so a resumed run continues from bit-identical state. Each class that a run carries
// writes and reads its own state with these.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace crux {

class CheckpointWriter {
 public:
  template <typename T>
  requires std::is_trivially_copyable_v<T>
  void value(const T& v) { bytes_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  template <typename T>
  requires std::is_trivially_copyable_v<T>
  void values(const T* data, std::size_t count) {
    value<std::uint64_t>(count);
    // An empty vector's data() may be null, which memcpy must never see, even for 0 bytes.
    if (data != nullptr) bytes_.append(reinterpret_cast<const char*>(data), count * sizeof(T));
  }
  template <typename T>
  void vector(const std::vector<T>& v) {
    values(v.data(), v.size());
  }
  void text(std::string_view s) { values(s.data(), s.size()); }

  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a CheckpointWriter wrote; InputError(source, ...) when the bytes end early
// or a count is impossible (a truncated or foreign file).
class CheckpointReader {
 public:
  CheckpointReader(std::string_view bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}

  template <typename T>
  requires std::is_trivially_copyable_v<T> T value() {
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  template <typename T>
  requires std::is_trivially_copyable_v<T> std::vector<T> vector() {
    const std::uint64_t count = value<std::uint64_t>();
    if (count > (bytes_.size() - at_) / sizeof(T)) fail();
    std::vector<T> v(count);
    if (count > 0) std::memcpy(v.data(), take(count * sizeof(T)), count * sizeof(T));
    return v;
  }
  std::string text() {
    const std::vector<char> chars = vector<char>();
    return {chars.begin(), chars.end()};
  }
  // A bool written as one byte: anything but 0 or 1 is not crux's.
  bool flag() {
    const auto byte = value<std::uint8_t>();
    if (byte > 1) fail();
    return byte == 1;
  }
  bool at_end() const { return at_ == bytes_.size(); }
  [[noreturn]] void fail() const;

 private:
  const char* take(std::size_t n) {
    if (n > bytes_.size() - at_) fail();
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
  std::string source_;
};

// The keys of a hash map in increasing order: a checkpoint does not depend on hashing.
template <typename Map>
std::vector<typename Map::key_type> sorted_keys(const Map& map) {
  std::vector<typename Map::key_type> keys;
  keys.reserve(map.size());
  for (const auto& entry : map) keys.push_back(entry.first);
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace crux
