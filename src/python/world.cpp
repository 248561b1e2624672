#include "python/world.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "python/bindings.hpp"
#include "python/errors.hpp"

namespace py = pybind11;

namespace swarmagg::python {
namespace {

// A Python value as the YAML value of a world key: bool, int, float, str, None and lists of
// them (numpy scalars through .item()). Typed, never re-read as text, as the CLI's typed
// options are.
YAML::Node yaml_value(py::handle value, const std::string& key) {
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return YAML::Node(value.cast<long long>());
  if (py::isinstance<py::float_>(value)) return YAML::Node(value.cast<double>());
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (py::handle item : value) list.push_back(yaml_value(item, key));
    return list;
  }
  if (py::hasattr(value, "dtype") && py::hasattr(value, "item"))
    return yaml_value(value.attr("item")(), key);
  throw py::type_error("set['" + key + "']: expected a bool, int, float, str, None or a list " +
                       "of them, got " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

// A `set` value as `--set` would have been written: booleans and None in YAML's words,
// numbers and strings as Python prints them, lists in brackets.
std::string value_text(py::handle value) {
  if (value.is_none()) return "null";
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string text = "[";
    for (py::handle item : value) text += (text.size() > 1 ? ", " : "") + value_text(item);
    return text + "]";
  }
  return py::str(value).cast<std::string>();
}

std::vector<std::string> set_texts(const py::dict& set) {
  std::vector<std::string> texts;
  for (const auto& [key, value] : set)
    texts.push_back(py::str(key).cast<std::string>() + "=" + value_text(value));
  return texts;
}

std::vector<WorldOverride> set_overrides(const py::dict& set) {
  std::vector<WorldOverride> overrides;
  for (const auto& [key, value] : set) {
    if (!py::isinstance<py::str>(key)) throw py::type_error("set: keys are world key paths (str)");
    const std::string path = key.cast<std::string>();
    overrides.emplace_back(path, yaml_value(value, path), "set");
  }
  return overrides;
}

World load(const std::filesystem::path& path, const py::dict& set) {
  const std::vector<WorldOverride> overrides = set_overrides(set);
  return {std::make_shared<const WorldSpec>(
              reading_file([&] { return load_world_with(path.string(), overrides); })),
          set_texts(set)};
}

std::string engine_name(const WorldSpec& spec) {
  return spec.engine.type == EngineType::Box2D ? "box2d" : "kinematic";
}

}  // namespace

World with_overrides(const World& world, const std::vector<WorldOverride>& overrides) {
  if (overrides.empty()) return world;
  auto spec = std::make_shared<WorldSpec>(*world.spec);
  for (const WorldOverride& o : overrides) apply_override(*spec, o);
  check_world(*spec);
  return {std::move(spec), world.changes};
}

void bind_world(py::module_& module) {
  py::class_<World>(module, "World",
                    "A loaded and checked world: every key resolved, immutable. Made by "
                    "load_world(); runs and simulations read it.")
      .def_property_readonly(
          "name", [](const World& w) { return w.spec->name; }, "The world's name (str).")
      .def_property_readonly(
          "source", [](const World& w) { return w.spec->source; },
          "The file it was loaded from (str).")
      .def_property_readonly(
          "agents", [](const World& w) { return w.spec->robots.count; },
          "robots.count, the number of agents (int).")
      .def_property_readonly(
          "steps", [](const World& w) { return w.spec->steps(); },
          "Steps of a run: run.duration / engine.dt (int).")
      .def_property_readonly(
          "dt", [](const World& w) { return w.spec->engine.dt; }, "engine.dt, tu per step (float).")
      .def_property_readonly(
          "replicates", [](const World& w) { return w.spec->run.replicates; },
          "run.replicates (int).")
      .def_property_readonly(
          "seed", [](const World& w) { return w.spec->run.seed; }, "run.seed (int).")
      .def_property_readonly(
          "engine", [](const World& w) { return engine_name(*w.spec); },
          "engine.type: 'kinematic' or 'box2d' (str).")
      .def(
          "to_yaml", [](const World& w) { return world_to_yaml(*w.spec); },
          "The resolved world as YAML, every key shown (what `swarmagg validate` prints); it "
          "loads back as the same world.")
      .def("__repr__", [](const World& w) {
        return "<swarmagg.World '" + w.spec->name + "': " + std::to_string(w.spec->robots.count) +
               " agents, " + std::to_string(w.spec->steps()) + " steps, " + engine_name(*w.spec) +
               ">";
      });
  module.def("load_world", &load, py::arg("path"), py::arg("set") = py::dict(),
             "Reads a world file and applies `set`, world key paths to values (as `--set` "
             "does), e.g. {'robots.count': 80}. Raises WorldError with the CLI's message.");
}

}  // namespace swarmagg::python
