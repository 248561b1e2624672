#include "cli/merge_removals.hpp"

#include "cli/follow_up_commands.hpp"

namespace swarmagg::cli {

std::string merge_removals_text(const MergeReport& report, const std::string& out,
                                bool plots_drawn) {
  if (report.removed.empty()) return "";
  std::string text =
      "removed what the earlier merge in " + out + "/ drew or held that this one outdates:";
  for (const std::filesystem::path& file : report.removed) text += " " + file.string();
  text += "\n";
  if (report.plots_removed && !plots_drawn)
    text += "`swarmagg plot " + shell_word(out) + "` draws the sweep's plots\n";
  return text;
}

}  // namespace swarmagg::cli
