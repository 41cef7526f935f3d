// Reads the tags of the small XML headers upf writes (.pvd collections, the XML part of .vtp
// files): element names and attributes in document order, nothing else. Enough for our own
// files, whose text is machine-written; not a general XML parser (no entities beyond the five
// predefined ones, no CDATA, no DTD).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace upf::render {

struct XmlTag {
  std::string name;
  bool closing = false;       // </name>
  bool self_closing = false;  // <name ... />
  std::map<std::string, std::string, std::less<>> attributes;

  std::optional<std::string> attribute(std::string_view key) const;
};

// The tags of `text` in order; processing instructions (<?xml ...?>) and comments are skipped.
// Throws std::runtime_error with the byte offset for an unterminated tag or attribute.
std::vector<XmlTag> read_xml_tags(std::string_view text);

}  // namespace upf::render
