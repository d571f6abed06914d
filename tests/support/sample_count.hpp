#pragma once
// How many random samples a sampling test draws. A sanitizer finds a memory or undefined-
// behaviour error on the first pass through a path, not on the thousandth, while the same
// path runs ten to thirty times slower under it; so the sanitized build draws a tenth of
// the samples (at least one) and the release build draws them all, and each claim is
// checked in full in the release build (docs/TESTING.md, "Labels").

namespace crux::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

constexpr int sample_count(int full) { return kSanitized ? (full >= 10 ? full / 10 : 1) : full; }

}  // namespace crux::testing
