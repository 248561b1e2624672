#include "geometry/hilbert_curve.hpp"

#include <utility>

namespace swarmagg {

// From the coarsest quadrant down: each level adds the quadrant's rank along the curve
// (lower left, upper left, upper right, lower right), then turns the cell's coordinates into
// that quadrant's frame, since the sub-curve in the two lower quadrants is the whole curve
// reflected on a diagonal.
std::uint64_t hilbert_position(std::uint32_t x, std::uint32_t y, int order) {
  const std::uint32_t side = std::uint32_t{1} << order;
  std::uint64_t position = 0;
  for (std::uint32_t half = side / 2; half > 0; half /= 2) {
    const std::uint32_t right = (x & half) ? 1 : 0;
    const std::uint32_t upper = (y & half) ? 1 : 0;
    position += std::uint64_t{half} * half * ((3 * right) ^ upper);
    if (upper == 0) {
      if (right == 1) {
        x = side - 1 - x;
        y = side - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return position;
}

}  // namespace swarmagg
