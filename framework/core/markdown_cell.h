// Text for one cell of a Markdown table: a bare '|' inside it would end the cell. Shared by the
// comparison report and the parameter tables of the reference pages.
#pragma once

#include <string>

namespace upf {

inline std::string markdown_cell(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

}  // namespace upf
