// What test_scene.cpp and test_scene_keys.cpp share: a matcher for SceneError messages and a
// complete, valid scene that each case changes one thing of.
#pragma once

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "scene/read_scene.hpp"

using Catch::Contains;
using impact::parse_scene;
using impact::SceneError;

// A SceneError's message in test output.
template <>
struct Catch::StringMaker<SceneError> {
  static std::string convert(const SceneError& e) { return '"' + std::string(e.what()) + '"'; }
};

namespace impact::testing {

// Matches a SceneError whose message satisfies a string matcher.
template <class Inner>
class SceneErrorSays : public Catch::MatcherBase<SceneError> {
 public:
  explicit SceneErrorSays(Inner inner) : inner_(std::move(inner)) {}
  bool match(const SceneError& e) const override { return inner_.match(e.what()); }
  std::string describe() const override {
    return "is a SceneError whose message " + inner_.describe();
  }

 private:
  Inner inner_;
};

// The expression throws SceneError (not just any exception) and its message matches.
#define CHECK_SCENE_ERROR(expr, matcher) \
  CHECK_THROWS_MATCHES(expr, SceneError, SceneErrorSays<decltype(matcher)>(matcher))

// A complete, valid scene; the cases below change one thing at a time.
const std::string kTime = "[time]\nT = 10.0\nh = 0.001\n";
const std::string kInitial = "[initial]\nu0 = 5.0\nv0 = -1.0\n";
const std::string kDirect = "[method]\nname = \"direct\"\n";
const std::string kBase = kInitial + kTime + kDirect;

inline impact::Scene parse(const std::string& text,
                           const std::vector<std::string>& overrides = {}) {
  return parse_scene(text, "scene.toml", overrides);
}

inline std::string with_method(const std::string& method_table) {
  return kInitial + kTime + method_table;
}

}  // namespace impact::testing

using namespace impact::testing;
