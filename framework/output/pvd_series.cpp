// ParaView .pvd collection writer. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
#include "framework/output/pvd_series.h"

#include "framework/core/state_stream.h"

#include <charconv>
#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "framework/output/atomic_file.h"
#include "framework/output/vtp_writer.h"  // xml_escape

namespace upf {

namespace {

// Shortest text that reads back as the same double, independent of any locale.
std::string format_time(double t) {
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof(buf), t);
  return result.ec == std::errc() ? std::string(buf, result.ptr) : std::string("0");
}

}  // namespace

PvdSeries::PvdSeries(std::filesystem::path pvd_path) : path_(std::move(pvd_path)) {}

void PvdSeries::add(double time, const std::string& relative_file) {
  add(time, std::vector<std::string>{relative_file});
}

void PvdSeries::add(double time, const std::vector<std::string>& relative_files) {
  if (relative_files.empty()) {
    throw std::invalid_argument("PvdSeries::add: a time step needs at least one file");
  }
  const std::size_t before = entries_.size();
  for (std::size_t part = 0; part < relative_files.size(); ++part) {
    entries_.push_back({time, part, relative_files[part]});
  }
  try {
    write();
  } catch (...) {
    // Keep memory and disk in agreement: the caller sees the failure and the step is not kept.
    entries_.resize(before);
    throw;
  }
}

void PvdSeries::write() const {
  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  xml += "  <Collection>\n";
  for (const Entry& e : entries_) {
    xml += "    <DataSet timestep=\"" + format_time(e.time) + "\" group=\"\" part=\"" +
           std::to_string(e.part) + "\" file=\"" + xml_escape(e.file) + "\"/>\n";
  }
  xml += "  </Collection>\n";
  xml += "</VTKFile>\n";
  write_file_atomically(path_, [&](std::ostream& out) {
    out.write(xml.data(), static_cast<std::streamsize>(xml.size()));
  });
}

void PvdSeries::save_state(StateWriter& out) const {
  out.put(std::uint64_t(entries_.size()));
  for (const Entry& e : entries_) {
    out.put(e.time);
    out.put(std::uint64_t(e.part));
    out.put_string(e.file);
  }
}

void PvdSeries::restore_state(StateReader& in) {
  const auto n = in.get<std::uint64_t>();
  if (n > in.remaining()) in.fail("more frames than the file can hold");
  entries_.resize(std::size_t(n));
  for (Entry& e : entries_) {
    e.time = in.get<double>();
    e.part = std::size_t(in.get<std::uint64_t>());
    e.file = in.get_string();
  }
  write();
}

}  // namespace upf
