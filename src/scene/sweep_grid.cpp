#include "scene/sweep_grid.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "impact/format.hpp"
#include "scene/read_scene.hpp"
#include "scene/scene_keys.hpp"
#include "scene/toml_text.hpp"
#include "scene/validate.hpp"

namespace impact {
namespace {

// A finite decimal number, the whole of `text` (a leading + allowed).
std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double x;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(x))
    return std::nullopt;
  return x;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

}  // namespace

SweepAxis::SweepAxis(const std::string& vary) {
  const auto fail = [&](const std::string& why) {
    throw SceneError("--vary " + vary + ": " + why +
                     " (SPEC: a:b:n, a:b:n:log or v1,v2,..., e.g. time.h=1e-4:1e-2:41:log)");
  };
  const std::size_t eq = vary.find('=');
  if (eq == std::string::npos || eq == 0) fail("expected table.key=SPEC");
  key_ = vary.substr(0, eq);
  const std::string_view spec = std::string_view(vary).substr(eq + 1);
  const auto number = [&](std::string_view text) {
    const auto x = parse_number(text);
    if (!x) fail("'" + std::string(text) + "' is not a finite number");
    return *x;
  };
  if (spec.find(':') == std::string_view::npos) {
    for (std::string_view item : split(spec, ',')) list_.push_back(number(item));
    size_ = static_cast<std::int64_t>(list_.size());
    return;
  }
  const auto parts = split(spec, ':');
  if (parts.size() != 3 && !(parts.size() == 4 && parts[3] == "log"))
    fail("a range is a:b:n or a:b:n:log");
  a_ = number(parts[0]);
  b_ = number(parts[1]);
  log_ = parts.size() == 4;
  const auto [end, error] =
      std::from_chars(parts[2].data(), parts[2].data() + parts[2].size(), size_);
  if (error != std::errc() || end != parts[2].data() + parts[2].size() || size_ < 1)
    fail("n = '" + std::string(parts[2]) + "' is not a whole number >= 1");
  if (size_ == 1 && a_ != b_) fail("n = 1 value cannot include both ends a != b");
  if (log_ && !(a_ > 0 && b_ > 0)) fail("a logarithmic range needs a > 0 and b > 0");
}

double SweepAxis::value(std::int64_t j) const {
  double x;
  if (!list_.empty()) {
    x = list_[static_cast<std::size_t>(j)];
  } else if (j == 0 || j == size_ - 1) {
    x = j == 0 ? a_ : b_;  // both ends exactly as given
  } else {
    // std::lerp is exact at its ends and monotonic, so the values stay between a and b.
    const double t = static_cast<double>(j) / static_cast<double>(size_ - 1);
    x = log_ ? std::pow(10.0, std::lerp(std::log10(a_), std::log10(b_), t)) : std::lerp(a_, b_, t);
  }
  // round_trip(-0.0) is "-0", which TOML reads as the integer 0.
  return x == 0 ? 0.0 : x;
}

std::string SweepAxis::text(std::int64_t j) const {
  return round_trip(value(j));
}

std::int64_t SweepAxis::smallest() const {
  if (list_.empty()) return a_ <= b_ ? 0 : size_ - 1;
  return std::min_element(list_.begin(), list_.end()) - list_.begin();
}

std::int64_t SweepAxis::largest() const {
  if (list_.empty()) return a_ <= b_ ? size_ - 1 : 0;
  return std::max_element(list_.begin(), list_.end()) - list_.begin();
}

namespace {

// The keys --vary accepts: the numbers and integers of the scene reader's key tables
// (scene_keys.hpp), whose accessors store them in a Scene as the reader does; a [method] key is
// the scene's method's.
// output.every is a number too, but a sweep writes a summary per point, not rows.
bool numeric(const KeySpec& spec) {
  return (spec.type == KeyType::number || spec.type == KeyType::integer) && spec.table != "output";
}

std::string full_name(const KeySpec& spec) {
  return std::string(spec.table) + "." + std::string(spec.key);
}

// Every number a scene reads, once each ("method.rtol" is penalty's and event_driven's).
const std::vector<std::string>& numeric_key_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto keys : {scene_keys(), method_keys()})
      for (const KeySpec& spec : keys)
        if (numeric(spec) && std::find(out.begin(), out.end(), full_name(spec)) == out.end())
          out.push_back(full_name(spec));
    return out;
  }();
  return names;
}

// The spec of `name` for a scene of `method`; nullptr when that method reads no such number.
const KeySpec* numeric_spec(const std::string& name, std::string_view method) {
  for (const auto keys : {scene_keys(), method_keys()})
    for (const KeySpec& spec : keys)
      if (numeric(spec) && full_name(spec) == name &&
          (spec.method().empty() || spec.method() == method))
        return &spec;
  return nullptr;
}

// internal.NAME.key for a number key of [[internal]] (initial): the spec, else nullptr.
const KeySpec* internal_number(const std::string& name) {
  const auto internal = internal_key(name);
  return internal && internal->spec && numeric(*internal->spec) ? internal->spec : nullptr;
}

}  // namespace

