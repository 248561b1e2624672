#pragma once
// The comparison's data tables and plots, each PNG made by a gnuplot script (.gp) beside
// the CSV it reads:
//   noa.csv + noa.gp -> noa.png          NOA over time, mean and 95% CI band of each arm
//   final_noa.csv, sizes.csv + final.gp -> final.png
//                                        final NOA and final aggregate sizes, side by side
//   escape_rate.csv + escape_rate.gp -> escape_rate.png   (Bayindir and Soysal worlds that
//                                        leave) escapes per tu per aggregate of size m of
//                                        each arm, with the leave laws m p/dt (every member
//                                        may leave) and periph(m) p/dt (the periphery only)
#include <filesystem>
#include <string>

#include "compare/arm_comparison.hpp"
#include "compare/engine_arm.hpp"

namespace swarmagg {

// noa.csv: time, then mean/low/high of each arm over its replicates at each recorded step a
// time plot draws (plot/drawn_points.hpp), read from the arms' timeseries.csv in `out`.
std::string noa_band_csv(const ArmResult& a, const ArmResult& b, const std::filesystem::path& out);
// value,<a>,<b>: how many samples of each arm take each value (a histogram table).
std::string histogram_csv(const std::string& value_name, const std::string& label_a,
                          const std::vector<double>& values_a, const std::string& label_b,
                          const std::vector<double>& values_b);

// escape_rate.csv: size, then each arm's escapes, aggregate_time, rate (escapes /
// aggregate_time) and the rate's 95% half width (NaN where the arm never had an aggregate of
// that size), then the two laws, with p the per-step leave probability of a member of an
// aggregate of that size.
std::string escape_rate_csv(const ArmResult& a, const ArmResult& b, const Comparison& c);

// Writes the figures' CSVs and scripts and draws them; returns what could not be drawn (gnuplot
// missing, a script it failed on), for the caller to warn about: the comparison stands.
std::vector<std::string> write_comparison_plots(const std::string& world_name, const ArmResult& a,
                                                const ArmResult& b, const Comparison& c,
                                                const std::filesystem::path& out);

}  // namespace swarmagg
