#pragma once
// The paper's figures (docs/reproducing.md) as data: which worlds of worlds/paper/ each one plots
// and how. One figure per world for the NOA and partition experiments; the two collision checks put
// eleven worlds on one axis each.
#include <string>
#include <vector>

namespace swarmagg {

enum class FigureKind {
  EncountersVsCount,  // Fig 7: encounters per tu against N
  EncountersVsSpeed,  // Fig 8: encounters per tu against v
  Noa,                // Figs 9-19: NOA over time, Bayindir model variants
  Partition,          // Figs 20-29: time fraction per partition, Soysal model variants
};

struct PaperFigure {
  std::string id;       // file stem of the plot, e.g. fig09-creation-50
  std::string figures;  // the paper's figure numbers, e.g. "9" or "20-21"
  std::string title;
  FigureKind kind = FigureKind::Noa;
  std::vector<std::string> worlds;  // world names, i.e. worlds/paper/<name>.yaml
};

std::vector<PaperFigure> paper_figures();

// Keeps the worlds whose name contains any of `patterns` (none keeps all) and drops
// figures left without worlds, so a test or a user can reproduce a subset through the
// same code path.
std::vector<PaperFigure> select_worlds(const std::vector<PaperFigure>& figures,
                                       const std::vector<std::string>& patterns);

}  // namespace swarmagg