std::vector<std::string> sweep_keys() {
  std::vector<std::string> keys = numeric_key_names();
  for (const KeySpec& spec : internal_keys())
    if (numeric(spec)) keys.push_back("internal.NAME." + std::string(spec.key));
  return keys;
}

SweepAxis::SweepAxis(std::string key, std::vector<double> values)
    : key_(std::move(key)),
      size_(static_cast<std::int64_t>(values.size())),
      list_(std::move(values)),
      given_(true) {
  if (list_.empty()) throw SceneError("axis " + key_ + ": no values");
  for (double& x : list_) {
    if (!std::isfinite(x))
      throw SceneError("axis " + key_ + ": " + shortest(x) + " is not a finite number");
    x += 0.0;  // -0 as the reader reads it: 0
  }
}

SweepGrid::SweepGrid(const std::string& scene_path, const std::vector<std::string>& overrides,
                     std::vector<SweepAxis> axes)
    : SweepGrid(
          scene_path,
          [&](const std::vector<std::string>& all) { return load_run(scene_path, all); }, overrides,
          std::move(axes)) {}

SweepGrid::SweepGrid(const SceneText& scene, const std::vector<std::string>& overrides,
                     std::vector<SweepAxis> axes)
    : SweepGrid(
          scene.source, [&](const std::vector<std::string>& all) { return load_run(scene, all); },
          overrides, std::move(axes)) {}

SweepGrid::SweepGrid(std::vector<SweepAxis> axes, std::string source,
                     std::vector<std::string> overrides)
    : path_(std::move(source)), overrides_(std::move(overrides)), axes_(std::move(axes)) {
  const auto& names = numeric_key_names();
  for (const SweepAxis& axis : axes_) {
    if (std::find(names.begin(), names.end(), axis.key()) == names.end() &&
        !internal_number(axis.key())) {
      const std::vector<std::string> keys = sweep_keys();
      std::vector<std::string_view> allowed(keys.begin(), keys.end());
      throw SceneError(axis.named() + ": not a key a sweep can vary (allowed: " + join(allowed) +
                       "; method.name and force.expression are not numbers, nor is "
                       "internal.NAME.rate: one sweep per value; the [output] keys do not change "
                       "a summary)");
    }
    for (const SweepAxis& other : axes_)
      if (&other != &axis && other.key() == axis.key())
        throw SceneError(axis.named() + ": the key is varied twice");
    grid_varies_ = grid_varies_ || axis.key() == "time.T" || axis.key() == "time.h";
  }
  // Strides for "the last axis varies fastest"; at most 2^53 points, so that a point's index and
  // the count of points done are exact as doubles too.
  strides_.assign(axes_.size(), 1);
  for (std::size_t k = axes_.size(); k-- > 0;) {
    strides_[k] = size_;
    if (__builtin_mul_overflow(size_, axes_[k].size(), &size_) || size_ > (std::int64_t{1} << 53))
      throw SceneError("--vary: more than 2^53 points");
  }
}

SweepGrid::SweepGrid(const std::string& source, const Loader& load,
                     const std::vector<std::string>& overrides, std::vector<SweepAxis> axes)
    : SweepGrid(std::move(axes), source, overrides) {
  try {
    std::vector<std::string> all = overrides_;
    for (const std::string& o : this->overrides(0)) all.push_back(o);
    Run read = load(all);
    base_ = std::move(read.scene);
    text_ = std::move(read.text);
  } catch (const SceneError& e) {
    throw SceneError(describe(0) + ": " + e.what());
  }
  check_points();
}

SweepGrid::SweepGrid(const Scene& scene, std::vector<SweepAxis> axes)
    : SweepGrid(std::move(axes), "the scene", {}) {
  base_ = scene;
  // What the reader refuses when it reads a file: a [method] key of another method than the
  // scene's, an internal variable the scene does not have.
  for (const SweepAxis& axis : axes_) {
    if (!internal_number(axis.key())) {
      if (!numeric_spec(axis.key(), method_name(base_.method)))
        throw SceneError(describe(0) + ": " + axis.key() + " is not a key of the scene's method " +
                         std::string(method_name(base_.method)));
      continue;
    }
    const std::string name = internal_key(axis.key())->name;
    if (std::none_of(scene.model.internal.begin(), scene.model.internal.end(),
                     [&](const InternalVariable& z) { return z.name == name; }))
      throw SceneError(describe(0) + ": " + axis.key() + ": the scene has no internal variable " +
                       name);
  }
  check_points();
  apply(0, base_);  // base() is point 0's scene, as the reader reads it
}

