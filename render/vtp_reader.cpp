#include "render/vtp_reader.h"

#include <zlib.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "framework/core/errors.h"
#include "render/xml_tags.h"

namespace upf::render {

namespace {

std::size_t type_size(const std::string& type) {
  if (type == "Float32" || type == "UInt32" || type == "Int32") return 4;
  if (type == "Float64" || type == "UInt64" || type == "Int64") return 8;
  if (type == "UInt16" || type == "Int16") return 2;
  if (type == "UInt8" || type == "Int8") return 1;
  return 0;
}

template <class T>
double load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return static_cast<double>(v);
}

double load_value(const std::string& type, const char* p) {
  if (type == "Float32") return load<float>(p);
  if (type == "Float64") return load<double>(p);
  if (type == "UInt8") return load<std::uint8_t>(p);
  if (type == "Int8") return load<std::int8_t>(p);
  if (type == "UInt16") return load<std::uint16_t>(p);
  if (type == "Int16") return load<std::int16_t>(p);
  if (type == "UInt32") return load<std::uint32_t>(p);
  if (type == "Int32") return load<std::int32_t>(p);
  if (type == "UInt64") return load<std::uint64_t>(p);
  return load<std::int64_t>(p);
}

std::size_t to_count(const std::optional<std::string>& text, const std::string& what) {
  if (!text) return 0;
  try {
    std::size_t used = 0;
    const unsigned long long v = std::stoull(*text, &used);
    if (used != text->size()) throw std::invalid_argument(what);
    return static_cast<std::size_t>(v);
  } catch (const std::exception&) {
    throw std::runtime_error(what + " \"" + *text + "\" is not a whole number");
  }
}

std::uint64_t header_at(const std::string& bytes, std::size_t at, const std::string& name) {
  if (at > bytes.size() || bytes.size() - at < 8)
    throw std::runtime_error("array '" + name + "' is cut short");
  std::uint64_t v = 0;
  std::memcpy(&v, bytes.data() + at, 8);
  return v;
}

// The bytes of the array stored at `begin` of `bytes`: a UInt64 byte count and the data, or,
// compressed, UInt64 [blocks, block size, last block's size, compressed sizes] and zlib blocks.
std::string array_bytes(const std::string& bytes, std::size_t begin, bool compressed,
                        const std::string& name) {
  if (!compressed) {
    const std::uint64_t length = header_at(bytes, begin, name);
    if (length > bytes.size() - begin - 8)
      throw std::runtime_error("array '" + name + "' is cut short");
    return bytes.substr(begin + 8, length);
  }
  const std::uint64_t blocks = header_at(bytes, begin, name);
  const std::uint64_t block_size = header_at(bytes, begin + 8, name);
  const std::uint64_t last_size = header_at(bytes, begin + 16, name);
  if (blocks > bytes.size() / 8 ||
      (blocks > 0 && (block_size == 0 || block_size > (1u << 30) || last_size > block_size)))
    throw std::runtime_error("array '" + name + "' has a malformed compression header");
  std::size_t at = begin + 24 + blocks * 8;
  std::string out;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t packed = header_at(bytes, begin + 24 + b * 8, name);
    const std::uint64_t expected = b + 1 == blocks && last_size != 0 ? last_size : block_size;
    if (at > bytes.size() || packed > bytes.size() - at)
      throw std::runtime_error("array '" + name + "' is cut short");
    const std::size_t start = out.size();
    out.resize(start + expected);
    uLongf unpacked = static_cast<uLongf>(expected);
    const int rc =
        uncompress(reinterpret_cast<Bytef*>(out.data() + start), &unpacked,
                   reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uLong>(packed));
    if (rc != Z_OK || unpacked != expected)
      throw std::runtime_error("array '" + name + "' block " + std::to_string(b) +
                               " does not decompress");
    at += packed;
  }
  return out;
}

