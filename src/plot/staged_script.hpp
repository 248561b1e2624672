#pragma once
// A gnuplot script as swarmagg runs it. The script written for the user names its PNGs
// (`set output 'noa.png'`); gnuplot empties such a file when it opens it, so a failed or
// stopped gnuplot would leave an empty or half-drawn plot where a good one was. swarmagg runs
// a hidden copy of the script instead, each output aimed at a temporary beside its PNG, and
// renames the temporaries over the PNGs once gnuplot succeeded: a plot is the earlier one or
// the complete new one.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace swarmagg {

class StagedScript {
 public:
  // Writes the hidden copy of `script` (its text, as written to `script_path`) beside it.
  StagedScript(const std::filesystem::path& script_path, const std::string& script);
  ~StagedScript();  // removes the copy and any temporary not committed
  StagedScript(StagedScript&&) noexcept;
  StagedScript& operator=(StagedScript&&) = delete;
  StagedScript(const StagedScript&) = delete;
  StagedScript& operator=(const StagedScript&) = delete;

  // The user's script, for messages.
  const std::filesystem::path& script() const { return script_; }
  // The copy to load, in the script's folder.
  const std::filesystem::path& to_run() const { return to_run_; }
  // gnuplot's messages about the copy, naming the user's script instead (the same lines).
  std::string named_as_script(std::string messages) const;
  // Once gnuplot drew the copy: its PNGs replace the earlier ones (std::system_error naming a
  // PNG that cannot be written).
  void commit();

 private:
  std::filesystem::path script_;
  std::filesystem::path to_run_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> outputs_;  // temp, PNG
};

}  // namespace swarmagg