void SweepGrid::check_points() {
  // A [method] key of another method than the scene's was refused by the reader above.
  // An internal variable's key: the variable, which the reader found (point 0 set it).
  for (const SweepAxis& axis : axes_) {
    std::ptrdiff_t variable = -1;
    const KeySpec* spec = internal_number(axis.key());
    if (spec) {
      const std::string name = internal_key(axis.key())->name;
      for (std::size_t i = 0; i < base_.model.internal.size(); ++i)
        if (base_.model.internal[i].name == name) variable = static_cast<std::ptrdiff_t>(i);
    } else {
      spec = numeric_spec(axis.key(), method_name(base_.method));
    }
    if (!spec || (spec->set_variable && variable < 0))
      throw std::logic_error(axis.named() + ": the reader took a key it has not");
    keys_.push_back(spec);
    variables_.push_back(variable);
  }
  // The scene reader's checks on plain values (validate.hpp, capabilities.hpp), the same functions
  // the reader calls: every value of every axis against its key's range (a point with the other
  // axes at their first values names it), then what joins keys and what the method refuses, at
  // every point.
  for (std::size_t k = 0; k < axes_.size(); ++k)
    for (std::int64_t j = 0; j < axes_[k].size(); ++j)
      if (const auto wrong = check_value(*keys_[k], axes_[k].value(j)))
        fail(j * strides_[k], keys_[k]->table, keys_[k]->key, *wrong, true);
  Scene scene = base_;
  for (std::int64_t i = 0; i < size_; ++i) {
    set_values(i, scene);
    const ShowKey shortest_value = [&](std::string_view, std::string_view) {
      return shortest(scene.T);  // the one other key a check shows
    };
    if (const auto issue = cross_check(scene, shortest_value))
      fail(i, issue->table, issue->key, issue->what, issue->with_value);
    // What the method refuses at this point (a step (5-1) cannot take, a bonding field that acts
    // from some gamma on), as the reader refuses it. A refusal that names a [method] key shows no
    // value: its message names the method, which is point 0's (method.name is not a number).
    if (const auto refused = refusal(scene.method, scene.model, scene.grid.h))
      fail(i, refused->table, refused->key, refused->message, refused->table != "method");
  }
}

void SweepGrid::fail(std::int64_t i, std::string_view table, std::string_view key,
                     const std::string& what, bool with_value) const {
  const std::string name = std::string(table) + "." + std::string(key);
  // Where the value came from: this point's --vary, else the last --set of the key, else the file.
  std::string origin = path_, value;
  for (const std::string& set : overrides_)
    if (set.starts_with(name + "=")) origin = "--set " + set;
  for (std::size_t k = 0; k < axes_.size(); ++k)
    if (axes_[k].key() == name) {
      value = axes_[k].text(index(i, k));
      origin = axes_[k].origin(index(i, k));
    }
  if (value.empty() && with_value) {
    Scene scene = base_;
    set_values(i, scene);
    value = show_float(name == "initial.u0" ? scene.initial.u : scene.grid.h);
  }
  throw SceneError(describe(i) + ": " + origin + ": " + name + (with_value ? " = " + value : "") +
                   ": " + what);
}

std::int64_t SweepGrid::shared_grid_run() const {
  for (std::size_t k = axes_.size(); k-- > 0;)
    if (axes_[k].key().starts_with("time.") || axes_[k].key().starts_with("method."))
      return strides_[k];
  return size_;
}

void SweepGrid::set_values(std::int64_t i, Scene& scene) const {
  for (std::size_t k = 0; k < axes_.size(); ++k) {
    const double x = axes_[k].value(index(i, k));
    const KeySpec& spec = *keys_[k];
    const KeyValue value =
        spec.type == KeyType::integer ? KeyValue(static_cast<std::int64_t>(x)) : KeyValue(x);
    if (variables_[k] >= 0)
      spec.set_variable(scene.model.internal[static_cast<std::size_t>(variables_[k])], value);
    else
      spec.set(scene, value);
  }
}

void SweepGrid::apply(std::int64_t i, Scene& scene) const {
  set_values(i, scene);
  if (grid_varies_) scene.grid = Grid::covering(scene.T, scene.grid.h);
}

std::vector<std::string> SweepGrid::overrides(std::int64_t i) const {
  std::vector<std::string> sets;
  for (std::size_t k = 0; k < axes_.size(); ++k)
    sets.push_back(axes_[k].key() + "=" + axes_[k].text(index(i, k)));
  return sets;
}

void SweepGrid::require(const std::function<std::optional<Refusal>(const Scene&)>& refuses,
                        std::string_view context) const {
  Scene scene = base_;
  for (std::int64_t i = 0; i < size_; ++i) {
    set_values(i, scene);
    if (const auto refused = refuses(scene)) {
      std::string what(context);
      what += ": ";
      what += refused->message;
      // The value is shown where an axis gives it (fail() shows no other key's value).
      const std::string name = std::string(refused->table) + "." + std::string(refused->key);
      const bool varied = std::any_of(axes_.begin(), axes_.end(),
                                      [&](const SweepAxis& axis) { return axis.key() == name; });
      fail(i, refused->table, refused->key, what, varied);
    }
  }
}

std::string SweepGrid::describe(std::int64_t i) const {
  std::string text = "point " + std::to_string(i + 1) + " of " + std::to_string(size_) + " (";
  const auto sets = overrides(i);
  for (std::size_t k = 0; k < sets.size(); ++k) text += (k ? ", " : "") + sets[k];
  return text + ")";
}

}  // namespace impact
