// VTK XML PolyData writer with raw appended binary data. Format: VTK XML file format
// documentation, https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
//
// Layout: the XML header lists every DataArray with format="appended" and an offset into the
// <AppendedData encoding="raw"> block, which starts after a '_' and holds, per array, a UInt64
// byte count followed by the array's bytes in the file's byte order.
#include "framework/output/vtp_writer.h"

#include <bit>
#include <cstdint>
#include <numeric>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "framework/output/atomic_file.h"

namespace upf {

namespace {

// The raw arrays are written straight from memory, so the declared types must match the layout.
static_assert(sizeof(Vec3) == 3 * sizeof(Real), "Vec3 must be three packed Reals");
static_assert(std::is_standard_layout_v<Vec3>);
static_assert(sizeof(ParticleType) == 1, "type is written as UInt8");
static_assert(std::is_same_v<ParticleId, std::uint32_t>, "id is written as UInt32");
static_assert(std::is_same_v<MaterialId, std::uint16_t>, "material is written as UInt16");
static_assert(std::endian::native == std::endian::little ||
              std::endian::native == std::endian::big);

constexpr const char* kRealType = std::is_same_v<Real, double> ? "Float64" : "Float32";
// Raw data is written in host order, so the file declares the host's order.
constexpr const char* kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

using Header = std::uint64_t;  // header_type="UInt64": no 4 GiB limit per array.

struct Array {
  std::string name;
  const char* type;
  int components;
  const void* data;
  std::size_t bytes;
};

template <class T>
Array make_array(std::string name, const char* type, int components, const std::vector<T>& v) {
  return {std::move(name), type, components, v.data(), v.size() * sizeof(T)};
}

// Appends the DataArray elements of `arrays` to `xml`, advancing the appended-data offset.
void describe(std::string& xml, const std::vector<Array>& arrays, std::uint64_t& offset,
              const char* indent) {
  for (const Array& a : arrays) {
    xml += indent;
    xml += "<DataArray type=\"";
    xml += a.type;
    xml += "\" Name=\"" + xml_escape(a.name) + "\" NumberOfComponents=\"" +
           std::to_string(a.components) + "\" format=\"appended\" offset=\"" +
           std::to_string(offset) + "\"/>\n";
    offset += sizeof(Header) + a.bytes;
  }
}

void check_size(const std::string& name, std::size_t values, std::size_t n) {
  // A short array would silently shift every later array in the appended block.
  if (values != n) {
    throw std::logic_error("write_vtp: field '" + name + "' has " + std::to_string(values) +
                           " values for " + std::to_string(n) + " particles");
  }
}

}  // namespace

std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void write_vtp(const std::filesystem::path& path, const Particles& particles,
               const std::vector<std::string>& fields) {
  const std::size_t n = particles.size();
  check_size("velocity", particles.velocity.size(), n);
  check_size("type", particles.type.size(), n);
  check_size("material", particles.material.size(), n);
  check_size("id", particles.id.size(), n);

  std::vector<Array> point_data = {
      make_array("id", "UInt32", 1, particles.id),
      make_array("type", "UInt8", 1, particles.type),
      make_array("material", "UInt16", 1, particles.material),
      make_array("velocity", kRealType, 3, particles.velocity),
  };
  std::set<std::string> written = {"id", "type", "material", "velocity"};
  for (const std::string& name : fields) {
    if (!written.insert(name).second)
      continue;  // VTK keeps one array per name: a repeat is dead weight
    if (const auto* s = particles.find_scalar(name)) {
      check_size(name, s->size(), n);
      point_data.push_back(make_array(name, kRealType, 1, *s));
    } else if (const auto* v = particles.find_vector(name)) {
      check_size(name, v->size(), n);
      point_data.push_back(make_array(name, kRealType, 3, *v));
    }
  }

  // Vertex i is point i: connectivity is 0..n-1 and the (end) offsets are 1..n, so one sequence
  // 0..n serves both arrays.
  std::vector<std::int64_t> sequence(n + 1);
  std::iota(sequence.begin(), sequence.end(), std::int64_t{0});
  const std::size_t index_bytes = n * sizeof(std::int64_t);
  const std::vector<Array> points = {
      make_array("Points", kRealType, 3, particles.position),
  };
  const std::vector<Array> verts = {
      {"connectivity", "Int64", 1, sequence.data(), index_bytes},
      {"offsets", "Int64", 1, sequence.data() + 1, index_bytes},
  };

  // Offsets are formatted with std::to_string, which ignores any global stream locale.
  const std::string count = std::to_string(n);
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"";
  xml += kByteOrder;
  xml += "\" header_type=\"UInt64\">\n";
  xml += "  <PolyData>\n";
  xml += "    <Piece NumberOfPoints=\"" + count + "\" NumberOfVerts=\"" + count +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  std::uint64_t offset = 0;
  xml += "      <PointData>\n";
  describe(xml, point_data, offset, "        ");
  xml += "      </PointData>\n";
  xml += "      <Points>\n";
  describe(xml, points, offset, "        ");
  xml += "      </Points>\n";
  xml += "      <Verts>\n";
  describe(xml, verts, offset, "        ");
  xml += "      </Verts>\n";
  xml += "    </Piece>\n";
  xml += "  </PolyData>\n";
  xml += "  <AppendedData encoding=\"raw\">\n   _";

  write_file_atomically(path, [&](std::ostream& out) {
    out.write(xml.data(), static_cast<std::streamsize>(xml.size()));
    for (const std::vector<Array>* group : {&std::as_const(point_data), &points, &verts}) {
      for (const Array& a : *group) {
        const Header bytes = a.bytes;
        out.write(reinterpret_cast<const char*>(&bytes), sizeof(bytes));
        // An empty vector's data() may be null, which write() must not see.
        if (a.bytes > 0) {
          out.write(static_cast<const char*>(a.data), static_cast<std::streamsize>(a.bytes));
        }
      }
    }
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace upf
