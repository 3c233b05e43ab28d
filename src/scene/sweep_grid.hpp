// The points of a parameter sweep (`impact sweep`): axes from --vary SPECs, their Cartesian
// product, and the scene of each point built as plain values, without reading TOML again, yet the
// same Scene, bit for bit, as `impact run SCENE --set key=value ...` reads for that point
// (overrides()). Values are computed when asked for, so a sweep takes O(axes) memory however many
// points it has.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impact/methods/capabilities.hpp"
#include "impact/run/scene.hpp"
#include "read_scene.hpp"
#include "scene_error.hpp"

namespace impact {

struct KeySpec;

// One --vary: "table.key=SPEC" with SPEC `a:b:n` (n values from a to b, evenly spaced, both ends
// included), `a:b:n:log` (evenly spaced in log10; a, b > 0) or `v1,v2,...` (the numbers given).
class SweepAxis {
 public:
  // Throws SceneError naming the --vary and what is wrong; the key is checked by SweepGrid.
  explicit SweepAxis(const std::string& vary);
  // The values given, in their order (a program's own list): the same as `key=v1,v2,...`. Throws
  // SceneError for an empty list or a value that is not finite.
  SweepAxis(std::string key, std::vector<double> values);

  const std::string& key() const { return key_; }
  // How a message names the axis: "--vary KEY" for a --vary, "axis KEY" for a program's values.
  std::string named() const { return (given_ ? "axis " : "--vary ") + key_; }
  // Where value j came from, in a point's message: the --set it stands for, or the axis.
  std::string origin(std::int64_t j) const {
    return given_ ? named() : "--set " + key_ + "=" + text(j);
  }
  std::int64_t size() const { return size_; }
  // Value j, as the scene reader reads its text() (a -0 is read as 0, so it is 0 here).
  double value(std::int64_t j) const;
  // Value j as the --set text that reads back as it: 17 significant digits (round_trip).
  std::string text(std::int64_t j) const;
  // Where the smallest and the largest value are.
  std::int64_t smallest() const;
  std::int64_t largest() const;

 private:
  std::string key_;
  std::int64_t size_ = 0;
  double a_ = 0, b_ = 0;
  bool log_ = false;
  std::vector<double> list_;  // the values of `v1,v2,...`; empty for a range
  bool given_ = false;        // a program's list of values, not a --vary
};

// The keys --vary accepts: every number a scene reads (method keys only for their method), and
// internal.NAME.initial for each internal variable NAME.
std::vector<std::string> sweep_keys();

class SweepGrid {
 public:
  // Reads the scene with `overrides` and point 0's values as `impact run` does, then checks every
  // point of the product of the axes (the last axis varies fastest) as a scene: throws SceneError
  // naming the first invalid point, its values, the key and what is allowed (sweep_grid.cpp says
  // why the checks are complete).
  SweepGrid(const std::string& scene_path, const std::vector<std::string>& overrides,
            std::vector<SweepAxis> axes);
  // The same for a scene's text in memory (named in messages by its source).
  SweepGrid(const SceneText& scene, const std::vector<std::string>& overrides,
            std::vector<SweepAxis> axes);
  // The same for a scene that `load` reads with the --set strings it is given (a program's own
  // source, such as a TOML document built in memory); `source` names it in messages.
  using Loader = std::function<Run(const std::vector<std::string>&)>;
  SweepGrid(const std::string& source, const Loader& load,
            const std::vector<std::string>& overrides, std::vector<SweepAxis> axes);
  // The same for a Scene a program built (make_scene, or read and edited): point i is `scene` with
  // the axes' values set, each checked as the reader checks the key. Messages name it "the scene";
  // scene_text() is empty.
  SweepGrid(const Scene& scene, std::vector<SweepAxis> axes);

  std::int64_t size() const { return size_; }
  const std::vector<SweepAxis>& axes() const { return axes_; }
  // The scene's text, as read.
  const std::string& scene_text() const { return text_; }
  // Point 0's scene.
  const Scene& base() const { return base_; }

  // Point i's value index on axis k.
  std::int64_t index(std::int64_t i, std::size_t k) const {
    return i / strides_[k] % axes_[k].size();
  }
  // How many consecutive points share h, T and the method's keys: the stride of the fastest varied
  // time.* or method.* key, or every point when none is varied.
  std::int64_t shared_grid_run() const;
  // Sets the varied values of `scene`, a copy of base(), to point i's, and its grid.
  void apply(std::int64_t i, Scene& scene) const;
  // The --set strings that give point i's scene to `impact run` (after the sweep's own --set).
  std::vector<std::string> overrides(std::int64_t i) const;
  // "point 3 of 41 (time.h=0.0001)", for messages.
  std::string describe(std::int64_t i) const;
  // Throws the SceneError of the first point that `refuses` (a refusal of capabilities.hpp), as a
  // point's bad value is refused: its table.key, where the value came from, then `context` and
  // the refusal's message. For what the sweep asks beside its scene (the errors against the
  // reference).
  void require(const std::function<std::optional<Refusal>(const Scene&)>& refuses,
               std::string_view context) const;

 private:
  // What every constructor does before it has a scene: the axes' keys and the strides.
  SweepGrid(std::vector<SweepAxis> axes, std::string source, std::vector<std::string> overrides);
  // What every constructor does once base_ is point 0's scene: each axis's key, then every point
  // checked.
  void check_points();
  void set_values(std::int64_t i, Scene& scene) const;
  // Throws the SceneError of point i's table.key: what is wrong, where the value came from.
  [[noreturn]] void fail(std::int64_t i, std::string_view table, std::string_view key,
                         const std::string& what, bool with_value) const;

  std::string path_;
  std::vector<std::string> overrides_;
  std::vector<SweepAxis> axes_;
  std::vector<const KeySpec*> keys_;       // the scene reader's key of each axis
  std::vector<std::ptrdiff_t> variables_;  // its internal variable (internal.NAME.key), else -1
  std::vector<std::int64_t> strides_;
  std::int64_t size_ = 1;
  bool grid_varies_ = false;
  Scene base_;
  std::string text_;
};

}  // namespace impact
