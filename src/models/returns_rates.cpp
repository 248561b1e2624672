#include "models/returns_rates.hpp"

#include "models/return_probability.hpp"

namespace swarmagg {

namespace {

void keep_leavers_that_do_not_return(const WorldSpec& world, std::vector<double>& loss) {
  for (std::size_t i = 2; i < loss.size(); ++i)
    loss[i] *= 1.0 - return_probability(world, static_cast<int>(i));
}

}  // namespace

SoysalRates returns_soysal_rates(const WorldSpec& world) {
  SoysalRates rates = soysal_rates(world, world.model.leaving);
  keep_leavers_that_do_not_return(world, rates.leave);
  return rates;
}

BayindirRates returns_bayindir_rates(const WorldSpec& world) {
  BayindirRates rates = bayindir_rates(world, world.model.creation);
  keep_leavers_that_do_not_return(world, rates.loss);
  return rates;
}

}  // namespace swarmagg
