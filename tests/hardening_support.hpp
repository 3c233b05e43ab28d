// The helpers of the hardening tests, test_hardening.cpp and test_hardening_output.cpp.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;

using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;
const std::string kFigure3 = kSource + "/experiments/figure3/no_cor.toml";

}  // namespace
