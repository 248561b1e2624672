#include "reproduce/figure_result.hpp"

#include <stdexcept>

namespace swarmagg {

const std::vector<VariantError>* model_errors(const FigureResult& result) {
  if (result.noa) return &result.noa->errors;
  if (result.partitions) return &result.partitions->errors;
  return nullptr;
}

double replicates_spread(const FigureResult& result) {
  if (result.noa) return result.noa->spread;
  if (result.partitions) return result.partitions->spread;
  return 0.0;
}

double variant_error(const std::vector<VariantError>& errors, const std::string& variant) {
  for (const VariantError& e : errors) {
    if (e.variant == variant) return e.error;
  }
  throw std::runtime_error("no error computed for model variant " + variant);
}

}  // namespace swarmagg
