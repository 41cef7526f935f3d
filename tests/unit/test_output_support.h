// Shared by the output writer tests (test_vtp_writer.cpp, test_mesh_vtp_writer.cpp): a
// temporary directory per test, catching OutputError messages, and a minimal reader for the .vtp
// files, written independently of the writers from the VTK XML file format documentation:
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
#pragma once

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "framework/core/errors.h"

namespace upf::output_test {

namespace fs = std::filesystem;

inline std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

// Each test gets its own directory, so tests may run in parallel processes (ctest -j).
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("upf_" + std::string(info->test_suite_name()) + "_" +
                                        info->name() + "_" + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  fs::path dir_;
};

// Runs `f`, expects an OutputError and returns its message.
template <class F>
std::string output_error_message(F&& f) {
  try {
    f();
  } catch (const OutputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected OutputError";
  return {};
}

// ---------------------------------------------------------------------------------------------
// A minimal reader for what write_vtp and write_mesh_vtp produce.

struct ArrayInfo {
  std::string name;
  std::string type;
  int components = 1;
  std::uint64_t offset = 0;
};

struct VtpFile {
  std::string xml;  // everything before the appended data
  std::map<std::string, std::string> piece;
  std::vector<ArrayInfo> arrays;
  std::string raw;          // the appended block, from the byte after '_'
  bool compressed = false;  // compressor="vtkZLibDataCompressor"

  std::uint64_t header_at(std::size_t at) const {
    std::uint64_t v = 0;
    EXPECT_LE(at + sizeof(v), raw.size());
    if (at + sizeof(v) <= raw.size()) std::memcpy(&v, raw.data() + at, sizeof(v));
    return v;
  }

  // One array's bytes. Raw: a UInt64 byte count, then the bytes. Compressed: UInt64 [number of
  // blocks, block size, size of the last block, compressed size of each block], then each
  // block as a zlib stream.
  std::string bytes_of(const std::string& name) const {
    for (const ArrayInfo& a : arrays) {
      if (a.name != name) continue;
      if (!compressed) {
        const std::uint64_t bytes = header_at(a.offset);
        EXPECT_LE(a.offset + sizeof(bytes) + bytes, raw.size());
        return raw.substr(a.offset + sizeof(bytes), bytes);
      }
      const std::uint64_t blocks = header_at(a.offset), block = header_at(a.offset + 8),
                          last = header_at(a.offset + 16);
      std::size_t at = a.offset + 24 + blocks * 8;
      std::string out;
      for (std::uint64_t k = 0; k < blocks; ++k) {
        const std::uint64_t packed = header_at(a.offset + 24 + k * 8);
        uLongf size = uLongf(k + 1 == blocks && last != 0 ? last : block);
        std::string part(size, '\0');
        EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(part.data()), &size,
                             reinterpret_cast<const Bytef*>(raw.data() + at), uLong(packed)),
                  Z_OK)
            << name << " block " << k;
        out += part.substr(0, size);
        at += packed;
      }
      return out;
    }
    ADD_FAILURE() << "no array named " << name;
    return {};
  }

  // Decodes one array into values of type T.
  template <class T>
  std::vector<T> decode(const std::string& name) const {
    const std::string bytes = bytes_of(name);
    EXPECT_EQ(bytes.size() % sizeof(T), 0u);
    std::vector<T> values(bytes.size() / sizeof(T));
    if (!bytes.empty()) std::memcpy(values.data(), bytes.data(), bytes.size());
    return values;
  }
  const ArrayInfo* find(const std::string& name) const {
    for (const ArrayInfo& a : arrays)
      if (a.name == name) return &a;
    return nullptr;
  }
};

