#include "framework/params/param_table_markdown.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "framework/core/markdown_cell.h"

namespace upf {

namespace {

std::string printed(const char* format, int precision, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, precision, value);
  return buffer;
}

// "1.50e+05" -> "1.5e5": no plus sign, no leading exponent zeros, no trailing mantissa zeros.
std::string short_exponent(const std::string& text) {
  const auto e = text.find('e');
  std::string mantissa = text.substr(0, e);
  if (mantissa.find('.') != std::string::npos) {
    while (mantissa.back() == '0') mantissa.pop_back();
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  const int exponent = std::atoi(text.c_str() + e + 1);
  return mantissa + "e" + std::to_string(exponent);
}

}  // namespace

std::string compact_number(double value) {
  const std::string plain = printed("%.*g", 6, value);
  if (value == 0) return plain;
  // The fewest mantissa digits that give back what %g shows.
  const double shown = std::strtod(plain.c_str(), nullptr);
  std::string scientific;
  for (int digits = 0; digits <= 5; ++digits) {
    scientific = printed("%.*e", digits, value);
    if (std::strtod(scientific.c_str(), nullptr) == shown) break;
  }
  const std::string exponent_form = short_exponent(scientific);
  const int exponent = std::atoi(scientific.c_str() + scientific.find('e') + 1);
  const bool far_from_one = exponent >= 4 || exponent <= -3;
  return far_from_one && exponent_form.size() < plain.size() ? exponent_form : plain;
}

std::string param_range_text(const ParamSpec& spec) {
  std::string range = std::string(spec.exclusive_min ? "(" : "[") + compact_number(spec.min_value) +
                      ", " + compact_number(spec.max_value) + "]";
  if (spec.integer) range += ", whole number";
  return range;
}

std::string param_table_markdown(const std::vector<ParamSpec>& specs, std::string_view key_prefix) {
  std::string table = "| Key | Unit | Default | Range | Meaning |\n|---|---|---|---|---|\n";
  for (const auto& spec : specs) {
    table += "| `" + std::string(key_prefix) + spec.name + "` | " + markdown_cell(spec.unit) +
             " | " + compact_number(spec.default_value) + " | " + param_range_text(spec) + " | " +
             markdown_cell(spec.description) + " |\n";
  }
  return table;
}

}  // namespace upf
