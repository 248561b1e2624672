#include "sweep/sweep_summary.hpp"

#include "config/world_keys.hpp"
#include "models/sample_statistics.hpp"

namespace swarmagg {
namespace {

std::string statistics_fields(const std::vector<double>& values) {
  std::string text = std::to_string(values.size());
  for (const double statistic :
       {sample_mean(values), sample_sd(values), sample_quantile(values, 0.0),
        sample_quantile(values, 0.25), sample_quantile(values, 0.5), sample_quantile(values, 0.75),
        sample_quantile(values, 1.0)}) {
    text += "," + format_number(statistic);
  }
  return text;
}

std::string joined(const std::vector<std::string>& fields) {
  std::string text;
  for (const std::string& field : fields) text += field + ",";
  return text;
}

}  // namespace

std::string sweep_summary_csv(const std::vector<std::string>& parameter_keys,
                              const std::vector<std::string>& observables,
                              const std::vector<PointFinals>& points) {
  std::string text =
      joined(parameter_keys) + "observable,replicates,mean,sd,min,q25,median,q75,max\n";
  for (const PointFinals& point : points) {
    for (std::size_t k = 0; k < observables.size(); ++k) {
      std::vector<double> values;
      for (const std::vector<double>& replicate : point.replicates) values.push_back(replicate[k]);
      text += joined(point.values) + observables[k] + "," + statistics_fields(values) + "\n";
    }
  }
  return text;
}

}  // namespace swarmagg
