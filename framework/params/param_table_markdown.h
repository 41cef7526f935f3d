// A parameter table as Markdown, `| Key | Unit | Default | Range | Meaning |`, the form the
// reference pages use: `upf info --markdown` prints it and scripts/update-reference-docs copies
// it into docs/, so the pages show the ranges the readers enforce.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "framework/params/param_spec.h"

namespace upf {

// Like %g, but exponents written short ("1e5", "5e-3") where that is the shorter form beyond
// three decimal places, as the pages write them.
std::string compact_number(double value);

// "[1e-6, 0.5]", "(0, 1e7]", "[1, 1000], whole number".
std::string param_range_text(const ParamSpec& spec);

// The table, each key written as `key_prefix + name`: "/time/" for a world-settings section.
std::string param_table_markdown(const std::vector<ParamSpec>& specs,
                                 std::string_view key_prefix = "");

}  // namespace upf
