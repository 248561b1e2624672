#include "plot/gnuplot_batch.hpp"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <system_error>

#include "output/temporary_directory.hpp"
#include "plot/gnuplot.hpp"
#include "plot/gnuplot_process.hpp"

namespace swarmagg {
namespace {

thread_local GnuplotBatch* open_batch = nullptr;

// Loads each script from its own folder, closes its PNG and forgets its settings, as if
// gnuplot had been started afresh for it.
std::string batch_commands(const std::vector<StagedScript>& scripts) {
  std::string commands;
  for (const StagedScript& script : scripts) {
    const auto absolute = std::filesystem::absolute(script.to_run());
    commands += "cd " + gnuplot_quote(absolute.parent_path().string()) + "\n";
    commands += "load " + gnuplot_quote(absolute.filename().string()) + "\n";
    commands += "unset output\nreset session\n";
  }
  return commands;
}

// A command file of its own in the temporary folder, removed when it goes out of scope.
class CommandFile {
 public:
  explicit CommandFile(const std::string& commands) {
    std::error_code missing;  // mkstemps below names the folder in its error
    std::string name = (temporary_directory(missing) / "swarmagg-plots-XXXXXX.gp");
    const int fd = ::mkstemps(name.data(), 3);
    if (fd < 0) throw std::runtime_error("cannot create a temporary file for gnuplot in " + name);
    path_ = name;
    const bool written =
        ::write(fd, commands.data(), commands.size()) == static_cast<ssize_t>(commands.size());
    ::close(fd);
    if (!written) throw std::runtime_error("cannot write " + name);
  }
  ~CommandFile() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  CommandFile(const CommandFile&) = delete;
  CommandFile& operator=(const CommandFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::filesystem::path folder_of(const std::filesystem::path& script) {
  return script.parent_path().empty() ? std::filesystem::path(".") : script.parent_path();
}

// A drawn script's PNGs replace the earlier ones; one that cannot be written is its failure.
void commit(StagedScript& script, std::vector<GnuplotFailure>& failures) {
  try {
    script.commit();
  } catch (const std::runtime_error& e) {  // system_error too
    failures.push_back({script.script(), e.what()});
  }
}

}  // namespace

GnuplotBatch::GnuplotBatch() : hidden_(open_batch) {
  open_batch = this;
}

GnuplotBatch::~GnuplotBatch() {
  open_batch = hidden_;
}

GnuplotBatch* GnuplotBatch::open_on_this_thread() {
  return open_batch;
}

void GnuplotBatch::queue(StagedScript script) {
  scripts_.push_back(std::move(script));
}

std::vector<GnuplotFailure> GnuplotBatch::draw() {
  std::vector<StagedScript> scripts = std::move(scripts_);
  scripts_.clear();
  if (scripts.empty()) return {};
  if (find_gnuplot().empty())
    throw std::runtime_error(gnuplot_missing_message(scripts.front().script()));
  std::vector<GnuplotFailure> failures;
  {
    const CommandFile commands(batch_commands(scripts));
    if (run_gnuplot_process(commands.path(), folder_of(scripts.front().to_run())).succeeded) {
      for (StagedScript& script : scripts) commit(script, failures);
      return failures;
    }
  }
  for (StagedScript& script : scripts) {
    const GnuplotExit exit =
        run_gnuplot_process(script.to_run().filename(), folder_of(script.to_run()));
    if (exit.succeeded) {
      commit(script, failures);
    } else {
      failures.push_back({script.script(), "gnuplot failed on " + script.script().string() + ":\n" +
                                               script.named_as_script(exit.messages)});
    }
  }
  return failures;
}

void GnuplotBatch::draw_or_throw() {
  std::string message;
  for (const GnuplotFailure& failure : draw()) {
    message += (message.empty() ? "" : "\n") + failure.message;
  }
  if (!message.empty()) throw std::runtime_error(message);
}

}  // namespace swarmagg
