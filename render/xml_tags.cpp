#include "render/xml_tags.h"

#include <cctype>
#include <stdexcept>

namespace upf::render {

namespace {

bool is_space(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

std::string unescape(std::string_view s) {
  static const std::pair<std::string_view, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool replaced = false;
    if (s[i] == '&') {
      for (const auto& [entity, c] : kEntities) {
        if (s.substr(i, entity.size()) == entity) {
          out += c;
          i += entity.size();
          replaced = true;
          break;
        }
      }
    }
    if (!replaced) out += s[i++];
  }
  return out;
}

[[noreturn]] void fail(std::size_t at, const std::string& what) {
  throw std::runtime_error("malformed XML at byte " + std::to_string(at) + ": " + what);
}

}  // namespace

std::optional<std::string> XmlTag::attribute(std::string_view key) const {
  auto it = attributes.find(key);
  if (it == attributes.end()) return std::nullopt;
  return it->second;
}

std::vector<XmlTag> read_xml_tags(std::string_view text) {
  std::vector<XmlTag> tags;
  std::size_t i = 0;
  while ((i = text.find('<', i)) != std::string_view::npos) {
    const std::size_t start = i;
    if (text.substr(i, 4) == "<!--") {
      const std::size_t end = text.find("-->", i);
      if (end == std::string_view::npos) fail(start, "unterminated comment");
      i = end + 3;
      continue;
    }
    if (text.substr(i, 2) == "<?") {
      const std::size_t end = text.find("?>", i);
      if (end == std::string_view::npos) fail(start, "unterminated processing instruction");
      i = end + 2;
      continue;
    }
    XmlTag tag;
    ++i;
    if (i < text.size() && text[i] == '/') {
      tag.closing = true;
      ++i;
    }
    const std::size_t name_start = i;
    while (i < text.size() && !is_space(text[i]) && text[i] != '>' && text[i] != '/') ++i;
    tag.name = std::string(text.substr(name_start, i - name_start));
    if (tag.name.empty()) fail(start, "a tag without a name");
    for (;;) {
      while (i < text.size() && is_space(text[i])) ++i;
      if (i >= text.size()) fail(start, "unterminated tag <" + tag.name);
      if (text[i] == '>') {
        ++i;
        break;
      }
      if (text[i] == '/') {
        if (i + 1 >= text.size() || text[i + 1] != '>') fail(i, "'/' not followed by '>'");
        tag.self_closing = true;
        i += 2;
        break;
      }
      const std::size_t key_start = i;
      while (i < text.size() && text[i] != '=' && !is_space(text[i]) && text[i] != '>') ++i;
      const std::string key(text.substr(key_start, i - key_start));
      while (i < text.size() && is_space(text[i])) ++i;
      if (i >= text.size() || text[i] != '=') fail(i, "attribute '" + key + "' without a value");
      ++i;
      while (i < text.size() && is_space(text[i])) ++i;
      if (i >= text.size() || (text[i] != '"' && text[i] != '\''))
        fail(i, "attribute '" + key + "' value is not quoted");
      const char quote = text[i++];
      const std::size_t value_end = text.find(quote, i);
      if (value_end == std::string_view::npos) fail(i, "unterminated value of '" + key + "'");
      tag.attributes[key] = unescape(text.substr(i, value_end - i));
      i = value_end + 1;
    }
    tags.push_back(std::move(tag));
  }
  return tags;
}

}  // namespace upf::render
