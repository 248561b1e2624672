#include "plot/staged_script.hpp"

#include <optional>
#include <sstream>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "plot/png_size.hpp"

namespace swarmagg {
namespace {

constexpr std::string_view kSetOutput = "set output '";

// The file a `set output '...'` line names (gnuplot_quote's single quotes), or nothing.
std::optional<std::string> output_named(const std::string& line) {
  if (!line.starts_with(kSetOutput) || !line.ends_with('\'') || line.size() < kSetOutput.size() + 1)
    return std::nullopt;
  const std::string quoted = line.substr(kSetOutput.size(), line.size() - kSetOutput.size() - 1);
  std::string name;
  for (std::size_t i = 0; i < quoted.size(); ++i) {
    name += quoted[i];
    if (quoted[i] == '\'') ++i;  // '' stands for '
  }
  return name;
}

}  // namespace

StagedScript::StagedScript(const std::filesystem::path& script_path, const std::string& script)
    : script_(script_path) {
  const std::filesystem::path folder = script_path.parent_path();
  std::istringstream lines(script);
  std::string staged;
  for (std::string line; std::getline(lines, line);) {
    if (const std::optional<std::string> name = output_named(line)) {
      const std::filesystem::path png = std::filesystem::path(*name);
      const std::filesystem::path temporary = temporary_beside(png);
      outputs_.emplace_back(folder / temporary, folder / png);
      line = "set output " + gnuplot_quote(temporary.string());
    }
    staged += line + "\n";
  }
  to_run_ = temporary_beside(script_path);
  write_file_atomic(to_run_, staged);
}

StagedScript::StagedScript(StagedScript&& other) noexcept
    : script_(std::move(other.script_)),
      to_run_(std::move(other.to_run_)),
      outputs_(std::move(other.outputs_)) {
  other.to_run_.clear();
  other.outputs_.clear();
}

StagedScript::~StagedScript() {
  if (!to_run_.empty()) discard_temporary(to_run_);
  for (const auto& [temporary, png] : outputs_) discard_temporary(temporary);
}

std::string StagedScript::named_as_script(std::string messages) const {
  const std::string copy = to_run_.filename().string(), script = script_.filename().string();
  for (auto at = messages.find(copy); at != std::string::npos;
       at = messages.find(copy, at + script.size()))
    messages.replace(at, copy.size(), script);
  return messages;
}

void StagedScript::commit() {
  auto outputs = std::move(outputs_);
  outputs_.clear();
  // gnuplot says nothing when a PNG could not be written whole (a full disk): such a plot
  // must not replace the earlier one.
  for (const auto& [temporary, png] : outputs) {
    if (png.extension() == ".png" && !png_complete(temporary)) {
      for (const auto& output : outputs) discard_temporary(output.first);
      throw std::runtime_error(png.string() + ": gnuplot wrote an incomplete file (disk full?)");
    }
  }
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    try {
      rename_or_discard(outputs[k].first, outputs[k].second);
    } catch (...) {
      for (std::size_t rest = k + 1; rest < outputs.size(); ++rest)
        discard_temporary(outputs[rest].first);
      throw;
    }
  }
}

}  // namespace swarmagg
