#pragma once
// Bit-for-bit equality of doubles: what "the same bytes" means for a number (0.0 and
// -0.0 differ, a NaN equals itself).

#include <bit>
#include <cstdint>

namespace crux::testing {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace crux::testing
