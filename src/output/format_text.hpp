#pragma once
// printf-style formatting of up to three numbers into a std::string, for the lines commands
// print (a pattern longer than 127 characters of output is cut).
#include <string>

namespace swarmagg {

std::string format_text(const char* pattern, double a, double b = 0.0, double c = 0.0);

}  // namespace swarmagg
