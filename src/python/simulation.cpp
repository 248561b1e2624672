// swarmagg.Simulation: one replicate stepped from Python, its state shown as read-only numpy
// views of the replicate's own arrays (no copy), valid until the next step(), as MuJoCo
// documents for its views. It is the replicate `swarmagg run` runs: the same world, seed and
// replicate index give the same states, step for step (state_hash() == final_state_hash).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <charconv>
#include <cstdint>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "core/agent_state.hpp"
#include "core/errors.hpp"
#include "python/bindings.hpp"
#include "python/bound_class.hpp"
#include "python/world.hpp"
#include "render/frame_recorder.hpp"
#include "render/frame_renderer.hpp"
#include "render/png_writer.hpp"
#include "run/replicate.hpp"
#include "run/state_hash.hpp"

namespace py = pybind11;

namespace swarmagg::python {
namespace {

// The PNG level frame recorders use, so a frame written here is the recorder's file.
const int kFrameCompression = FrameRecorderOptions{}.compression_level;

// (width, height) as Python passes it: integers read as whole_argument reads them, so that a
// side beyond an int is the documented ValueError rather than pybind's "incompatible arguments".
using Size = std::optional<std::pair<py::object, py::object>>;

// A count or index as Python passes it: a bool or a float is a TypeError (True ran replicate
// 1, or one step), a number outside [0, most] a ValueError naming the argument (pybind's own
// conversion said only "incompatible arguments").
std::int64_t whole_argument(const py::object& value, const std::string& name, std::int64_t most) {
  const std::string text = yaml_index(value, name).Scalar();
  std::int64_t number = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc() || end != text.data() + text.size() || number < 0 || number > most) {
    throw InputError(name + ": expected a whole number from 0 to " + std::to_string(most) +
                     ", got " + text);
  }
  return number;
}

class Simulation {
 public:
  using BoundToPython = void;

  Simulation(const World& world, std::optional<py::object> seed, const py::object& replicate,
             std::optional<std::string> engine)
      : world_(world_for(world, seed, engine)) {
    const auto index =
        static_cast<int>(whole_argument(replicate, "replicate", std::numeric_limits<int>::max()));
    replicate_ = std::make_unique<Replicate>(*world_.spec, index);
  }

