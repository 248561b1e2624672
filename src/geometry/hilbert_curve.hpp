#pragma once
// The position of a cell along a Hilbert curve through a square grid of 2^order x 2^order
// cells. Consecutive positions are neighbouring cells, and every run of positions covers a
// compact patch of the grid, so that numbering things in this order keeps what is near in
// space near in number on every scale (a numbering by rows keeps only one row together).
#include <cstdint>

namespace swarmagg {

// Cells x, y in [0, 2^order), order at most 31; the result is in [0, 4^order).
std::uint64_t hilbert_position(std::uint32_t x, std::uint32_t y, int order);

}  // namespace swarmagg
