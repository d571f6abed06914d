#include "climbing/posture_cache.hpp"

#include <gtest/gtest.h>

#include "common/checkpoint_stream.hpp"

namespace crux {
namespace {

// A posture told apart from others by its root.
Posture posture_at(double z) { return standing_posture(Eigen::Vector3d(0.3, 0.6, z)); }

TEST(PostureCache, EmptyCacheKnowsNothing) {
  const PostureCache cache;
  EXPECT_EQ(cache.reached(7), nullptr);
  EXPECT_FALSE(cache.known_unreachable(7));
  EXPECT_EQ(cache.reached_count(), 0u);
  EXPECT_EQ(cache.unreachable_count(), 0u);
}

TEST(PostureCache, ReturnsTheStoredPostureOfEachConfiguration) {
  PostureCache cache;
  Posture first = posture_at(1.0);
  first[10] = 0.25;  // a joint angle too, not only the root
  cache.store_reached(11, first);
  cache.store_reached(12, posture_at(1.5));
  ASSERT_NE(cache.reached(11), nullptr);
  ASSERT_NE(cache.reached(12), nullptr);
  EXPECT_EQ(*cache.reached(11), first);
  EXPECT_EQ(*cache.reached(12), posture_at(1.5));
  EXPECT_EQ(cache.reached(13), nullptr);
  EXPECT_EQ(cache.reached_count(), 2u);
  EXPECT_FALSE(cache.known_unreachable(11)) << "reached is not unreachable";
  EXPECT_EQ(cache.unreachable_count(), 0u);
}

TEST(PostureCache, StoresACopyNotAReference) {
  PostureCache cache;
  Posture posture = posture_at(1.0);
  cache.store_reached(5, posture);
  posture[0] = 99.0;
  EXPECT_EQ((*cache.reached(5))[0], 0.3);
}

TEST(PostureCache, UnreachableVerdictsAreRememberedApart) {
  PostureCache cache;
  cache.store_unreachable(21);
  cache.store_unreachable(22);
  cache.store_unreachable(21);  // a second verdict on the same configuration
  EXPECT_TRUE(cache.known_unreachable(21));
  EXPECT_TRUE(cache.known_unreachable(22));
  EXPECT_FALSE(cache.known_unreachable(23));
  EXPECT_EQ(cache.unreachable_count(), 2u) << "counted once";
  EXPECT_EQ(cache.reached(21), nullptr) << "no posture for an unreachable configuration";
  EXPECT_EQ(cache.reached_count(), 0u);
}

TEST(PostureCache, CodesUseTheFull64Bits) {
  // Configuration codes grow as (n + 1)^4 and need not fit 32 bits.
  PostureCache cache;
  const std::uint64_t high = (std::uint64_t{1} << 40) + 3, low = 3;
  cache.store_reached(high, posture_at(2.0));
  cache.store_unreachable(low);
  EXPECT_NE(cache.reached(high), nullptr);
  EXPECT_EQ(cache.reached(low), nullptr);
  EXPECT_FALSE(cache.known_unreachable(high));
  EXPECT_TRUE(cache.known_unreachable(low));
}

TEST(PostureCache, PointersStayValidAsTheCacheGrows) {
  // ConfigurationReacher hands out these pointers as valid for its lifetime while it
  // keeps solving new configurations: rehashing must not move stored postures.
  PostureCache cache;
  cache.store_reached(0, posture_at(0.5));
  const Posture* kept = cache.reached(0);
  for (std::uint64_t c = 1; c < 2000; ++c) cache.store_reached(c, posture_at(static_cast<double>(c)));
  EXPECT_EQ(cache.reached(0), kept);
  EXPECT_EQ(*kept, posture_at(0.5));
  EXPECT_EQ(cache.reached_count(), 2000u);
}

TEST(PostureCache, ACheckpointRestoresEveryVerdict) {
  PostureCache cache;
  Posture p = Posture::Zero();
  p[5] = 0.125;
  cache.store_reached(12, p);
  cache.store_reached(~0ULL, Posture::Constant(-2.0));
  cache.store_unreachable(7);
  CheckpointWriter out;
  cache.save_state(out);
  const std::string bytes = out.take();
  PostureCache restored;
  restored.store_unreachable(99);  // replaced
  CheckpointReader in(bytes, "test");
  restored.load_state(in);
  EXPECT_TRUE(in.at_end());
  ASSERT_NE(restored.reached(12), nullptr);
  EXPECT_EQ(*restored.reached(12), p);
  EXPECT_EQ(*restored.reached(~0ULL), Posture::Constant(-2.0));
  EXPECT_TRUE(restored.known_unreachable(7));
  EXPECT_FALSE(restored.known_unreachable(99));
  EXPECT_EQ(restored.reached_count(), 2u);
}

}  // namespace
}  // namespace crux
