// The help of the `impact` command, wrapped at 80 columns. CLI11 2.1 writes each description on
// one line however long it is; this formatter wraps the descriptions of options and subcommands
// under their column. Set on the app before its subcommands are added, it is theirs too (CLI11
// copies the parent's formatter into a new subcommand).
#pragma once

#include <CLI/CLI.hpp>
#include <sstream>
#include <string>

#include "scene/scene_help.hpp"

namespace impact::cli {

constexpr std::size_t kHelpWidth = 80;

class WrappingFormatter : public CLI::Formatter {
 public:
  // CLI11 indents the lines after a line break of a description by the name column.
  std::string make_option_desc(const CLI::Option* opt) const override {
    return wrap(CLI::Formatter::make_option_desc(opt), kHelpWidth - get_column_width());
  }
  std::string make_subcommand(const CLI::App* sub) const override {
    std::stringstream out;
    CLI::detail::format_help(out, sub->get_display_name(true),
                             wrap(sub->get_description(), kHelpWidth - get_column_width()),
                             get_column_width());
    return out.str();
  }
  std::string make_description(const CLI::App* app) const override {
    return wrap(CLI::Formatter::make_description(app), kHelpWidth);
  }
};

}  // namespace impact::cli