PolyData parse(const std::string& bytes) {
  const std::size_t appended = bytes.find("<AppendedData");
  if (appended == std::string::npos)
    throw std::runtime_error("no <AppendedData> block (only raw appended data is supported)");
  const std::size_t underscore = bytes.find('_', appended);
  if (underscore == std::string::npos) throw std::runtime_error("the appended data has no '_'");
  const std::size_t data_start = underscore + 1;
  const auto tags = read_xml_tags(std::string_view(bytes).substr(0, underscore));

  PolyData out;
  std::size_t points = 0, polys = 0, pieces = 0;
  std::string section;
  std::vector<double> connectivity, offsets;
  bool have_points = false;
  bool compressed = false;
  for (const XmlTag& tag : tags) {
    if (tag.name == "VTKFile" && !tag.closing) {
      if (tag.attribute("type") != "PolyData") throw std::runtime_error("not a PolyData file");
      if (tag.attribute("byte_order").value_or("LittleEndian") != "LittleEndian")
        throw std::runtime_error("big-endian data is not supported");
      if (tag.attribute("header_type").value_or("UInt32") != "UInt64")
        throw std::runtime_error("only header_type=\"UInt64\" is supported");
      if (const auto c = tag.attribute("compressor")) {
        if (*c != "vtkZLibDataCompressor")
          throw std::runtime_error("compressor " + *c + " is not supported (only zlib)");
        compressed = true;
      }
    } else if (tag.name == "Piece" && !tag.closing) {
      if (++pieces > 1) throw std::runtime_error("more than one <Piece>");
      points = to_count(tag.attribute("NumberOfPoints"), "NumberOfPoints");
      polys = to_count(tag.attribute("NumberOfPolys"), "NumberOfPolys");
    } else if (tag.name == "PointData" || tag.name == "CellData" || tag.name == "Points" ||
               tag.name == "Verts" || tag.name == "Polys" || tag.name == "Lines" ||
               tag.name == "Strips") {
      section = tag.closing || tag.self_closing ? "" : tag.name;
    } else if (tag.name == "DataArray" && !tag.closing) {
      const std::string name = tag.attribute("Name").value_or("");
      const std::string type = tag.attribute("type").value_or("");
      if (tag.attribute("format") != "appended")
        throw std::runtime_error("array '" + name + "' is not in the appended block");
      const std::size_t size = type_size(type);
      if (size == 0) throw std::runtime_error("array '" + name + "' has unknown type " + type);
      const std::size_t components =
          std::max<std::size_t>(1, to_count(tag.attribute("NumberOfComponents"), "components"));
      const std::size_t offset = to_count(tag.attribute("offset"), "offset");
      if (offset > bytes.size() - data_start)
        throw std::runtime_error("array '" + name + "' starts past the end of the file");
      const std::string data = array_bytes(bytes, data_start + offset, compressed, name);
      if (data.size() % (size * components) != 0)
        throw std::runtime_error("array '" + name + "' is of a wrong length");
      VtpArray array{name, int(components), {}};
      array.values.resize(data.size() / size);
      for (std::size_t k = 0; k < array.values.size(); ++k)
        array.values[k] = load_value(type, data.data() + k * size);
      if (section == "Points") {
        if (components != 3 || array.tuples() != points)
          throw std::runtime_error("Points does not hold 3 components per point");
        out.points.resize(points);
        for (std::size_t p = 0; p < points; ++p)
          out.points[p] =
              Eigen::Vector3d(array.values[3 * p], array.values[3 * p + 1], array.values[3 * p + 2])
                  .cast<float>();
        have_points = true;
      } else if (section == "PointData") {
        if (array.tuples() != points)
          throw std::runtime_error("point array '" + name + "' has a wrong length");
        out.point_data.push_back(std::move(array));
      } else if (section == "CellData") {
        out.cell_data.push_back(std::move(array));
      } else if (section == "Polys" && name == "connectivity") {
        connectivity = std::move(array.values);
      } else if (section == "Polys" && name == "offsets") {
        offsets = std::move(array.values);
      }
    }
  }
  if (pieces != 1) throw std::runtime_error("no <Piece>");
  if (!have_points && points > 0) throw std::runtime_error("no <Points> array");
  if (offsets.size() != polys) throw std::runtime_error("Polys offsets do not match NumberOfPolys");
  double previous = 0;
  for (std::size_t c = 0; c < polys; ++c) {
    if (offsets[c] - previous != 3 || offsets[c] > double(connectivity.size()))
      throw std::runtime_error("polygon " + std::to_string(c) + " is not a triangle");
    std::array<std::uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const double index = connectivity[std::size_t(previous) + std::size_t(k)];
      if (index < 0 || index >= double(points))
        throw std::runtime_error("triangle " + std::to_string(c) + " names a missing point");
      t[std::size_t(k)] = std::uint32_t(index);
    }
    out.triangles.push_back(t);
    previous = offsets[c];
  }
  for (const auto& a : out.cell_data)
    if (a.tuples() != polys)
      throw std::runtime_error("cell array '" + a.name + "' has a wrong length");
  return out;
}

