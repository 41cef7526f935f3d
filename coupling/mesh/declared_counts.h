// PLY and OFF headers declare how many vertices and faces follow, and assimp allocates for the
// declared counts before reading them: a 197-byte PLY claiming 10^7 vertices and faces took 48 s
// and 1 GB before "no triangles". require_counts_fit checks the claim against the bytes that
// follow the header first, with lower bounds no valid file goes under:
//   binary PLY  each property its type's size; a list its count, and 3 entries in a face (a
//               polygon, by the format's definition), else none
//   ASCII PLY   2 bytes a value (a digit and a separator), counted the same way
//   OFF         2 bytes a value; a vertex 3 values, a face 4 (its count and 3 indices)
// (the last value of a file may lack its separator: 1 byte of slack). OBJ and STL declare no
// counts (binary STL's is checked by assimp against the file size). Header-only: the loader and
// its tests include it.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "coupling/mesh/mesh_error.h"

namespace upf {

namespace declared_counts_detail {

struct Claim {
  std::string name;   // "vertex", "face"
  std::string count;  // as written in the header
  double bytes = 0;   // the least the elements can take
};

// A count as written: digits only, else nullopt (left to the reader to reject).
inline std::optional<double> count_value(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return {};
  double v = 0;
  for (char c : text) v = v * 10 + (c - '0');  // inf for absurd lengths: still a claim
  return v;
}

inline double least_bytes(const std::string& count, double per_element) {
  const double n = *count_value(count);
  return per_element > 0 ? n * per_element : 0;
}

// Bytes of a binary PLY scalar type; 0 for a name PLY does not have.
inline int ply_type_size(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

struct Parsed {
  std::vector<Claim> claims;
  std::uintmax_t header_bytes = 0;
  bool text = true;  // values in ASCII (the 1 byte of slack)
};

// A PLY header's elements and their least sizes; nullopt when it is not one we understand (then
// assimp reads and judges the file as before).
// `whole`: `head` is the whole file, else its first bytes (a last line may be cut).
inline std::optional<Parsed> parse_ply(const std::string& head, bool whole) {
  std::istringstream in(head);
  std::string line;
  Parsed p;
  std::optional<bool> binary;
  std::vector<std::pair<std::string, std::string>> elements;  // name, count
  std::vector<double> per_element;
  bool first = true;
  while (std::getline(in, line)) {
    if (in.eof() && !whole) return {};  // no end_header within what was read
    p.header_bytes += line.size() + (in.eof() ? 0 : 1);
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (first) {
      if (word != "ply") return {};
      first = false;
    } else if (word == "format") {
      words >> word;
      if (word == "ascii")
        binary = false;
      else if (word == "binary_little_endian" || word == "binary_big_endian")
        binary = true;
      else
        return {};
    } else if (word == "element") {
      std::string name, count;
      words >> name >> count;
      if (!count_value(count)) return {};
      elements.emplace_back(name, count);
      per_element.push_back(0);
    } else if (word == "property") {
      if (elements.empty() || !binary.has_value()) return {};
      std::string type, count_type, entry_type;
      words >> type;
      if (type == "list") words >> count_type >> entry_type;
      const bool list = type == "list";
      const int size = ply_type_size(list ? count_type : type);
      const int entries = list && elements.back().first == "face" ? 3 : 0;
      const int entry_size = entries ? ply_type_size(entry_type) : 0;
      if (size == 0 || (entries && entry_size == 0)) return {};
      per_element.back() += *binary ? size + entries * entry_size : 2 * (1 + entries);
    } else if (word == "end_header") {
      if (!binary.has_value()) return {};
      p.text = !*binary;
      for (std::size_t e = 0; e < elements.size(); ++e)
        p.claims.push_back({elements[e].first, elements[e].second,
                            least_bytes(elements[e].second, per_element[e])});
      return p;
    }  // comment, obj_info: nothing to count
  }
  return {};
}

// The keywords after which the counts follow at once: OFF with the ST, C, N, 4 prefixes (whose
// vertices hold 3 or more values). nOFF (a dimension first) and lower case are not checked.
inline bool off_keyword(const std::string& word) {
  return word.size() >= 3 && word.ends_with("OFF") &&
         word.find_first_not_of("STCN4") == word.size() - 3;
}

// An OFF header ("OFF", comments, "NV NF NE"); nullopt when it is not one we understand.
inline std::optional<Parsed> parse_off(const std::string& head, bool whole) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (words.size() < 3 && i < head.size()) {
    if (head[i] == '#') {
      i = std::min(head.find('\n', i), head.size());
    } else if (std::isspace(static_cast<unsigned char>(head[i]))) {
      ++i;
    } else {
      const std::size_t end = std::min(head.find_first_of(" \t\r\n#", i), head.size());
      if (end == head.size() && !whole) return {};  // the word may go on past what was read
      words.push_back(head.substr(i, end - i));
      i = end;
      if (words.size() == 1 && !off_keyword(words[0])) return {};
    }
  }
  if (words.size() < 3 || !count_value(words[1]) || !count_value(words[2])) return {};
  Parsed p;
  p.header_bytes = i;
  p.claims.push_back({"vertex", words[1], least_bytes(words[1], 3 * 2)});
  p.claims.push_back({"face", words[2], least_bytes(words[2], 4 * 2)});
  return p;
}

// The largest count a header we could not parse declares: in a PLY the third word of every
// "element" line before "end_header"; in an OFF every whole number of its first two lines that
// are not comments. 0 when there is none.
inline std::uintmax_t largest_count(const std::string& head, bool ply) {
  std::istringstream in(head);
  std::string line;
  std::uintmax_t largest = 0;
  int lines = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (ply && first == "end_header") break;
    if (!ply && (first.empty() || first[0] == '#')) continue;
    if (!ply && ++lines > 2) break;
    std::vector<std::string> rest{first};
    for (std::string w; words >> w;) rest.push_back(w);
    for (std::size_t k = 0; k < rest.size(); ++k) {
      if (ply && !(first == "element" && k == 2)) continue;
      if (rest[k].empty() || rest[k].find_first_not_of("0123456789") != std::string::npos) continue;
      largest = rest[k].size() > 19 ? std::numeric_limits<std::uintmax_t>::max()
                                    : std::max<std::uintmax_t>(largest, std::stoull(rest[k]));
    }
  }
  return largest;
}

}  // namespace declared_counts_detail

