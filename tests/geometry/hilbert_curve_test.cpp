#include "geometry/hilbert_curve.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

namespace swarmagg {
namespace {

TEST(HilbertCurve, WalksTheFourByFourGridInTheCurvesOrder) {
  // Drawn by hand: the order-2 curve from the lower left to the lower right.
  const int expected[4][4] = {
      // x = 0, 1, 2, 3 at y = 0
      {0, 1, 14, 15},
      {3, 2, 13, 12},
      {4, 7, 8, 11},
      {5, 6, 9, 10},
  };
  for (std::uint32_t y = 0; y < 4; ++y) {
    for (std::uint32_t x = 0; x < 4; ++x) {
      EXPECT_EQ(hilbert_position(x, y, 2), static_cast<std::uint64_t>(expected[y][x]))
          << "cell (" << x << ", " << y << ")";
    }
  }
}

TEST(HilbertCurve, VisitsEveryCellOnceThroughNeighbouringCells) {
  constexpr int kOrder = 6;
  constexpr std::uint32_t kSide = 1u << kOrder;
  std::vector<int> cell_at(kSide * kSide, -1);
  for (std::uint32_t y = 0; y < kSide; ++y) {
    for (std::uint32_t x = 0; x < kSide; ++x) {
      const std::uint64_t position = hilbert_position(x, y, kOrder);
      ASSERT_LT(position, cell_at.size());
      ASSERT_EQ(cell_at[position], -1) << "two cells at position " << position;
      cell_at[position] = static_cast<int>(y * kSide + x);
    }
  }
  for (std::size_t k = 1; k < cell_at.size(); ++k) {
    const int dx = cell_at[k] % static_cast<int>(kSide) - cell_at[k - 1] % static_cast<int>(kSide);
    const int dy = cell_at[k] / static_cast<int>(kSide) - cell_at[k - 1] / static_cast<int>(kSide);
    EXPECT_EQ(std::abs(dx) + std::abs(dy), 1) << "positions " << k - 1 << " and " << k;
  }
}

TEST(HilbertCurve, TheLargestGridReachesItsLastPosition) {
  constexpr int kOrder = 31;
  constexpr std::uint32_t kLast = (1u << kOrder) - 1;
  EXPECT_EQ(hilbert_position(0, 0, kOrder), 0u);
  EXPECT_EQ(hilbert_position(kLast, 0, kOrder), (std::uint64_t{1} << 62) - 1);
}

}  // namespace
}  // namespace swarmagg
