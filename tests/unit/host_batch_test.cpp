#include "app/lab/host_batch.h"

#include <gtest/gtest.h>

namespace shadelab {

// What a lab keeps across hosts goes when the last open batch closes, not before, and nothing is
// kept outside one (tests/gl/lab_lifecycle_test.cpp weighs the surface lab's meshes so).
TEST(HostBatch, WorkKeptInABatchGoesWhenTheLastOneCloses) {
  static int releases = 0;  // registered once for the process, as a lab does
  static const bool registered = [] {
    HostBatch::onClose([] { ++releases; });
    return true;
  }();
  ASSERT_TRUE(registered);
  const int before = releases;
  EXPECT_FALSE(HostBatch::open());
  {
    const HostBatch outer;
    EXPECT_TRUE(HostBatch::open());
    {
      const HostBatch inner;  // a Check's step inside a grading run
      EXPECT_TRUE(HostBatch::open());
    }
    EXPECT_TRUE(HostBatch::open()) << "an inner batch closed the outer one";
    EXPECT_EQ(releases, before) << "work let go while a batch was still open";
  }
  EXPECT_FALSE(HostBatch::open());
  EXPECT_EQ(releases, before + 1);
}

// A memo makes each key's value once while a batch is open, afresh outside one, and forgets it
// when the last batch closes.
TEST(HostBatch, AMemoMakesAValueOncePerBatch) {
  static BatchMemo<int, int> memo;
  int made = 0;
  const auto make = [&] { return ++made; };
  EXPECT_EQ(memo.get(1, make), 1);
  EXPECT_EQ(memo.get(1, make), 2) << "outside a batch nothing is kept";
  {
    const HostBatch batch;
    EXPECT_EQ(memo.get(1, make), 3);
    EXPECT_EQ(memo.get(1, make), 3);
    EXPECT_EQ(memo.get(2, make), 4);
  }
  const HostBatch next;
  EXPECT_EQ(memo.get(1, make), 5) << "the closed batch's values were let go";
}

}  // namespace shadelab
