// SPDX-License-Identifier: MIT
#include "metrics/frame_id_set.h"

#include <gtest/gtest.h>

#include <string>

namespace rpt::metrics {
namespace {

TEST(FrameIdSet, RefusesRepeatedIdsBeforeAndAfterCompaction) {
  FrameIdSet ids;
  for (int i = 0; i < 5000; ++i) ASSERT_TRUE(ids.Insert("seq/" + std::to_string(i))) << i;
  EXPECT_EQ(ids.size(), 5000);
  for (const int i : {0, 1023, 1024, 4096, 4999}) EXPECT_FALSE(ids.Insert("seq/" + std::to_string(i))) << i;
  EXPECT_TRUE(ids.Insert("seq/5000"));
  EXPECT_TRUE(ids.Insert(""));
  EXPECT_FALSE(ids.Insert(""));
}

TEST(FrameIdSet, CountSharedAndMerge) {
  FrameIdSet a, b;
  for (int i = 0; i < 3000; ++i) a.Insert(std::to_string(i));
  for (int i = 2990; i < 4000; ++i) b.Insert(std::to_string(i));
  EXPECT_EQ(a.CountShared(b), 10);
  EXPECT_EQ(b.CountShared(a), 10);
  FrameIdSet c;
  for (int i = 3000; i < 4000; ++i) c.Insert(std::to_string(i));
  EXPECT_EQ(a.CountShared(c), 0);
  a.Merge(c);
  EXPECT_EQ(a.size(), 4000);
  EXPECT_FALSE(a.Insert("3500"));
  EXPECT_FALSE(a.Insert("17"));
  EXPECT_TRUE(a.Insert("4000"));
}

}  // namespace
}  // namespace rpt::metrics
