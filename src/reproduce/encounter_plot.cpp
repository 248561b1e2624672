#include "reproduce/encounter_plot.hpp"

#include "analysis/csv_text.hpp"
#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"

namespace swarmagg {

void plot_encounters(const FigureFiles& files, const std::string& title, EncounterAxis axis,
                     const std::vector<EncounterPoint>& points) {
  std::string csv = "agents,speed,simulated,simulated_sd,kinetic,paper_fit\n";
  for (const EncounterPoint& p : points) {
    csv += std::to_string(p.agents) + "," + csv_number(p.speed) + "," + csv_number(p.simulated) +
           "," + csv_number(p.simulated_sd) + "," + csv_number(p.kinetic) + "," +
           csv_number(p.paper_fit) + "\n";
  }
  write_file_atomic(files.csv("points"), csv);
  const std::string data = gnuplot_quote(files.csv_name("points"));
  const std::string x = axis == EncounterAxis::Agents ? "1" : "2";
  std::string script = png_preamble(files.size, files.png_name(), title);
  script += axis == EncounterAxis::Agents ? "set xlabel 'number of agents N'\n"
                                          : "set xlabel 'speed v (u/tu)'\n";
  script += "set ylabel 'encounters per tu'\nset key top left\nset yrange [0:*]\n";
  script += "plot " + data + " skip 1 using " + x +
            ":3:4 with yerrorbars pt 7 lc 'black' title 'simulation (mean, sd)', \\\n"
            "  " +
            data + " skip 1 using " + x +
            ":5 with lines lw 2 lc rgb '#ff7f0e' title 'kinetic theory (4/pi) s v N(N-1)/A', \\\n"
            "  " +
            data + " skip 1 using " + x +
            ":6 with lines lw 2 dt 2 lc rgb '#1f77b4' title 'paper fit C s v N^2'\n";
  run_gnuplot(files.script(), script);
}

}  // namespace swarmagg
