#include "module_scene.hpp"

#include <toml++/toml.h>

#include <sstream>
#include <stdexcept>

namespace py = pybind11;

namespace impact::python {
namespace {

toml::array to_array(py::handle list);
toml::table to_table(py::handle dict);

// A Python value as a TOML node, handed to `put`: bool, int, float, str, list, dict.
template <class Put>
void convert(py::handle value, Put&& put) {
  if (py::isinstance<py::bool_>(value))
    put(value.cast<bool>());
  else if (py::isinstance<py::int_>(value))
    put(value.cast<std::int64_t>());
  else if (py::isinstance<py::float_>(value))
    put(value.cast<double>());
  else if (py::isinstance<py::str>(value))
    put(value.cast<std::string>());
  else if (py::isinstance<py::dict>(value))
    put(to_table(value));
  else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value))
    put(to_array(value));
  else
    throw py::type_error("scene: a value of type " +
                         py::str(value.get_type().attr("__name__")).cast<std::string>() +
                         " is not a TOML value (bool, int, float, str, list, dict)");
}

toml::array to_array(py::handle list) {
  toml::array array;
  for (py::handle item : list) convert(item, [&](auto&& node) { array.push_back(node); });
  return array;
}

toml::table to_table(py::handle dict) {
  toml::table table;
  for (auto [key, value] : dict.cast<py::dict>())
    convert(value, [&](auto&& node) { table.insert(py::str(key).cast<std::string>(), node); });
  return table;
}

}  // namespace

std::string set_value(py::handle value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  // repr: the shortest text that reads back as the double, as one would type it after --set.
  if (py::isinstance<py::float_>(value)) return py::repr(value).cast<std::string>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  // A list (output.channels): its TOML spelling.
  std::ostringstream text;
  text << to_array(value);
  return text.str();
}

SceneSource scene_source(py::handle scene, py::handle set, py::handle method, py::handle every) {
  SceneSource source;
  if (py::isinstance<py::dict>(scene)) {
    std::ostringstream text;
    text << to_table(scene);
    source.text = text.str();
    source.name = "<dict>";
  } else if (py::isinstance<py::str>(scene) &&
             scene.cast<std::string>().find('\n') != std::string::npos) {
    source.text = scene.cast<std::string>();
    source.name = "<string>";
  } else if (py::isinstance<py::str>(scene) || py::hasattr(scene, "__fspath__")) {
    source.path = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
  } else {
    throw py::type_error("scene: a path, a TOML text or a dict");
  }
  if (py::isinstance<py::dict>(set)) {
    for (auto [k, v] : set.cast<py::dict>())
      source.overrides.push_back(py::str(k).cast<std::string>() + "=" + set_value(v));
  } else if (!set.is_none()) {
    if (py::isinstance<py::str>(set))
      throw py::type_error("set: a dict {'table.key': value} or a list of 'table.key=value'");
    for (py::handle s : set) source.overrides.push_back(py::str(s).cast<std::string>());
  }
  if (!method.is_none()) source.overrides.push_back("method.name=" + set_value(method));
  if (!every.is_none()) source.overrides.push_back("output.every=" + set_value(every));
  return source;
}

Run load(const SceneSource& source) {
  if (!source.path.empty()) return load_run(source.path, source.overrides);
  Scene scene = parse_scene(source.text, source.name, source.overrides);
  try {
    AnyStepper stepper = make_stepper(scene);
    return {std::move(scene), std::move(stepper), source.text};
  } catch (const std::invalid_argument& e) {
    throw SceneError(source.name + ": " + e.what());
  }
}

}  // namespace impact::python
