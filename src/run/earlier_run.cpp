#include "run/earlier_run.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <system_error>

#include "config/world_difference.hpp"
#include "core/errors.hpp"
#include "rates/rate_rows.hpp"
#include "rates/rates_origin.hpp"
#include "run/run_folder.hpp"

namespace swarmagg {
namespace {

// The terms in the first column of a rates.csv, each once. Read leniently, not with read_csv,
// which refuses a damaged file: that would throw after the new simulation and lose it.
std::vector<std::string> rate_terms(const std::filesystem::path& rates_csv) {
  std::vector<std::string> terms;
  std::ifstream in(rates_csv);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    const std::string term = line.substr(0, line.find(','));
    if (!term.empty() && std::find(terms.begin(), terms.end(), term) == terms.end())
      terms.push_back(term);
  }
  return terms;
}

std::string pass_out_or_force() {
  return " Pass --out DIR, or --force to write there anyway";
}

// Refuses when the resolved world text `there` (what `out` holds, `held`) is another system.
void refuse_another_system(const std::string& there, const WorldSpec& spec,
                           const std::filesystem::path& out, const std::string& held,
                           const std::string& command, const std::string& consequence) {
  const std::vector<std::string> differences = system_differences(there, spec);
  if (differences.empty()) return;
  throw InputError(out.string() + "/ holds " + held + " of another world (" +
                   differences_text(differences) + "): `" + command + consequence + "." +
                   pass_out_or_force());
}

void refuse_another_worlds_run(const std::filesystem::path& out, const WorldSpec& spec,
                               const std::string& command) {
  const std::filesystem::path resolved = out / "world.resolved.yaml";
  std::error_code error;
  if (!std::filesystem::is_regular_file(resolved, error)) {
    throw InputError(resolved.string() + " is not a file: `" + command +
                     "` cannot tell whose folder this is." + pass_out_or_force());
  }
  refuse_another_system(resolved_world_in(out), spec, out, "a run", command,
                        "` would write this world's outputs beside that run, whose plots would "
                        "draw them as its own");
}

// A folder `rates` wrote (no run in it) records its world in rates.json: another world's
// rates would be replaced by `rates`, or sit beside this world's model.
void refuse_another_worlds_rates(const std::filesystem::path& out, const WorldSpec& spec,
                                 const std::string& command) {
  const RatesJsonWorld recorded = rates_json_world(out / "rates.json");
  if (recorded.found == RatesJsonWorld::Found::None) return;
  if (recorded.found == RatesJsonWorld::Found::Unreadable) {
    throw InputError((out / "rates.json").string() + " cannot be read: `" + command +
                     "` cannot tell whose rates the folder holds." + pass_out_or_force());
  }
  refuse_another_system(recorded.resolved_world, spec, out, "rates", command,
                        command == "rates" ? "` would replace them with this world's"
                                           : "` would write this world's outputs beside them");
}

}  // namespace

void remove_earlier_output(const std::filesystem::path& path, std::vector<std::string>& failures) {
  std::error_code error;
  std::filesystem::remove_all(path, error);
  if (error) failures.push_back(path.string() + ": " + error.message());
}

void clear_earlier_rates(const std::filesystem::path& out, std::vector<std::string>& failures) {
  // The terms of the earlier rates.csv, and every term this version writes: a rates.csv that
  // is gone or damaged would otherwise leave another model's plots beside the new ones.
  std::vector<std::string> terms = rate_terms(out / "rates.csv");
  terms.insert(terms.end(), std::begin(kRateTerms), std::end(kRateTerms));
  for (const std::string& term : terms) {
    for (const char* extension : {".png", ".gp", ".csv"})
      remove_earlier_output(out / ("rates-" + term + extension), failures);
  }
}

void refuse_another_worlds_outputs(const std::filesystem::path& out, const WorldSpec& spec,
                                   const std::string& command, bool force) {
  if (force) return;
  const std::filesystem::path resolved = out / "world.resolved.yaml";
  std::error_code error;
  if (std::filesystem::exists(resolved, error))
    return refuse_another_worlds_run(out, spec, command);
  refuse_another_worlds_rates(out, spec, command);
}

std::vector<std::string> clear_earlier_run(const std::filesystem::path& out) {
  std::vector<std::string> failures;
  const auto remove = [&](const std::filesystem::path& path) {
    remove_earlier_output(path, failures);
  };
  std::error_code missing;
  if (!std::filesystem::is_regular_file(out / "world.resolved.yaml", missing)) {
    // A folder `rates` wrote (its rates.json records a world): its rates, of another run,
    // would stay beside this run's outputs and be taken for its rates. Only they go; any
    // other file there is the user's.
    if (rates_json_world(out / "rates.json").found == RatesJsonWorld::Found::World) {
      clear_earlier_rates(out, failures);
      for (const char* name : {"rates.csv", "rates.json"}) remove(out / name);
    }
    return failures;
  }
  remove(out / "world.resolved.yaml");
  clear_earlier_rates(out, failures);
  for (const char* name :
       {"timeseries.csv", "summary.json", "partitions.csv", "model.csv", "rates.csv", "rates.json",
        "noa.png", "states.png", "sizes.png", "partitions.png", "model-timeseries", "plots"}) {
    remove(out / name);
  }
  return failures;
}

}  // namespace swarmagg
