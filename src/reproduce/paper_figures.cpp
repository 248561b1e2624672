#include "reproduce/paper_figures.hpp"

#include <algorithm>

namespace swarmagg {
namespace {

std::vector<std::string> numbered(const std::string& stem, const std::vector<std::string>& values) {
  std::vector<std::string> names;
  for (const auto& value : values) names.push_back(stem + value);
  return names;
}

PaperFigure noa(const std::string& number, const std::string& world, const std::string& title) {
  std::string padded = number.size() < 2 ? "0" + number : number;
  return {"fig" + padded + "-" + world, number, title, FigureKind::Noa, {world}};
}

PaperFigure partition(const std::string& numbers, const std::string& world,
                      const std::string& title) {
  return {"fig" + numbers + "-" + world, numbers, title, FigureKind::Partition, {world}};
}

}  // namespace

std::vector<PaperFigure> paper_figures() {
  return {
      {"fig07-collision-count", "7", "Encounters per tu vs number of agents (540 x 540, v = 1)",
       FigureKind::EncountersVsCount,
       numbered("collision-count-",
                {"100", "126", "152", "178", "204", "230", "256", "282", "308", "334", "360"})},
      {"fig08-collision-speed", "8", "Encounters per tu vs speed (380 x 380, N = 100)",
       FigureKind::EncountersVsSpeed,
       numbered("collision-speed-", {"1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11"})},
      noa("9", "creation-50", "Creation, 50 agents"),
      noa("10", "creation-100", "Creation, 100 agents"),
      noa("11", "creation-150", "Creation, 150 agents"),
      noa("12", "creation-growing-80", "Creation + growing, 80 agents"),
      noa("13", "creation-growing-160", "Creation + growing, 160 agents"),
      noa("14", "creation-dissipation-0.0001", "Creation + dissipation, 150 agents, p = 0.0001"),
      noa("15", "creation-dissipation-0.0005", "Creation + dissipation, 150 agents, p = 0.0005"),
      noa("16", "creation-dissipation-0.001", "Creation + dissipation, 150 agents, p = 0.001"),
      noa("17", "creation-dissipation-0.005", "Creation + dissipation, 150 agents, p = 0.005"),
      noa("18", "full-0.0005", "Creation + growing + shrinking, 120 agents, p = 0.0005"),
      noa("19", "full-0.0025", "Creation + growing + shrinking, 120 agents, p = 0.0025"),
      partition("20-21", "soysal-5-constant", "Soysal, 5 agents, P_l = 2e-5"),
      partition("22-23", "soysal-5-inverse", "Soysal, 5 agents, P_l = 2e-5 / i"),
      partition("24-25", "soysal-5-inverse_square", "Soysal, 5 agents, P_l = 2e-5 / i^2"),
      partition("26-27", "soysal-10-constant", "Soysal, 10 agents, P_l = 2e-5"),
      partition("28-29", "soysal-20-constant", "Soysal, 20 agents, P_l = 2e-5"),
  };
}

std::vector<PaperFigure> select_worlds(const std::vector<PaperFigure>& figures,
                                       const std::vector<std::string>& patterns) {
  auto wanted = [&](const std::string& world) {
    return patterns.empty() ||
           std::any_of(patterns.begin(), patterns.end(),
                       [&](const std::string& p) { return world.find(p) != std::string::npos; });
  };
  std::vector<PaperFigure> selected;
  for (PaperFigure figure : figures) {
    std::erase_if(figure.worlds, [&](const std::string& world) { return !wanted(world); });
    if (!figure.worlds.empty()) selected.push_back(std::move(figure));
  }
  return selected;
}

}  // namespace swarmagg