  void step(const py::object& count) {
    const std::int64_t steps =
        whole_argument(count, "steps", std::numeric_limits<std::int64_t>::max());
    if (failure_) std::rethrow_exception(failure_);
    for (std::int64_t k = 1; k <= steps; ++k) {
      try {
        replicate_->step();
      } catch (...) {
        // The failed step left the state half changed (moved bodies, an uncounted step):
        // carrying on would reach states no run reaches, so every later step() fails alike.
        failure_ = std::current_exception();
        throw;
      }
      // After every step, as the docs promise: with no signal pending it reads one flag, and
      // one step of a large swarm takes long enough (13 ms at 2 x 10^5 agents) that every
      // 1024th step kept Ctrl-C waiting for 14 s.
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  }

  // A read-only view whose base is `self`, the Python Simulation: the simulation lives as long
  // as any view of it.
  template <typename T>
  static py::array view(const T* data, std::vector<py::ssize_t> shape,
                        std::vector<py::ssize_t> strides, const py::object& self) {
    py::array array(py::dtype::of<T>(), std::move(shape), std::move(strides), data, self);
    array.attr("setflags")(py::arg("write") = false);
    return array;
  }
  static py::array vectors(std::span<const Vec2> values, const py::object& self) {
    static_assert(sizeof(Vec2) == 2 * sizeof(double));
    const auto n = static_cast<py::ssize_t>(values.size());
    return view(&values.data()->x, {n, 2}, {sizeof(Vec2), sizeof(double)}, self);
  }

  py::array positions(const py::object& self) const {
    return vectors(replicate_->engine().positions(), self);
  }
  py::array headings(const py::object& self) const {
    return vectors(replicate_->swarm().heading, self);
  }
  py::array states(const py::object& self) const {
    static_assert(sizeof(AgentState) == sizeof(std::int8_t));
    const auto& states = replicate_->swarm().state;
    return view(reinterpret_cast<const std::int8_t*>(states.data()),
                {static_cast<py::ssize_t>(states.size())}, {1}, self);
  }
  py::array aggregates(const py::object& self) const {
    const auto ids = replicate_->aggregates().aggregate_of();
    return view(ids.data(), {static_cast<py::ssize_t>(ids.size())}, {sizeof(std::int32_t)}, self);
  }

  std::string hash() const { return state_hash_text(state_hash(*replicate_)); }

  void render_png(const std::filesystem::path& path, const Size& size) {
    FrameRenderer& renderer = renderer_for(size);
    write_png(path, renderer.width(), renderer.height(), renderer.render(replicate_->snapshot()),
              kFrameCompression);
  }
  py::array_t<std::uint8_t> frame(const Size& size) {
    FrameRenderer& renderer = renderer_for(size);
    py::array_t<std::uint8_t> pixels({renderer.height(), renderer.width(), 4});
    renderer.render(
        replicate_->snapshot(),
        std::span<std::uint8_t>(pixels.mutable_data(), static_cast<std::size_t>(pixels.size())));
    return pixels;
  }

  const Replicate& replicate() const { return *replicate_; }
  const World& world() const { return world_; }

 private:
  static World world_for(const World& world, std::optional<py::object> seed,
                         std::optional<std::string> engine) {
    std::vector<WorldOverride> overrides;
    add_argument(overrides, "engine.type", engine, "engine");
    add_argument(overrides, "run.seed", seed, "seed");
    return with_overrides(world, overrides);
  }

  // One renderer, kept while the size stays (its context and shaders cost a first frame).
  FrameRenderer& renderer_for(const Size& size) {
    constexpr std::int64_t kMostSide = std::numeric_limits<int>::max();
    const int width = size ? static_cast<int>(whole_argument(size->first, "size", kMostSide))
                           : world_.spec->render.width;
    const int height = size ? static_cast<int>(whole_argument(size->second, "size", kMostSide))
                            : world_.spec->render.height;
    if (!renderer_ || renderer_->width() != width || renderer_->height() != height)
      renderer_ = std::make_unique<FrameRenderer>(width, height);
    return *renderer_;
  }

  World world_;
  std::unique_ptr<Replicate> replicate_;
  std::exception_ptr failure_;  // what stopped a step, raised again by every later step()
  std::unique_ptr<FrameRenderer> renderer_;
};

// A view property: the view's base is the Python object the attribute was read from.
template <py::array (Simulation::*View)(const py::object&) const>
py::array view_of(const py::object& self) {
  return (self.cast<const Simulation&>().*View)(self);
}

}  // namespace

void bind_simulation(py::module_& module) {
  py::list states;
  for (int s = 0; s < kAgentStateCount; ++s)
    states.append(py::make_tuple(std::string(to_string(static_cast<AgentState>(s))), s));
  module.attr("AGENT_STATES") = states;

  py::class_<Simulation> simulation(
      module, "Simulation",
      "Simulation(world: World, seed: int | None = None, replicate: int = 0, engine: str | None "
      "= None)\n\n"
      "One replicate of `world`, stepped by hand: the replicate `swarmagg run` runs with the "
      "same seed and index. The state attributes are read-only numpy views of the "
      "simulation's own arrays, valid until the next step() (take .copy() to keep one).");
  // No copy: the replicate's engine and controllers cannot be copied, and replaying its steps
  // could take as long as the steps took.
  refuse_pickling(simulation,
                  "swarmagg.Simulation cannot be copied or pickled: its replicate lives in the "
                  "library's memory. For a second one in the same state, make "
                  "Simulation(sim.world, replicate=<the same index>) and step() it "
                  "sim.step_count steps: the same world, seed, replicate and steps give the "
                  "same state, bit for bit");
  simulation
      .def(py::init<const World&, std::optional<py::object>, const py::object&,
                    std::optional<std::string>>(),
           py::arg("world"), py::arg("seed") = py::none(), py::arg("replicate") = 0,
           py::arg("engine") = py::none())
      .def("step", &Simulation::step, py::arg("steps") = 1,
           "Advances by `steps` steps of dt (Ctrl-C stops it between steps).")
      .def_property_readonly("positions", &view_of<&Simulation::positions>,
                             "numpy.ndarray (N, 2) float64, read-only view: agent centres (x, y).")
      .def_property_readonly("headings", &view_of<&Simulation::headings>,
                             "numpy.ndarray (N, 2) float64, read-only view: unit heading vectors.")
      .def_property_readonly(
          "states", &view_of<&Simulation::states>,
          "numpy.ndarray (N,) int8, read-only view: controller states, values of swarmagg.State.")
      .def_property_readonly(
          "aggregates", &view_of<&Simulation::aggregates>,
          "numpy.ndarray (N,) int32, read-only view: aggregate id of each agent (0 .. noa-1), "
          "-1 for agents in no aggregate.")
      .def_property_readonly(
          "step_count", [](const Simulation& s) { return s.replicate().steps_done(); },
          "Steps done so far (int).")
      .def_property_readonly(
          "time", [](const Simulation& s) { return s.replicate().time(); },
          "Simulated time, step_count * dt (float).")
      .def_property_readonly(
          "noa", [](const Simulation& s) { return s.replicate().aggregates().count(); },
          "Number of aggregates now (int).")
      .def_property_readonly("world", &Simulation::world, "The world simulated (World).")
      .def("state_hash", &Simulation::hash,
           "Hash of every agent's position, heading and state (str, 16 hex digits): "
           "final_state_hash in summary.json of a run of as many steps.")
      .def("render_png", &Simulation::render_png, py::arg("path"), py::arg("size") = py::none(),
           "Draws the current state into a PNG file, the same pixels as the off-screen "
           "renderer of `swarmagg run --render-every` (size (width, height); default the "
           "world's render size).")
      .def("frame", &Simulation::frame, py::arg("size") = py::none(),
           "The current state drawn as a new (height, width, 4) uint8 RGBA array (a copy), "
           "as render_png draws it.");
}

}  // namespace swarmagg::python
