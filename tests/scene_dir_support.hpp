// A scratch directory for the scene reader's tests, test_scene.cpp and test_scene_method.cpp.
#pragma once

#include <stdlib.h>  // mkdtemp

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/read_scene.hpp"
#include "scene_support.hpp"

using impact::Channel;

namespace {

// A scratch directory under /tmp, removed with everything in it.
struct TempDir {
  std::string path;
  TempDir() {
    char name[] = "/tmp/impact_scene_test_XXXXXX";
    REQUIRE(mkdtemp(name) != nullptr);
    path = name;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  std::string write(const std::string& file, const std::string& text) const {
    std::string full = path + "/" + file;
    std::ofstream(full) << text;
    return full;
  }
};

}  // namespace
