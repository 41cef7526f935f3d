// VTK XML PolyData writer for particles: one vertex per particle. Format: VTK XML file format
// documentation, https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html; the
// appended-data layout is in vtk_appended_data.h.
#include "framework/output/vtp_writer.h"

#include <cstdint>
#include <limits>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "framework/output/atomic_file.h"
#include "framework/output/vtk_appended_data.h"
#include "framework/particles/array_sizes.h"

namespace upf {

namespace {

// The raw arrays are written straight from memory, so the declared types must match the layout.
static_assert(sizeof(Vec3) == 3 * sizeof(Real), "Vec3 must be three packed Reals");
static_assert(std::is_standard_layout_v<Vec3>);
static_assert(sizeof(ParticleType) == 1, "type is written as UInt8");
static_assert(std::is_same_v<ParticleId, std::uint32_t>, "id is written as UInt32");
static_assert(std::is_same_v<MaterialId, std::uint16_t>, "material is written as UInt16");
constexpr const char* kRealType = std::is_same_v<Real, double> ? "Float64" : "Float32";

using vtk_xml::make_array;

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

namespace {

// The point-data arrays of a frame, in file order.
std::vector<vtk_xml::Array> point_arrays(const Particles& particles,
                                         const std::vector<std::string>& fields) {
  std::vector<vtk_xml::Array> point_data = {
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
      point_data.push_back(make_array(name, kRealType, 1, *s));
    } else if (const auto* v = particles.find_vector(name)) {
      point_data.push_back(make_array(name, kRealType, 3, *v));
    }
  }
  return point_data;
}

// Vertex i is point i: connectivity is 0..n-1 and the (end) offsets are 1..n, so one sequence
// 0..n serves both arrays. Int32 while it fits: half the bytes of Int64.
template <class Index>
void write_with_index(const std::filesystem::path& path, const Particles& particles,
                      std::vector<vtk_xml::Array> point_data, const char* index_type,
                      vtk_xml::Compression compression) {
  const std::size_t n = particles.size();
  std::vector<Index> sequence(n + 1);
  std::iota(sequence.begin(), sequence.end(), Index{0});
  const std::size_t index_bytes = n * sizeof(Index);
  vtk_xml::write_polydata(path, {.points = n, .verts = n, .polys = 0},
                          {{"PointData", std::move(point_data)},
                           {"Points", {make_array("Points", kRealType, 3, particles.position)}},
                           {"Verts",
                            {{"connectivity", index_type, 1, sequence.data(), index_bytes},
                             {"offsets", index_type, 1, sequence.data() + 1, index_bytes}}}},
                          compression);
}

bool fits_int32(std::size_t n) {
  return n < std::size_t(std::numeric_limits<std::int32_t>::max());
}

}  // namespace

void write_vtp(const std::filesystem::path& path, const Particles& particles,
               const std::vector<std::string>& fields, vtk_xml::Compression compression) {
  check_array_sizes(particles, "write_vtp");
  auto point_data = point_arrays(particles, fields);
  if (fits_int32(particles.size()))
    write_with_index<std::int32_t>(path, particles, std::move(point_data), "Int32", compression);
  else
    write_with_index<std::int64_t>(path, particles, std::move(point_data), "Int64", compression);
}

void write_pvtp(const std::filesystem::path& path, const Particles& like,
                const std::vector<std::string>& fields, const std::vector<std::string>& pieces) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
        << "  <PPolyData GhostLevel=\"0\">\n    <PPointData>\n";
    for (const vtk_xml::Array& a : point_arrays(like, fields))
      out << "      <PDataArray type=\"" << a.type << "\" Name=\"" << xml_escape(a.name)
          << "\" NumberOfComponents=\"" << a.components << "\"/>\n";
    out << "    </PPointData>\n    <PPoints>\n      <PDataArray type=\"" << kRealType
        << "\" Name=\"Points\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
    for (const std::string& piece : pieces)
      out << "    <Piece Source=\"" << xml_escape(piece) << "\"/>\n";
    out << "  </PPolyData>\n</VTKFile>\n";
  });
}

std::size_t vtp_data_bytes(const Particles& particles, const std::vector<std::string>& fields) {
  const std::size_t n = particles.size();
  std::size_t bytes = 0;
  std::size_t arrays = 3;  // Points, connectivity, offsets
  for (const vtk_xml::Array& a : point_arrays(particles, fields)) {
    bytes += a.bytes;
    ++arrays;
  }
  bytes += n * sizeof(Vec3) + 2 * n * (fits_int32(n) ? 4 : 8);
  return bytes + arrays * sizeof(vtk_xml::Header);
}

}  // namespace upf
