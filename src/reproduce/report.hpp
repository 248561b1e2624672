#pragma once
// REPORT.md: one table per kind of experiment with a row per experiment (collision checks
// per world; NOA RMSE per Bayindir variant; total-variation distance per Soysal variant),
// the better variant of each row and a link to its figure, each table followed by its
// figures as images (FigureResult::plot); every model error beside its noise floor, the
// Soysal runs' distributions and stationarity, the leave-timeout series and why the models
// miss (reproduce/returns_report.hpp); then one line per claim of the paper with its
// verdict and numbers. Numbers are printed to 4 significant digits.
#include <string>
#include <vector>

#include "reproduce/claims.hpp"
#include "reproduce/figure_result.hpp"
#include "reproduce/timeout_series.hpp"

namespace swarmagg {

struct ReportContext {
  std::string mode;    // "full" or "quick", with the overrides applied to every world
  std::string engine;  // kinematic | box2d
  double wall_seconds = 0.0;
  std::vector<TimeoutPoint> timeout_series = {};  // empty when not run
};

std::string report_markdown(const ReportContext& context, const std::vector<FigureResult>& results,
                            const std::vector<ClaimCheck>& claims);

// The number formatting of the report's tables.
std::string report_number(double value);

}  // namespace swarmagg
