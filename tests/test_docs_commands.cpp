// The README and the pages of docs/ as a reader uses them: every ```sh block runs, in order, in a
// scratch directory of its own (exit 0 with `set -euo pipefail`), after the scenes the pages give
// as ```toml blocks whose first line names a file (`# ball.toml: ...`) are written there, the
// README's quick start among them. `build/impact`, `build/python`, `experiments/` and `examples/`
// in that directory are this build's and this checkout's, so a command reads as written and
// writes nothing outside it. Blocks fenced without `sh` are shown, not run (make targets, a
// cluster's job script). Also: every relative link of these pages names a file that exists, and
// docs/library.md shows examples/scene_run.cpp and examples/run_scene_file.cpp (built against the
// installed package by `make examples`) as they are.
#include <catch2/catch.hpp>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using impact::testing::quote;
using impact::testing::slurp;
using impact::testing::TempDir;

namespace {

const fs::path kRoot = IMPACT_SOURCE_DIR;

struct Block {
  std::string lang, text;
  int line = 0;  // of the opening fence
};

std::vector<Block> fenced_blocks(const std::string& markdown) {
  std::vector<Block> blocks;
  std::istringstream in(markdown);
  std::string line;
  int number = 0;
  Block* open = nullptr;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("```", 0) == 0) {
      if (open) {
        open = nullptr;
      } else {
        blocks.push_back({line.substr(3), "", number});
        open = &blocks.back();
      }
    } else if (open) {
      open->text += line + "\n";
    }
  }
  REQUIRE(open == nullptr);  // every fence closed
  return blocks;
}

// The file a ```toml block names in its first line, or "".
std::string scene_name(const Block& block) {
  static const std::regex named(R"(^# ([A-Za-z0-9_]+\.toml)[: ])");
  std::smatch m;
  return block.lang == "toml" && std::regex_search(block.text, m, named) ? m[1].str() : "";
}

bool python_module_built() {
  const fs::path dir = fs::path(IMPACT_BUILD_DIR) / "python";
  if (!fs::is_directory(dir)) return false;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().rfind("impact", 0) == 0) return true;
  return false;
}

// A scratch directory laid out as the checkout a reader runs the commands in.
void lay_out(const TempDir& dir) {
  fs::create_directories(dir / "build");
  fs::create_symlink(IMPACT_CLI, dir / "build/impact");
  if (python_module_built())
    fs::create_directory_symlink(fs::path(IMPACT_BUILD_DIR) / "python", dir / "build/python");
  fs::create_directory_symlink(kRoot / "experiments", dir / "experiments");
  fs::create_directory_symlink(kRoot / "examples", dir / "examples");
  // `python3` is Debian's, whose NumPy the module was built against (docs/python.md says so).
  fs::create_directories(dir / "bin");
  if (fs::exists("/usr/bin/python3")) fs::create_symlink("/usr/bin/python3", dir / "bin/python3");
}

// Writes the named scenes of `pages` and runs the ```sh blocks of the last page (with bash, as
// a reader's shell would); returns the number of blocks run.
int run_page(const TempDir& dir, const std::vector<fs::path>& pages) {
  for (const auto& page : pages)
    for (const auto& block : fenced_blocks(slurp(page.string())))
      if (const auto name = scene_name(block); !name.empty()) dir.write(name, block.text);
  int ran = 0;
  for (const auto& block : fenced_blocks(slurp(pages.back().string()))) {
    if (block.lang != "sh") continue;
    INFO(pages.back().filename().string() << ", the block at line " << block.line << ":\n"
                                          << block.text);
    if (block.text.find("python3") != std::string::npos && !python_module_built()) {
      WARN("skipped: this build has no Python module (make asan-test, or pybind11 missing)");
      continue;
    }
    const auto script = dir.write(".block.sh", block.text);
    const auto r =
        dir.shell("PATH=" + quote(dir / "bin") + ":\"$PATH\" bash -euo pipefail " + quote(script));
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.code == 0);
    ++ran;
  }
  return ran;
}

std::vector<fs::path> docs_pages() {
  std::vector<fs::path> pages;
  for (const auto& entry : fs::directory_iterator(kRoot / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  std::sort(pages.begin(), pages.end());
  return pages;
}

}  // namespace

TEST_CASE("the README's quick start runs its scene and plots it", "[docs]") {
  TempDir dir;
  lay_out(dir);
  CHECK(run_page(dir, {kRoot / "README.md"}) == 1);
  CHECK(slurp(dir / "ball.csv").rfind("t,u,v,N,E\n", 0) == 0);
  CHECK(slurp(dir / "ball_events.csv").rfind("t,kind,v_before,v_after\n", 0) == 0);
  CHECK(slurp(dir / "ball.png").rfind("\x89PNG\r\n\x1a\n", 0) == 0);
}

TEST_CASE("the runnable commands of every page of docs/ run", "[docs]") {
  const auto pages = docs_pages();
  REQUIRE(pages.size() >= 8);
  for (const auto& page : pages) {
    DYNAMIC_SECTION(page.filename().string()) {
      TempDir dir;
      lay_out(dir);
      run_page(dir, {kRoot / "README.md", page});
    }
  }
}

TEST_CASE("every relative link of the README and docs/ names a file that exists", "[docs]") {
  auto pages = docs_pages();
  pages.push_back(kRoot / "README.md");
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  int links = 0;
  for (const auto& page : pages) {
    const std::string text = slurp(page.string());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), link);
         it != std::sregex_iterator(); ++it) {
      std::string target = (*it)[1].str();
      if (target.rfind("http", 0) == 0 || target[0] == '#') continue;
      target = target.substr(0, target.find('#'));
      INFO(page.filename().string() << " links to " << target);
      CHECK(fs::exists(page.parent_path() / target));
      ++links;
    }
  }
  CHECK(links > 50);
}

TEST_CASE("docs/library.md shows examples/scene_run.cpp as it is", "[docs]") {
  const std::string page = slurp((kRoot / "docs/library.md").string());
  const std::string program = slurp((kRoot / "examples/scene_run.cpp").string());
  REQUIRE(!program.empty());
  CHECK(page.find("```cpp\n" + program + "```\n") != std::string::npos);
}

TEST_CASE("docs/library.md shows examples/run_scene_file.cpp as it is", "[docs]") {
  const std::string page = slurp((kRoot / "docs/library.md").string());
  const std::string program = slurp((kRoot / "examples/run_scene_file.cpp").string());
  REQUIRE(!program.empty());
  CHECK(page.find("```cpp\n" + program + "```\n") != std::string::npos);
}