const VtpArray* find(const std::vector<VtpArray>& arrays, std::string_view name) {
  for (const auto& a : arrays)
    if (a.name == name) return &a;
  return nullptr;
}

}  // namespace

double VtpArray::magnitude(std::size_t i) const {
  if (components == 1) return values[i];
  double s = 0;
  for (int c = 0; c < components; ++c) {
    const double v = values[i * std::size_t(components) + std::size_t(c)];
    s += v * v;
  }
  return std::sqrt(s);
}

const VtpArray* PolyData::point_array(std::string_view name) const {
  return find(point_data, name);
}
const VtpArray* PolyData::cell_array(std::string_view name) const {
  return find(cell_data, name);
}

namespace {

// The pieces a .pvtp joins, in its order, as paths beside it.
std::vector<std::filesystem::path> pvtp_sources(const std::filesystem::path& path,
                                                const std::string& bytes) {
  std::vector<std::filesystem::path> sources;
  bool parallel = false;
  for (const XmlTag& tag : read_xml_tags(bytes)) {
    if (tag.name == "VTKFile" && !tag.closing)
      parallel = tag.attribute("type") == "PPolyData";
    else if (tag.name == "Piece" && !tag.closing)
      sources.push_back(path.parent_path() / tag.attribute("Source").value_or(""));
  }
  if (!parallel) throw std::runtime_error("not a PPolyData file");
  return sources;
}

// Appends `piece`'s points and point arrays to `whole` (particle pieces: no cells).
void append_piece(PolyData& whole, PolyData piece, const std::filesystem::path& from) {
  if (!piece.triangles.empty()) throw InputError(from.string(), "a piece with polygons");
  // A rank without particles of the frame's types writes an empty piece.
  if (piece.points.empty() && !whole.point_data.empty()) return;
  if (whole.points.empty()) {
    whole = std::move(piece);
    return;
  }
  if (piece.point_data.size() != whole.point_data.size())
    throw InputError(from.string(), "its point arrays differ from the first piece's");
  whole.points.insert(whole.points.end(), piece.points.begin(), piece.points.end());
  for (std::size_t a = 0; a < piece.point_data.size(); ++a) {
    VtpArray& to = whole.point_data[a];
    const VtpArray& add = piece.point_data[a];
    if (add.name != to.name || add.components != to.components)
      throw InputError(from.string(), "array " + add.name + " differs from the first piece's");
    to.values.insert(to.values.end(), add.values.begin(), add.values.end());
  }
}

}  // namespace

PolyData read_vtp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open the frame file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::filesystem::path> sources;
  try {
    if (path.extension() != ".pvtp") return parse(bytes);
    sources = pvtp_sources(path, bytes);
  } catch (const std::runtime_error& e) {
    throw InputError(path.string(), std::string("not a frame upf can read: ") + e.what());
  }
  // A split run's frame, one piece per rank (framework/run/frame_pieces.h): one data set.
  PolyData whole;
  for (const auto& source : sources) append_piece(whole, read_vtp(source), source);
  return whole;
}

}  // namespace upf::render
