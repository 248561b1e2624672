#pragma once
// What a sweep may vary, shared by the sweep file's reader and sweep.json's: the keys the sweep
// sets itself are not parameters, and a value becomes part of a folder name, so it is a number
// or a name.
#include <string>
#include <string_view>

namespace swarmagg {

// The keys a sweep sets itself (its name, seed and replicates; it writes no frames).
inline bool swept_by_sweep(const std::string& path) {
  return path == "name" || path == "run.seed" || path == "run.replicates" ||
         path.rfind("render.", 0) == 0;
}

// A value as a resolved world writes it, of letters, digits, '.', '_', '+' and '-' only.
inline bool is_sweep_value_text(std::string_view text) {
  constexpr std::string_view allowed =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._+-";
  return !text.empty() && text.find_first_not_of(allowed) == std::string_view::npos;
}

}  // namespace swarmagg
