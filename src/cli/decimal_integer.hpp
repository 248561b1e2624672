#pragma once
// CLI11 reads integers as C does, in the base their prefix names: `--replicates 010` would run
// 8 replicates and `0x10` 16, where the same text in a world file or `--set` reads 10 (or is
// refused). Integers on the command line are decimal: this transform drops leading zeros and
// refuses any other form. Give it before a range check, which would read the raw text.
#include <CLI/CLI.hpp>

namespace swarmagg::cli {

CLI::Validator decimal_integer();

// Every integer option of every command that has no range check of its own.
void read_integers_in_decimal(CLI::App& app);

}  // namespace swarmagg::cli
