#include "plot/drawn_points.hpp"

namespace swarmagg {

namespace {

// Every `stride`-th of `count` points from the first, and the last.
std::size_t points_drawn(std::size_t count, std::size_t stride) {
  const std::size_t last = count - 1;
  return last / stride + 1 + (last % stride != 0 ? 1 : 0);
}

}  // namespace

std::vector<std::size_t> drawn_indices(std::size_t count) {
  std::vector<std::size_t> indices;
  if (count == 0) return indices;
  std::size_t stride = 1;
  while (points_drawn(count, stride) > kMostDrawnPoints) ++stride;
  for (std::size_t i = 0; i < count; i += stride) indices.push_back(i);
  if (indices.back() != count - 1) indices.push_back(count - 1);
  return indices;
}

StepSeries drawn_part(const StepSeries& series) {
  StepSeries drawn;
  for (const std::size_t i : drawn_indices(series.steps.size())) {
    drawn.steps.push_back(series.steps[i]);
    drawn.times.push_back(series.times[i]);
    drawn.values.push_back(series.values[i]);
  }
  return drawn;
}

std::vector<ModelCurve> drawn_part(const std::vector<ModelCurve>& curves) {
  std::vector<ModelCurve> drawn;
  for (const ModelCurve& curve : curves) {
    ModelCurve& part = drawn.emplace_back(ModelCurve{curve.variant, {}, {}});
    for (const std::size_t i : drawn_indices(curve.x.size())) {
      part.x.push_back(curve.x[i]);
      part.y.push_back(curve.y[i]);
    }
  }
  return drawn;
}

}  // namespace swarmagg
