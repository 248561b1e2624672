#include "core/counted.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

TEST(Counted, IsSingularForOneOnly) {
  EXPECT_EQ(counted(1, "replicate"), "1 replicate");
  EXPECT_EQ(counted(0, "run"), "0 runs");
  EXPECT_EQ(counted(4, "thread"), "4 threads");
}

}  // namespace
}  // namespace swarmagg
