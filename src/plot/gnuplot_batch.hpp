#pragma once
// Starting gnuplot and loading its PNG terminal costs about as much as drawing a plot, and a
// run or a reproduction draws dozens. While a GnuplotBatch is open on a thread, run_gnuplot
// there writes and queues its script; draw() then draws every queued script in one gnuplot
// process, each from its own folder and with gnuplot's settings reset in between, so the
// PNGs are the ones each script draws on its own.
#include <filesystem>
#include <string>
#include <vector>

#include "plot/staged_script.hpp"

namespace swarmagg {

struct GnuplotFailure {
  std::filesystem::path script;
  std::string message;  // gnuplot's own words
};

class GnuplotBatch {
 public:
  GnuplotBatch();  // opens on this thread; a batch opened inside another hides it until closed
  ~GnuplotBatch();
  GnuplotBatch(const GnuplotBatch&) = delete;
  GnuplotBatch& operator=(const GnuplotBatch&) = delete;

  static GnuplotBatch* open_on_this_thread();
  void queue(StagedScript script);

  // Draws the queued scripts and empties the queue. When the shared process fails, each
  // script is drawn on its own, so every failure names its script and the others are drawn.
  // Throws std::runtime_error when gnuplot is missing.
  std::vector<GnuplotFailure> draw();
  // draw(), throwing std::runtime_error with every failure's message if any script failed.
  void draw_or_throw();

 private:
  std::vector<StagedScript> scripts_;
  GnuplotBatch* hidden_;
};

}  // namespace swarmagg
