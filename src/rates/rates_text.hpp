#pragma once
// The measured terms as lines for the terminal: each term's rate and interval, and its
// ratio to each model variant's value (the interval divided by the model's value).
#include <string>
#include <vector>

#include "rates/rate_rows.hpp"

namespace swarmagg {

std::vector<std::string> rate_summary_lines(const std::vector<RateRow>& rows);

}  // namespace swarmagg
