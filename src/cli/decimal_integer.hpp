#pragma once
// CLI11 reads integers as C does, in the base their prefix names: `--replicates 010` would run
// 8 replicates and `0x10` 16, where the same text in a world file or `--set` reads 10 (or is
// refused). Integers on the command line are decimal digits, as in world files: leading zeros
// are dropped, and a sign other than a minus on a signed option is refused. CLI11 runs a
// transform before an option's checks (a range), so those read the digits.
#include <CLI/CLI.hpp>

namespace swarmagg::cli {

CLI::Validator decimal_integer(bool signed_option);

// Every integer option of every command (type INT or UINT, with or without checks).
void read_integers_in_decimal(CLI::App& app);

}  // namespace swarmagg::cli
