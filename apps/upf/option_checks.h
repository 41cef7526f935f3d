// Checks of command-line values that CLI11's own validators let through: CLI::PositiveNumber and
// CLI::Range pass NaN (every comparison with it is false), so `--end nan` ran 0 steps and said
// ok; an empty --out silently meant the default directory. A failed check is a CLI11
// ValidationError, "OPTION: message", exit code 2. Header-only (main.cpp, commands.cpp).
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framework/scene/world_setting_specs.h"

namespace upf::app {

// --threads of every command: 0 (the default) means all of OpenMP's.
inline constexpr int kMaxThreads = 1024;

// --end: finite, > 0 and no later than the scene's /time/end may be (its spec's maximum).
inline CLI::Validator end_time_check() {
  const std::vector<ParamSpec> specs = time_setting_specs();
  const ParamSpec* end = find_spec(specs, "end");
  const double hi = end ? end->max_value : 1e7;
  return CLI::Validator(
      [hi](std::string& text) -> std::string {
        char* stop = nullptr;
        const double value = std::strtod(text.c_str(), &stop);
        if (!text.empty() && *stop == '\0' && std::isfinite(value) && value > 0 && value <= hi)
          return {};
        char range[64];
        std::snprintf(range, sizeof range, "(0, %g] s", hi);
        return "'" + text + "' is not an end time: allowed range " + range;
      },
      "", "end time");
}

// --out: a directory must be named; leaving the option out gives the default.
inline CLI::Validator non_empty_dir_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? "an empty directory name: name one, or leave the option out for "
                              "the default"
                            : "";
      },
      "", "directory");
}

}  // namespace upf::app
