#include "python/world.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "python/bindings.hpp"
#include "python/errors.hpp"
#include "python/python_text.hpp"

namespace py = pybind11;

namespace swarmagg::python {

YAML::Node yaml_integer(py::handle value, const std::string& name) {
  const py::int_ integer = py::reinterpret_borrow<py::int_>(value);
  int overflow = 0;
  const long long signed_value = PyLong_AsLongLongAndOverflow(integer.ptr(), &overflow);
  if (overflow == 0) return YAML::Node(signed_value);
  if (overflow > 0) {
    const unsigned long long unsigned_value = PyLong_AsUnsignedLongLong(integer.ptr());
    if (!PyErr_Occurred()) return YAML::Node(unsigned_value);
    PyErr_Clear();
  }
  throw InputError(name + ": " + py::str(value).cast<std::string>() + " does not fit in 64 bits");
}

YAML::Node yaml_index(py::handle value, const std::string& name) {
  if (py::isinstance<py::bool_>(value))
    throw py::type_error(name + ": expected an integer, got a bool");
  // Any integer Python can use as an index (numpy's too); a float is a TypeError.
  PyObject* index = PyNumber_Index(value.ptr());
  if (index == nullptr) throw py::error_already_set();
  return yaml_integer(py::reinterpret_steal<py::object>(index), name);
}

namespace {

// Deeper lists are refused rather than followed (a list holding itself would never end); a
// world file is refused past 499 levels too.
constexpr int kDeepestSetValue = 499;

// A Python float as YAML text that reads back as the same double and never as an integer, so
// that 80.0 is refused where a whole number is expected, as `80.0` in a world file is.
YAML::Node yaml_float(double value) {
  YAML::Node node(value);
  std::string text = node.Scalar();
  if (std::isfinite(value) && text.find_first_of(".eE") == std::string::npos) text += ".0";
  return YAML::Node(text);
}

// A numpy scalar or array, whose tolist() gives the Python scalar or (nested) list of it.
bool is_numpy(py::handle value) {
  return py::hasattr(value, "dtype") && py::hasattr(value, "tolist");
}

// The Python value of a numpy scalar or array. numpy's long double is its own tolist(): it is
// read as the float it rounds to; a long double complex has no value a world key takes.
py::object python_value_of_numpy(py::handle value, const std::string& key) {
  py::object plain = value.attr("tolist")();
  if (!is_numpy(plain)) return plain;
  const std::string kind = py::str(plain.attr("dtype").attr("kind"));
  if (kind == "f") return py::float_(py::reinterpret_borrow<py::object>(plain));
  if (kind != "c") return plain;  // an object array's element: followed, as far as the guard
  throw py::type_error("set['" + key + "']: expected a bool, int, float, str, None or a list " +
                       "of them, got numpy " + std::string(py::str(plain.attr("dtype"))));
}

// A Python value as the YAML value of a world key: bool, int, float, str, None and lists of
// them (numpy scalars and arrays through .tolist()). A str is what a quoted scalar of a world file
// would be; an int beyond 64 bits is refused here, naming the key.
YAML::Node yaml_value(py::handle value, const std::string& key, int depth = 0) {
  if (depth > kDeepestSetValue) {
    throw InputError("set['" + key + "']: nested more than " + std::to_string(kDeepestSetValue) +
                     " levels deep");
  }
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return yaml_integer(value, "set['" + key + "']");
  if (py::isinstance<py::float_>(value)) return yaml_float(value.cast<double>());
  if (py::isinstance<py::str>(value)) return YAML::Node(utf8_text(value, "set['" + key + "']"));
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (py::handle item : value) list.push_back(yaml_value(item, key, depth + 1));
    return list;
  }
  if (is_numpy(value)) return yaml_value(python_value_of_numpy(value, key), key, depth + 1);
  throw py::type_error("set['" + key + "']: expected a bool, int, float, str, None or a list " +
                       "of them, got " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

// A `set` value as `--set` would have been written: booleans and None in YAML's words,
// numbers and strings as Python prints them, lists in brackets.
std::string value_text(py::handle value, const std::string& key) {
  if (is_numpy(value)) return value_text(python_value_of_numpy(value, key), key);
  if (value.is_none()) return "null";
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string text = "[";
    for (py::handle item : value) text += (text.size() > 1 ? ", " : "") + value_text(item, key);
    return text + "]";
  }
  return utf8_text(py::str(value), "set['" + key + "']");
}

std::vector<std::string> set_texts(const py::dict& set) {
  std::vector<std::string> texts;
  for (const auto& [key, value] : set) {
    const std::string path = utf8_text(key, "set");
    texts.push_back(path + "=" + value_text(value, path));
  }
  return texts;
}

std::vector<WorldOverride> set_overrides(const py::dict& set) {
  std::vector<WorldOverride> overrides;
  for (const auto& [key, value] : set) {
    if (!py::isinstance<py::str>(key)) throw py::type_error("set: keys are world key paths (str)");
    const std::string path = utf8_text(key, "set: a key");
    overrides.emplace_back(path, yaml_value(value, path), "set");
  }
  return overrides;
}

World load(const std::filesystem::path& path, const py::dict& set) {
  const std::vector<WorldOverride> overrides = reading_file([&] { return set_overrides(set); });
  return {std::make_shared<const WorldSpec>(
              reading_file([&] { return load_world_with(path.string(), overrides); })),
          set_texts(set)};
}

std::string engine_name(const WorldSpec& spec) {
  return spec.engine.type == EngineType::Box2D ? "box2d" : "kinematic";
}

// A world's pickle: its resolved YAML (to_yaml(), which loads back as the same world), the file
// it came from and what `set` changed, so that a world reaches multiprocessing's workers.
using WorldState = std::tuple<std::string, std::filesystem::path, std::vector<std::string>>;

WorldState world_state(const World& world) {
  return {world_to_yaml(*world.spec), world.spec->source, world.changes};
}

World world_from_state(const WorldState& state) {
  const auto& [yaml, source, changes] = state;
  return {std::make_shared<const WorldSpec>(
              reading_file([&] { return load_world_text_with(yaml, source.string(), {}); })),
          changes};
}

// A world run again with another value of a key it changed (a seed, say) names the value the
// run used, once, where the first change stood: as the CLI would for the world file given
// every change at once.
void record_change(std::vector<std::string>& changes, const std::string& key,
                   const std::string& value) {
  const std::string prefix = key + "=";
  const auto earlier = std::find_if(changes.begin(), changes.end(),
                                    [&](const std::string& c) { return c.starts_with(prefix); });
  if (earlier == changes.end()) {
    changes.push_back(prefix + value);
  } else {
    *earlier = prefix + value;
  }
}

}  // namespace

std::string utf8_text(py::handle text, const std::string& what) {
  Py_ssize_t size = 0;
  const char* utf8 = PyUnicode_AsUTF8AndSize(text.ptr(), &size);
  if (utf8 != nullptr) return {utf8, static_cast<std::size_t>(size)};
  PyErr_Clear();
  throw InputError(what + ": expected text that UTF-8 can hold, got " +
                   std::string(py::str(py::repr(text))) +
                   " (a name os.fsdecode made of bytes that are not UTF-8?)");
}

World with_overrides(const World& world, const std::vector<WorldOverride>& overrides) {
  if (overrides.empty()) return world;
  auto spec = std::make_shared<WorldSpec>(*world.spec);
  std::vector<std::string> changes = world.changes;
  for (const WorldOverride& o : overrides) {
    apply_override(*spec, o);
    if (o.key != "run.threads") record_change(changes, o.key, o.value.Scalar());
  }
  check_world(*spec);
  return {std::move(spec), std::move(changes)};
}

void bind_world(py::module_& module) {
  py::class_<World> world(module, "World",
                          "A loaded and checked world: every key resolved, immutable. Made by "
                          "load_world(); runs and simulations read it. Copies are the world "
                          "itself; a pickle holds its resolved YAML.");
  copied_as_itself(world);
  pickled_by_state(world, &world_state, &world_from_state);
  world
      .def_property_readonly(
          "name", [](const World& w) { return w.spec->name; }, "The world's name (str).")
      .def_property_readonly(
          "source", [](const World& w) { return python_path(w.spec->source); },
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
