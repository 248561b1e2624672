#include "models/returns_rates.hpp"

#include "models/return_probability.hpp"

namespace swarmagg {

namespace {

// A leave law over the periphery counts rim leavers; one over all members counts inside
// members too, who come back (models/return_probability.hpp).
void keep_leavers_that_do_not_return(const WorldSpec& world, std::vector<double>& loss,
                                     bool over_all_members) {
  for (std::size_t i = 2; i < loss.size(); ++i) {
    const int size = static_cast<int>(i);
    loss[i] *= 1.0 - (over_all_members ? attempt_return_probability(world, size)
                                       : return_probability(world, size));
  }
}

}  // namespace

SoysalRates returns_soysal_rates(const WorldSpec& world) {
  SoysalRates rates = soysal_rates(world, world.model.leaving);
  keep_leavers_that_do_not_return(world, rates.leave,
                                  world.model.leaving == LeavingVariant::Original);
  return rates;
}

BayindirRates returns_bayindir_rates(const WorldSpec& world) {
  BayindirRates rates = bayindir_rates(world, world.model.creation);
  keep_leavers_that_do_not_return(world, rates.loss, false);  // p min(m, periph(m))
  return rates;
}

}  // namespace swarmagg
