#include "cli/frame_output.hpp"

#include "config/world_override.hpp"
#include "render/frame_recorder.hpp"
#include "render/render_size.hpp"
#include "run/replicate.hpp"

namespace swarmagg::cli {
namespace {

class FrameObserver final : public ReplicateObserver {
 public:
  FrameObserver(const WorldSpec& spec, const std::filesystem::path& folder)
      : every_(spec.render.every), recorder_(spec, folder) {}

  void observe(const Replicate& replicate) override {
    if (replicate.steps_done() % every_ == 0) recorder_.record(replicate.snapshot());
  }
  void finish() override { recorder_.finish(); }

 private:
  int every_;
  FrameRecorder recorder_;
};

}  // namespace

std::filesystem::path frames_folder(const WorldSpec& spec, const std::filesystem::path& out,
                                    bool out_given) {
  if (!spec.render.dir.empty()) return spec.render.dir;
  if (out_given) return out / "frames";
  return std::filesystem::path("renders") / spec.name;
}

std::vector<WorldOverride> render_size_overrides(std::string_view size, const std::string& origin) {
  const RenderSize parsed = parse_render_size(size);
  return {typed_override("render.width", parsed.width, origin),
          typed_override("render.height", parsed.height, origin)};
}

ObserverFactory frame_observers(const WorldSpec& spec, const std::filesystem::path& folder) {
  if (spec.render.every <= 0) return nullptr;
  return [&spec, folder](int index) -> std::unique_ptr<ReplicateObserver> {
    if (index != spec.render.replicate) return nullptr;
    return std::make_unique<FrameObserver>(spec, folder);
  };
}

}  // namespace swarmagg::cli
