#include "module_scene.hpp"

#include <toml++/toml.h>

#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include "scene/scene_error.hpp"

namespace py = pybind11;

namespace impact::python {
namespace {

// How deep a scene's dicts and lists may nest: a scene's deepest value is a list in a table in a
// table ([[internal]], output.channels), far below; a deeper structure (or one that contains
// itself) is refused before its depth can exhaust the stack.
constexpr int kMaxDepth = 32;

// A Python structure as TOML, walked with the key path of the value at hand (for messages) and
// the containers on the way to it (a container met again on its own path contains itself).
class Converter {
 public:
  explicit Converter(std::string root) : path_(std::move(root)) {}

  toml::table table(py::handle dict) {
    const Enter enter(*this, dict);
    toml::table out;
    for (auto [key, value] : dict.cast<py::dict>()) {
      const std::string name = py::str(key).cast<std::string>();
      const Step step(*this, "['" + name + "']");
      convert(value, [&](auto&& node) { out.insert(name, std::move(node)); });
    }
    return out;
  }

  toml::array array(py::handle list) {
    const Enter enter(*this, list);
    toml::array out;
    std::size_t i = 0;
    for (py::handle item : list) {
      const Step step(*this, "[" + std::to_string(i++) + "]");
      convert(item, [&](auto&& node) { out.push_back(std::move(node)); });
    }
    return out;
  }

 private:
  // A container entered: its depth and its identity on the path, for as long as it is walked.
  struct Enter {
    Enter(Converter& c, py::handle container) : c(c), id(container.ptr()) {
      if (!c.open_.insert(id).second)
        throw SceneError(c.path_ +
                         ": refers back to a dict or list that holds it (a structure that "
                         "contains itself is not a TOML value)");
      if (++c.depth_ > kMaxDepth)
        throw SceneError(c.path_ + ": nested more than " + std::to_string(kMaxDepth) +
                         " levels deep; a scene's tables and lists nest a few levels");
    }
    ~Enter() {
      c.open_.erase(id);
      --c.depth_;
    }
    Converter& c;
    const void* id;
  };
  struct Step {
    Step(Converter& c, const std::string& part) : c(c), size(c.path_.size()) { c.path_ += part; }
    ~Step() { c.path_.resize(size); }
    Converter& c;
    std::size_t size;
  };

  // A Python value as a TOML node, handed to `put`: bool, int, float, str, list, tuple, dict.
  template <class Put>
  void convert(py::handle value, Put&& put) {
    if (py::isinstance<py::bool_>(value))
      put(toml::value<bool>(value.cast<bool>()));
    else if (py::isinstance<py::int_>(value))
      put(toml::value<std::int64_t>(integer(value)));
    else if (py::isinstance<py::float_>(value))
      put(toml::value<double>(value.cast<double>()));
    else if (py::isinstance<py::str>(value))
      put(toml::value<std::string>(value.cast<std::string>()));
    else if (py::isinstance<py::dict>(value))
      put(table(value));
    else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value))
      put(array(value));
    else
      throw py::type_error(path_ + " = " + repr(value) + ": a value of type " +
                           py::str(value.get_type().attr("__name__")).cast<std::string>() +
                           " is not a TOML value (bool, int, float, str, list, dict)");
  }

  std::int64_t integer(py::handle value) const {
    try {
      return value.cast<std::int64_t>();
    } catch (const py::cast_error&) {
      throw SceneError(path_ + " = " + repr(value) + ": a TOML integer is a 64-bit integer");
    }
  }

  // At most 200 characters of repr(value), so that a long list does not make a long message.
  static std::string repr(py::handle value) {
    std::string text = py::repr(value).cast<std::string>();
    if (text.size() > 200) text = text.substr(0, 200) + "...";
    return text;
  }

  std::string path_;
  std::unordered_set<const void*> open_;
  int depth_ = 0;
};

// A NumPy scalar (numpy.float64, numpy.int64, numpy.bool_) as the Python number it holds.
py::object plain(py::handle value) {
  if (py::isinstance(value, py::module_::import("numpy").attr("generic")))
    return value.attr("item")();
  return py::reinterpret_borrow<py::object>(value);
}

}  // namespace

std::string set_value(py::handle given, const std::string& what) {
  const py::object value = plain(given);
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  // repr: the shortest text that reads back as the double, as one would type it after --set.
  if (py::isinstance<py::float_>(value)) return py::repr(value).cast<std::string>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  // A list (output.channels): its TOML spelling.
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::ostringstream text;
    text << Converter(what).array(value);
    return text.str();
  }
  throw SceneError(what + " = " + py::repr(value).cast<std::string>() + ": a value of type " +
                   py::str(value.get_type().attr("__name__")).cast<std::string>() +
                   " is not one --set takes (bool, int, float, str or a list of them)");
}

SceneSource scene_source(py::handle scene, py::handle set, py::handle method, py::handle every) {
  SceneSource source;
  if (py::isinstance<py::dict>(scene)) {
    source.document = SceneDocument{Converter("scene").table(scene), "<dict>"};
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
    for (auto [k, v] : set.cast<py::dict>()) {
      const std::string key = py::str(k).cast<std::string>();
      source.overrides.push_back(key + "=" + set_value(v, "set['" + key + "']"));
    }
  } else if (!set.is_none()) {
    if (py::isinstance<py::str>(set))
      throw py::type_error("set: a dict {'table.key': value} or a list of 'table.key=value'");
    for (py::handle s : set) source.overrides.push_back(py::str(s).cast<std::string>());
  }
  if (!method.is_none()) source.overrides.push_back("method.name=" + set_value(method, "method"));
  if (!every.is_none()) source.overrides.push_back("output.every=" + set_value(every, "every"));
  return source;
}

Run load(const SceneSource& source, const std::vector<std::string>& overrides) {
  if (source.document) return load_run(*source.document, {overrides, {}});
  if (!source.path.empty()) return load_run(source.path, overrides);
  return load_run(SceneText{source.text, source.name}, overrides);
}

Run load(const SceneSource& source) {
  return load(source, source.overrides);
}

const std::string& source_name(const SceneSource& source) {
  return source.path.empty() ? source.name : source.path;
}

}  // namespace impact::python