// Throws InputError at `where` (see load_mesh), naming the file and the counts, when the
// header of a .ply or .off file declares more elements than the rest of the file can hold.
inline void require_counts_fit(const std::filesystem::path& file, const std::string& where) {
  namespace d = declared_counts_detail;
  std::string extension = file.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".ply" && extension != ".off") return;
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return;  // the reader says what is wrong with it
  // Headers are small; one longer than this is left to assimp unchecked.
  std::string head(std::size_t(std::min<std::uintmax_t>(size, 65536)), '\0');
  std::ifstream(file, std::ios::binary).read(head.data(), std::streamsize(head.size()));
  const bool whole = head.size() == size;
  const auto parsed = extension == ".ply" ? d::parse_ply(head, whole) : d::parse_off(head, whole);
  if (!parsed) {
    // A header we do not understand may still carry a count assimp believes (the fuzzer found a
    // mangled PLY header whose "element vertex 10000000" kept assimp busy past its timeout): no
    // element takes less than a byte, so a count beyond the file's size is refused as well.
    if (const auto count = d::largest_count(head, extension == ".ply"); count > size)
      throw mesh_error(file.string(), where,
                       "its header declares " + std::to_string(count) +
                           " elements, more than the file's " + std::to_string(size) +
                           " bytes can hold: the file is truncated or its counts are wrong");
    return;
  }
  double need = 0;
  std::string claims;
  for (const d::Claim& c : parsed->claims) {
    need += c.bytes;
    if (c.bytes > 0) claims += (claims.empty() ? "" : " and ") + c.count + " " + c.name;
  }
  const std::uintmax_t body = size - std::min(size, parsed->header_bytes);
  if (!(need > double(body) + (parsed->text ? 1 : 0))) return;
  throw mesh_error(file.string(), where,
                   "its header declares " + claims + " elements, at least " + format_number(need) +
                       " bytes of data, but only " + std::to_string(body) +
                       " bytes follow the header: the file is truncated "
                       "or its counts are wrong");
}

}  // namespace upf