// The name="value" pairs of one start tag. Hand-written rather than std::regex, whose GCC 12
// implementation trips -Wmaybe-uninitialized in optimised sanitizer builds.
inline std::map<std::string, std::string> attributes(const std::string& element) {
  std::map<std::string, std::string> attrs;
  std::size_t pos = 0;
  while ((pos = element.find("=\"", pos)) != std::string::npos) {
    const std::size_t name_begin = element.find_last_of(" \t\n", pos) + 1;
    const std::size_t value_end = element.find('"', pos + 2);
    if (value_end == std::string::npos) break;
    attrs[element.substr(name_begin, pos - name_begin)] =
        element.substr(pos + 2, value_end - pos - 2);
    pos = value_end + 1;
  }
  return attrs;
}

// Every start tag in `text` that begins with `open` (for example "<DataArray"), up to its '>'.
inline std::vector<std::string> elements(const std::string& text, const std::string& open) {
  std::vector<std::string> found;
  for (std::size_t pos = text.find(open); pos != std::string::npos;
       pos = text.find(open, pos + 1)) {
    found.push_back(text.substr(pos, text.find('>', pos) + 1 - pos));
  }
  return found;
}

inline VtpFile parse_vtp(const fs::path& p) {
  const std::string text = read_all(p);
  VtpFile f;
  const std::string marker = "<AppendedData encoding=\"raw\">";
  const std::size_t appended = text.find(marker);
  EXPECT_NE(appended, std::string::npos);
  if (appended == std::string::npos) return f;
  const std::size_t underscore = text.find('_', appended + marker.size());
  EXPECT_NE(underscore, std::string::npos);
  // Only whitespace may stand between the element and the '_'.
  EXPECT_EQ(text.find_first_not_of(" \n", appended + marker.size()), underscore);
  f.xml = text.substr(0, appended);
  f.raw = text.substr(underscore + 1);

  const std::string vtkfile = f.xml.substr(f.xml.find("<VTKFile"));
  const auto head = attributes(vtkfile.substr(0, vtkfile.find('>')));
  EXPECT_EQ(head.at("type"), "PolyData");
  EXPECT_EQ(head.at("byte_order"), "LittleEndian");
  EXPECT_EQ(head.at("header_type"), "UInt64");
  f.compressed = head.count("compressor") != 0;
  if (f.compressed) {
    EXPECT_EQ(head.at("compressor"), "vtkZLibDataCompressor");
  }

  const std::size_t piece = f.xml.find("<Piece");
  f.piece = attributes(f.xml.substr(piece, f.xml.find('>', piece) - piece));

  for (const std::string& element : elements(f.xml, "<DataArray")) {
    auto a = attributes(element);
    EXPECT_EQ(a["format"], "appended");
    ArrayInfo info;
    info.name = a["Name"];
    info.type = a["type"];
    if (a.count("NumberOfComponents")) info.components = std::stoi(a["NumberOfComponents"]);
    info.offset = std::stoull(a["offset"]);
    f.arrays.push_back(info);
  }
  return f;
}

// The elements still open at the end of `xml` (the part of a file before its appended data),
// outermost first, after checking that every end tag closes the innermost open element. Skips
// the <?xml?> declaration and self-closing elements; attribute values never hold '>' since the
// writers escape it.
inline std::vector<std::string> unclosed_elements(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t pos = xml.find('<'); pos != std::string::npos; pos = xml.find('<', pos + 1)) {
    const std::size_t end = xml.find('>', pos);
    if (end == std::string::npos) {
      ADD_FAILURE() << "unterminated tag at " << pos;
      break;
    }
    const std::string tag = xml.substr(pos + 1, end - pos - 1);
    if (tag.starts_with('?') || tag.ends_with('/')) continue;
    if (tag.starts_with('/')) {
      if (open.empty() || open.back() != tag.substr(1)) {
        ADD_FAILURE() << "</" << tag.substr(1) << "> closes "
                      << (open.empty() ? std::string("nothing") : "<" + open.back() + ">");
        break;
      }
      open.pop_back();
    } else {
      open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
    }
  }
  return open;
}

}  // namespace upf::output_test
