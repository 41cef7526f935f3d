// VTK XML PolyData with appended binary data, raw or zlib-compressed, shared by the .vtp
// writers. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html ; zlib: RFC 1950.
#include "framework/output/vtk_appended_data.h"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <ostream>
#include <string>

#include "framework/core/errors.h"
#include "framework/output/atomic_file.h"
#include "framework/output/vtp_writer.h"  // xml_escape

namespace upf::vtk_xml {

namespace {

static_assert(std::endian::native == std::endian::little ||
              std::endian::native == std::endian::big);

// Raw data is written in host order, so the file declares the host's order.
constexpr const char* kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

// zlib's fastest level: frames are written while the run waits, and the data that shrinks
// (ids, types, materials, connectivity) shrinks nearly as much as at the default level.
constexpr int kZlibLevel = 1;

void put_header(std::string& out, Header value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// One array compressed as it is stored in the appended block: its header and its blocks.
std::string compress(const Array& a, const std::filesystem::path& path) {
  std::string out;
  const char* bytes = static_cast<const char*>(a.data);
  const std::size_t blocks = (a.bytes + kBlockBytes - 1) / kBlockBytes;
  const std::size_t last = a.bytes - (blocks == 0 ? 0 : (blocks - 1) * kBlockBytes);
  put_header(out, blocks);
  put_header(out, kBlockBytes);
  put_header(out, blocks == 0 ? 0 : last);
  const std::size_t sizes_at = out.size();
  out.resize(out.size() + blocks * sizeof(Header));  // the compressed sizes, filled in below
  std::string block(compressBound(kBlockBytes), '\0');
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t length = std::min(kBlockBytes, a.bytes - b * kBlockBytes);
    uLongf packed = static_cast<uLongf>(block.size());
    const int rc = compress2(reinterpret_cast<Bytef*>(block.data()), &packed,
                             reinterpret_cast<const Bytef*>(bytes + b * kBlockBytes),
                             static_cast<uLong>(length), kZlibLevel);
    if (rc != Z_OK)
      throw OutputError(path.string() + ": zlib could not compress array '" + a.name +
                        "' (zlib error " + std::to_string(rc) + ")");
    const Header size = packed;
    std::copy_n(reinterpret_cast<const char*>(&size), sizeof size,
                out.begin() + std::ptrdiff_t(sizes_at + b * sizeof(Header)));
    out.append(block.data(), packed);
  }
  return out;
}

// The arrays as the appended block stores them. Uncompressed, they are written straight from
// memory (a frame of 10^8 particles is not copied); compressed, they are compressed first, since
// the offsets in the XML are the compressed sizes.
class StoredArrays {
 public:
  StoredArrays(const std::vector<Section>& sections, Compression compression,
               const std::filesystem::path& path) {
    for (const Section& s : sections)
      for (const Array& a : s.arrays) {
        arrays_.push_back(&a);
        if (compression == Compression::zlib) compressed_.push_back(compress(a, path));
      }
  }
  std::size_t size(std::size_t k) const {
    return compressed_.empty() ? sizeof(Header) + arrays_[k]->bytes : compressed_[k].size();
  }
  void write(std::ostream& out, std::size_t k) const {
    if (!compressed_.empty()) {
      out.write(compressed_[k].data(), static_cast<std::streamsize>(compressed_[k].size()));
      return;
    }
    const Header bytes = arrays_[k]->bytes;
    out.write(reinterpret_cast<const char*>(&bytes), sizeof(bytes));
    // An empty vector's data() may be null, which write() must not see.
    if (bytes > 0)
      out.write(static_cast<const char*>(arrays_[k]->data), static_cast<std::streamsize>(bytes));
  }
  std::size_t count() const { return arrays_.size(); }

 private:
  std::vector<const Array*> arrays_;
  std::vector<std::string> compressed_;
};

// Appends the DataArray elements of `arrays` to `xml`, advancing the appended-data offset by
// each array's stored size.
void describe(std::string& xml, const std::vector<Array>& arrays, const StoredArrays& stored,
              std::size_t& index, std::uint64_t& offset, const char* indent) {
  for (const Array& a : arrays) {
    xml += indent;
    xml += "<DataArray type=\"";
    xml += a.type;
    xml += "\" Name=\"" + xml_escape(a.name) + "\" NumberOfComponents=\"" +
           std::to_string(a.components) + "\" format=\"appended\" offset=\"" +
           std::to_string(offset) + "\"/>\n";
    offset += stored.size(index++);
  }
}

}  // namespace

void write_polydata(const std::filesystem::path& path, const PieceCounts& counts,
                    const std::vector<Section>& sections, Compression compression) {
  const StoredArrays stored(sections, compression, path);

  // Numbers are formatted with std::to_string, which ignores any global stream locale.
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"";
  xml += kByteOrder;
  xml += "\" header_type=\"UInt64\"";
  if (compression == Compression::zlib) xml += " compressor=\"vtkZLibDataCompressor\"";
  xml += ">\n";
  xml += "  <PolyData>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(counts.points) + "\" NumberOfVerts=\"" +
         std::to_string(counts.verts) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(counts.polys) + "\">\n";
  std::uint64_t offset = 0;
  std::size_t index = 0;
  for (const Section& s : sections) {
    xml += "      <" + std::string(s.tag) + ">\n";
    describe(xml, s.arrays, stored, index, offset, "        ");
    xml += "      </" + std::string(s.tag) + ">\n";
  }
  xml += "    </Piece>\n";
  xml += "  </PolyData>\n";
  xml += "  <AppendedData encoding=\"raw\">\n   _";

  write_file_atomically(path, [&](std::ostream& out) {
    out.write(xml.data(), static_cast<std::streamsize>(xml.size()));
    for (std::size_t k = 0; k < stored.count(); ++k) stored.write(out, k);
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace upf::vtk_xml
