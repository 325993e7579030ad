// src/simd/target.h: our names for Highway's targets and the restriction FFCOMPAT_SIMD applies.
#include "simd/target.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace ffc::simd {
namespace {

TEST(SimdTarget, ScalarIsAlwaysThereAndLast) {
  const auto targets = available();
  ASSERT_FALSE(targets.empty());
  EXPECT_EQ(targets.back(), "scalar");
}

TEST(SimdTarget, RestrictNarrowsAndLifts) {
  const std::string best = current();
  ASSERT_TRUE(restrict("scalar"));
  EXPECT_EQ(current(), "scalar");
  EXPECT_EQ(available(), std::vector<std::string>{"scalar"});
  ASSERT_TRUE(restrict(""));
  EXPECT_EQ(current(), best);
  for (const std::string& t : available()) {
    ASSERT_TRUE(restrict(t)) << t;
    EXPECT_EQ(current(), t);
  }
  restrict("");
}

TEST(SimdTarget, UnknownNamesAreRefused) {
  EXPECT_FALSE(restrict("avx1024"));
  EXPECT_EQ(target_bit("avx1024"), 0);
  EXPECT_NE(target_bit("avx2"), 0);
}

TEST(SimdTarget, ARefusedRequestKeepsTheRestrictionInForce) {
  ASSERT_TRUE(restrict("scalar"));
  EXPECT_FALSE(restrict("avx1024"));
  EXPECT_EQ(current(), "scalar");
  restrict("");
}

}  // namespace
}  // namespace ffc::simd
