#pragma once
// Where a figure's files go: <plots>/<id>.png, drawn by <plots>/<id>.gp from CSVs named
// <id>-<part>.csv beside it, so a user can restyle the script and re-run gnuplot there.
#include <filesystem>
#include <string>

#include "plot/png_terminal.hpp"

namespace swarmagg {

struct FigureFiles {
  std::filesystem::path folder;
  std::string id;
  PlotSize size;

  std::filesystem::path png() const { return folder / (id + ".png"); }
  std::filesystem::path script() const { return folder / (id + ".gp"); }
  std::string csv_name(const std::string& part) const { return id + "-" + part + ".csv"; }
  std::filesystem::path csv(const std::string& part) const { return folder / csv_name(part); }
};

}  // namespace swarmagg
