// Writes the particles as a VTK XML PolyData file (.vtp) for ParaView and VisIt.
//
// One vertex per particle, binary data in an appended block with 64-bit size headers, raw (a
// frame costs little more than a memory copy to write) or zlib-compressed (VTK's own
// vtkZLibDataCompressor layout, which ParaView reads). Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html (PolyData, appended
// data, header_type).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "framework/output/vtk_appended_data.h"
#include "framework/particles/particles.h"

namespace upf {

// Writes `particles` to `path` atomically (see write_file_atomically). Point data always holds
// "id" (UInt32), "type" (UInt8), "material" (UInt16) and "velocity" (3 components), then each
// named field of `fields` in order, scalar or vector; names that match no field, or repeat one
// already written, are skipped (run_simulation reports unknown names before the first frame).
// Positions and real-valued fields are written as Float32, or Float64 when upf::Real is double;
// the vertex cells' connectivity and offsets as Int32 (Int64 past 2^31 - 1 particles).
// Throws OutputError if the file cannot be written; the directory must exist.
void write_vtp(const std::filesystem::path& path, const Particles& particles,
               const std::vector<std::string>& fields,
               vtk_xml::Compression compression = vtk_xml::Compression::none);

// Writes the parallel PolyData file (.pvtp) that makes `pieces` (.vtp files written by write_vtp
// with the same `fields`, paths relative to the .pvtp's directory) one data set for ParaView and
// VTK's vtkXMLPPolyDataReader. `like`: particles with the fields of the pieces (any count: the
// array declarations are all it gives). Atomic; throws OutputError if it cannot be written.
void write_pvtp(const std::filesystem::path& path, const Particles& like,
                const std::vector<std::string>& fields, const std::vector<std::string>& pieces);

// The bytes write_vtp writes for `particles` uncompressed, apart from the XML header (a few
// hundred bytes): for the size estimate of a run's frames.
std::size_t vtp_data_bytes(const Particles& particles, const std::vector<std::string>& fields);

// Escapes `s` for use inside a double-quoted XML attribute (field names, file names).
std::string xml_escape(std::string_view s);

}  // namespace upf
