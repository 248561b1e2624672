#include "plot/gnuplot.hpp"

#include <stdexcept>

#include "output/atomic_file.hpp"
#include "plot/gnuplot_batch.hpp"
#include "plot/gnuplot_process.hpp"
#include "plot/staged_script.hpp"

namespace swarmagg {

bool gnuplot_available() {
  return !find_gnuplot().empty();
}

// Single quotes: gnuplot runs the text between backquotes as a shell command anywhere on a
// line but inside single-quoted strings, and a world's name, a --set value or a model.csv
// cell reaches the titles. A line break would end the command, so control characters become
// spaces.
std::string gnuplot_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') quoted += '\'';
    const bool control = static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
    quoted += control ? ' ' : c;
  }
  return quoted + "'";
}

void run_gnuplot(const std::filesystem::path& script_path, const std::string& script) {
  write_file_atomic(script_path, script);
  if (GnuplotBatch* batch = GnuplotBatch::open_on_this_thread()) {
    batch->queue(StagedScript(script_path, script));
    return;
  }
  if (find_gnuplot().empty()) throw std::runtime_error(gnuplot_missing_message(script_path));
  StagedScript staged(script_path, script);
  const GnuplotExit exit = run_gnuplot_process(
      staged.to_run().filename(),
      script_path.parent_path().empty() ? std::filesystem::path(".") : script_path.parent_path());
  if (!exit.succeeded) {
    throw std::runtime_error("gnuplot failed on " + script_path.string() + ":\n" +
                             staged.named_as_script(exit.messages));
  }
  staged.commit();
}

}  // namespace swarmagg
