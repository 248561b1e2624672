#include "plot/plot_collection.hpp"

#include <algorithm>
#include <system_error>

#include "core/errors.hpp"
#include "plot/png_size.hpp"

namespace swarmagg {

void PlotCollection::prepare(const FigureFiles& files,
                             const std::function<void(const FigureFiles&)>& write) {
  try {
    write(files);
    prepared_.push_back(files);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    outcome_.failures.push_back(files.id + ".png: " + e.what());
  }
}

PlotOutcome PlotCollection::draw() {
  const std::vector<GnuplotFailure> failures = batch_.draw();
  for (const FigureFiles& files : prepared_) {
    const auto failed = std::find_if(failures.begin(), failures.end(),
                                     [&](const auto& f) { return f.script == files.script(); });
    if (failed != failures.end()) {
      outcome_.failures.push_back(files.id + ".png: " + failed->message);
    } else if (!png_complete(files.png())) {
      // gnuplot says nothing when its PNG could not be written whole (a full disk).
      std::error_code ignored;
      std::filesystem::remove(files.png(), ignored);
      outcome_.failures.push_back(files.id + ".png: gnuplot wrote an incomplete file (disk full?)");
    } else {
      outcome_.drawn.push_back(files.png());
    }
  }
  prepared_.clear();
  PlotOutcome outcome = std::move(outcome_);
  outcome_ = {};
  return outcome;
}

}  // namespace swarmagg
