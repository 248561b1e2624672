#pragma once
// The variants a world's model writes (docs/models.md), each as a PendingVariant computed
// while its rows are written: the creation variants (Bayindir) or leaving variants (Soysal),
// `returns` where aggregates lose leavers, `measured` from measured terms, and for Bayindir
// each also as seeded stochastic replicates (model.stochastic_replicates).
#include <map>
#include <vector>

#include "config/world_spec.hpp"
#include "models/measured_terms.hpp"
#include "models/partitions.hpp"
#include "models/pending_variant.hpp"

namespace swarmagg {

inline constexpr CreationVariant kCreationVariants[] = {CreationVariant::Original,
                                                        CreationVariant::Collision};

// The returns variant matters only where aggregates lose leavers.
bool knows_returns(const WorldSpec& world);

// `start`: the aggregate counts the models start from (models/initial_state.hpp).
std::vector<PendingVariant> bayindir_variants(const WorldSpec& world, const MeasuredTerms* measured,
                                              const std::vector<double>& start);
// `start_partitions`: the sampled partitions of a placement start, when there is one.
std::vector<PendingVariant> soysal_variants(const WorldSpec& world, const MeasuredTerms* measured,
                                            const std::vector<double>& start,
                                            const std::map<Partition, double>* start_partitions);

}  // namespace swarmagg
