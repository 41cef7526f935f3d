// The help text as a user reads it: each option with a plain placeholder (N, T, DIR, ...) and
// its description, without the parser's annotations ("INT:INT in [1 - 1024]", "Excludes: ...").
// The ranges and exclusions are still enforced; their messages say what went wrong when it does.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace upf::app {

class PlainHelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_opts(const CLI::Option* option) const override;
};

// Placeholders by option name: what the value is, not its C++ type.
std::string placeholder_for(const CLI::Option& option);

// The footers of `upf --help` and of each command's help: examples and exit codes.
std::string main_help_footer();

}  // namespace upf::app
