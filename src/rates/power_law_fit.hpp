#pragma once
// The weighted least-squares fit of a power law y = a m^b in log-log coordinates,
//   log y_i = log a + b log m_i,   weights w_i,
// with 95% intervals from the regression's standard errors: the residual variance
// sigma^2 = sum w_i e_i^2 / (n - 2) (weights are relative precisions, so their scale does
// not matter), Var b = sigma^2 / Sxx, Var log a = sigma^2 (1 / sum w + xbar^2 / Sxx), and
// the Student t quantile at n - 2 degrees. The interval of a is exp of that of log a.
// Fewer than kMinimumFitSizes distinct sizes leave no degree of freedom for the residual
// variance to mean anything: the fit is refused, and says why.
#include <optional>
#include <span>
#include <string>

namespace swarmagg {

inline constexpr int kMinimumFitSizes = 3;

struct PowerLawPoint {
  double size = 0.0;    // m > 0
  double value = 0.0;   // y > 0
  double weight = 1.0;  // > 0: the observations behind y
};

struct FittedParameter {
  double value = 0.0;
  double low = 0.0;  // 95% interval
  double high = 0.0;
  bool covers(double x) const { return low <= x && x <= high; }
};

struct PowerLawFit {
  int sizes = 0;  // the points fitted
  std::optional<FittedParameter> a, b;
  std::string refused;  // why there is no fit; empty when fitted
  bool fitted() const { return refused.empty(); }
};

PowerLawFit fit_power_law(std::span<const PowerLawPoint> points, double confidence = 0.95);

}  // namespace swarmagg
