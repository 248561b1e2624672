#include "models/noise_floor.hpp"

#include <cmath>
#include <span>
#include <stdexcept>

#include "models/bayindir_expected.hpp"
#include "models/bayindir_stochastic.hpp"
#include "models/binomial_draw.hpp"

namespace swarmagg {

namespace {

// Replicates of one batch use indices batch * replicates + k, so batches never share draws.
std::uint64_t replicate_index(int batch, int replicates, int k) {
  return static_cast<std::uint64_t>(batch) * static_cast<std::uint64_t>(replicates) +
         static_cast<std::uint64_t>(k);
}

int draw_state(const Eigen::VectorXd& distribution, double u) {
  double cumulative = 0.0;
  for (Eigen::Index i = 0; i < distribution.size(); ++i) {
    cumulative += distribution(i);
    if (u < cumulative) return static_cast<int>(i);
  }
  return static_cast<int>(distribution.size()) - 1;
}

// The next state from `state`, by its off-diagonal rates (u in [0, 1) times the exit rate).
int next_state(const Generator& generator, int state, double target) {
  int last = state;
  for (Generator::InnerIterator entry(generator, state); entry; ++entry) {
    if (entry.col() == state) continue;
    last = static_cast<int>(entry.col());
    target -= entry.value();
    if (target < 0.0) return last;
  }
  return last;  // rounding: the last target
}

}  // namespace

std::uint64_t noise_floor_stream(const std::string& variant) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : variant) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash | (1ull << 63);  // apart from the small stream numbers the model variants use
}

Eigen::VectorXd chain_time_fractions(const PartitionChain& chain, const ChainRun& run,
                                     std::uint64_t seed, std::uint64_t replicate,
                                     std::uint64_t stream) {
  const auto n = static_cast<Eigen::Index>(chain.states.size());
  Eigen::VectorXd time = Eigen::VectorXd::Zero(n);
  if (run.steps <= 0) return time;
  UniformStream uniforms(CounterRng::for_replicate(seed, replicate), 0, stream);
  const double end = static_cast<double>(run.steps);
  double now = static_cast<double>(std::min(run.start_step, run.steps));
  time(chain.all_free) += now;
  int state = draw_state(run.start, uniforms.next());
  while (now < end) {
    const double exit_rate = -chain.generator.coeff(state, state);
    const double hold = exit_rate > 0.0 ? -std::log(1.0 - uniforms.next()) / exit_rate : end;
    time(state) += std::min(hold, end - now);
    now += hold;
    if (now < end) state = next_state(chain.generator, state, uniforms.next() * exit_rate);
  }
  return time / end;
}

double partition_noise_floor(const PartitionChain& chain, const ChainRun& run,
                             const Eigen::VectorXd& run_average, int replicates, std::uint64_t seed,
                             std::uint64_t stream, int batches) {
  if (replicates < 1 || batches < 1) throw std::invalid_argument("noise floor: no replicates");
  double sum = 0.0;
  for (int batch = 0; batch < batches; ++batch) {
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(run_average.size());
    for (int k = 0; k < replicates; ++k)
      mean += chain_time_fractions(chain, run, seed, replicate_index(batch, replicates, k), stream);
    mean /= replicates;
    sum += 0.5 * (mean - run_average).cwiseAbs().sum();
  }
  return sum / batches;
}

double noa_noise_floor(const BayindirRates& rates, const std::vector<std::int64_t>& grid,
                       const std::vector<double>& start, int replicates, std::uint64_t seed,
                       std::uint64_t stream, int batches, const WalkProgress& progress) {
  if (replicates < 1 || batches < 1) throw std::invalid_argument("noise floor: no replicates");
  const auto noa = [&](const BayindirState& state) {
    return rates.forms_aggregates ? state.noa() : 0.0;
  };
  BayindirState expected = BayindirState::all_searching(rates.agents);
  std::int64_t expected_step = 0;
  std::vector<double> squares(static_cast<std::size_t>(batches), 0.0);
  walk_stochastic_side_by_side(
      rates, grid, seed, replicates * batches, stream, start,
      [&](std::span<const BayindirState> states, std::int64_t step) {
        for (; expected_step < step; ++expected_step)
          advance_expected_series(rates, expected, expected_step, start);
        for (int batch = 0; batch < batches; ++batch) {
          double mean = 0.0;
          for (int k = 0; k < replicates; ++k)
            mean += noa(states[replicate_index(batch, replicates, k)]);
          const double difference = mean / replicates - noa(expected);
          squares[static_cast<std::size_t>(batch)] += difference * difference;
        }
      },
      progress);
  double sum = 0.0;
  for (const double batch_squares : squares)
    sum += std::sqrt(batch_squares / static_cast<double>(grid.size()));
  return sum / batches;
}

}  // namespace swarmagg
