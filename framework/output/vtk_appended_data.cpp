// VTK XML PolyData with raw appended binary data, shared by the .vtp writers. Format: VTK XML
// file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
#include "framework/output/vtk_appended_data.h"

#include <bit>
#include <ostream>
#include <string>

#include "framework/output/atomic_file.h"
#include "framework/output/vtp_writer.h"  // xml_escape

namespace upf::vtk_xml {

namespace {

static_assert(std::endian::native == std::endian::little ||
              std::endian::native == std::endian::big);

// Raw data is written in host order, so the file declares the host's order.
constexpr const char* kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

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

}  // namespace

void write_polydata(const std::filesystem::path& path, const PieceCounts& counts,
                    const std::vector<Section>& sections) {
  // Numbers are formatted with std::to_string, which ignores any global stream locale.
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"";
  xml += kByteOrder;
  xml += "\" header_type=\"UInt64\">\n";
  xml += "  <PolyData>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(counts.points) + "\" NumberOfVerts=\"" +
         std::to_string(counts.verts) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(counts.polys) + "\">\n";
  std::uint64_t offset = 0;
  for (const Section& s : sections) {
    xml += "      <" + std::string(s.tag) + ">\n";
    describe(xml, s.arrays, offset, "        ");
    xml += "      </" + std::string(s.tag) + ">\n";
  }
  xml += "    </Piece>\n";
  xml += "  </PolyData>\n";
  xml += "  <AppendedData encoding=\"raw\">\n   _";

  write_file_atomically(path, [&](std::ostream& out) {
    out.write(xml.data(), static_cast<std::streamsize>(xml.size()));
    for (const Section& s : sections) {
      for (const Array& a : s.arrays) {
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

}  // namespace upf::vtk_xml
