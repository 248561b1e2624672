#include "models/model_series.hpp"

namespace swarmagg {

void add_size_distribution(std::vector<TidyValue>& extra, std::int64_t step,
                           const std::vector<double>& by_size) {
  for (std::size_t m = 2; m < by_size.size(); ++m) {
    if (by_size[m] < kNegligibleAggregates) continue;
    extra.push_back({kAggregatesOfSize + std::to_string(m), step, by_size[m]});
  }
}

}  // namespace swarmagg
