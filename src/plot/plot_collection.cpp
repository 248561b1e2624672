#include "plot/plot_collection.hpp"

#include <algorithm>

namespace swarmagg {

void PlotCollection::prepare(const FigureFiles& files,
                             const std::function<void(const FigureFiles&)>& write) {
  try {
    write(files);
    prepared_.push_back(files);
  } catch (const std::exception& e) {
    outcome_.failures.push_back(files.id + ".png: " + e.what());
  }
}

PlotOutcome PlotCollection::draw() {
  const std::vector<GnuplotFailure> failures = batch_.draw();
  for (const FigureFiles& files : prepared_) {
    const auto failed = std::find_if(failures.begin(), failures.end(),
                                     [&](const auto& f) { return f.script == files.script(); });
    if (failed == failures.end()) {
      outcome_.drawn.push_back(files.png());
    } else {
      outcome_.failures.push_back(files.id + ".png: " + failed->message);
    }
  }
  prepared_.clear();
  PlotOutcome outcome = std::move(outcome_);
  outcome_ = {};
  return outcome;
}

}  // namespace swarmagg
