// states.png: see run_plot.hpp.
#include <cstdio>

#include "analysis/csv_text.hpp"
#include "analysis/step_series.hpp"
#include "controllers/controller_registry.hpp"
#include "core/counted.hpp"
#include "output/atomic_file.hpp"
#include "plot/drawn_points.hpp"
#include "plot/gnuplot.hpp"
#include "plot/run_plot.hpp"
#include "render/palette.hpp"

namespace swarmagg {
namespace {

struct StateLine {
  const char* column;
  const char* label;
  Rgba8 colour;  // the state's colour in rendered frames, so plots and frames agree
};

std::string hex(Rgba8 c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

}  // namespace

void draw_states_over_time(const RunFiles& run, const FigureFiles& files) {
  std::vector<StateLine> states{{"searching", "searching (GO)", palette::kGo},
                                {"waiting", "waiting (WAIT)", palette::kWait},
                                {"leaving", "leaving (LEAVE)", palette::kLeave}};
  if (controller_rules(run.world).allows(AgentState::Approach))
    states.push_back({"approaching", "approaching (APPROACH)", palette::kApproach});
  std::vector<std::string> columns;
  for (const StateLine& state : states) columns.emplace_back(state.column);
  const std::vector<StepSeries> series = read_drawn_series(run, columns);

  std::string csv = "time";
  for (const StateLine& state : states) csv += "," + std::string(state.column);
  csv += "\n";
  for (std::size_t i = 0; i < series.front().steps.size(); ++i) {
    csv += csv_number(series.front().times[i]);
    for (const StepSeries& s : series) csv += "," + csv_number(s.mean_at(i));
    csv += "\n";
  }
  write_file_atomic(files.csv(""), csv);

  const std::size_t replicates = series.front().values.front().size();
  const std::string data = gnuplot_quote(files.csv_name(""));
  std::string script = png_preamble(files.size, files.png_name(),
                                    run_title(run) + ": agents per state, mean of " +
                                        counted(static_cast<long long>(replicates), "replicate"));
  script += std::string(kKeyAbovePlot) +
            "set xlabel 'time (tu)'\nset ylabel 'agents'\n"
            "set yrange [0:" +
            std::to_string(run.world.robots.count) + "]\n";
  script += "plot ";
  for (std::size_t k = 0; k < states.size(); ++k) {
    script += (k == 0 ? "" : ", \\\n  ") + data + " skip 1 using 1:" + std::to_string(k + 2) +
              " with lines lw 2 lc rgb " + gnuplot_quote(hex(states[k].colour)) + " title " +
              gnuplot_quote(states[k].label);
  }
  script += "\n";
  run_gnuplot(files.script(), script);
}

}  // namespace swarmagg
