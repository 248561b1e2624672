#pragma once
// Number formatting for the figure CSVs: shortest text that reads back to the same double
// (so the report, the plots and a test recomputing from the CSV agree), NaN as empty.
#include <string>

namespace swarmagg {

std::string csv_number(double value);

}  // namespace swarmagg
