#pragma once
// Where a figure's files go: a gnuplot script <folder>/<id>.gp reads CSVs beside it
// (<id>-<part>.csv, or <id>.csv for a figure with one table) and draws <id>.png, beside the
// script by default or in `png_dir` (relative to the script's folder, e.g. ".." for a run
// folder's top level), so a user can restyle the script and re-run gnuplot there.
#include <filesystem>
#include <string>

#include "plot/png_terminal.hpp"

namespace swarmagg {

struct FigureFiles {
  std::filesystem::path folder;
  std::string id;
  PlotSize size;
  std::string png_dir;  // empty: beside the script

  // The PNG as the script names it (relative to the script's folder).
  std::string png_name() const {
    return png_dir.empty() ? id + ".png" : png_dir + "/" + id + ".png";
  }
  std::filesystem::path png() const { return (folder / png_name()).lexically_normal(); }
  std::filesystem::path script() const { return folder / (id + ".gp"); }
  std::string csv_name(const std::string& part) const {
    return part.empty() ? id + ".csv" : id + "-" + part + ".csv";
  }
  std::filesystem::path csv(const std::string& part) const { return folder / csv_name(part); }
};

}  // namespace swarmagg
