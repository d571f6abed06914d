#pragma once
// Named, counter-based random streams: common random numbers that hold between paired
// runs. A draw is a pure function of (run seed, stream name, index, draw), where the
// index is usually the iteration; nothing is consumed, so one consumer's draws never
// shift another's, and two runs that meet the same situation at the same iteration see
// the same draws however differently they got there.

#include <cstdint>
#include <string_view>

#include "common/random.hpp"

namespace crux {

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::string_view name) : key_(derive_seed(seed, name_hash(name))) {}

  // 64 random bits for (index, draw).
  std::uint64_t bits(std::uint64_t index, std::uint64_t draw) const {
    return mix(mix(key_ + 0x9E3779B97F4A7C15ULL * (index + 1)) ^ (0xD1B54A32D192ED03ULL * (draw + 1)));
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform(std::uint64_t index, std::uint64_t draw) const {
    return static_cast<double>(bits(index, draw) >> 11) * 0x1.0p-53;
  }

  // Integer in [0, n), n > 0, by Lemire's multiply-shift: a pure function needs no
  // rejection loop, and the bias (below n / 2^64) is far beneath anything measurable.
  std::uint64_t below(std::uint64_t n, std::uint64_t index, std::uint64_t draw) const {
    return static_cast<std::uint64_t>((static_cast<Wide>(bits(index, draw)) * n) >> 64);
  }

 private:
  __extension__ using Wide = unsigned __int128;  // GCC's and Clang's 128-bit integer

  static constexpr std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  // FNV-1a 64: stable across compilers, unlike std::hash.
  static constexpr std::uint64_t name_hash(std::string_view name) {
    std::uint64_t h = 0xCBF29CE484222325ULL;
    for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001B3ULL;
    return h;
  }

  std::uint64_t key_;
};

}  // namespace crux
