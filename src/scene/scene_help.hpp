// What `impact run --help` says about scenes: every key with its default and allowed values, the
// methods and the channels, printed from the tables the reader checks against (scene_keys.hpp),
// so that the help cannot drift from what is accepted.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace impact {

// The scene keys, the methods' keys, the methods and the channels, wrapped at `width` columns.
std::string scene_help(std::size_t width = 80);

// `text` wrapped at `width` columns (UTF-8 characters), its own line breaks kept. The first line
// starts at column `start` (what the caller has written before it; default `indent`), the lines
// it wraps into are indented by `indent` spaces, and those after a line break of the text by none.
std::string wrap(std::string_view text, std::size_t width, std::size_t indent = 0,
                 std::size_t start = std::string::npos);

}  // namespace impact
