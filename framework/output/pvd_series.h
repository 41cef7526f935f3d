// A ParaView data-set collection (.pvd) that lists the frames of a run with their times, so
// ParaView plays the frames at their simulated times. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html (and ParaView's
// "Collection" reader, vtkPVDReader).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace upf {

class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvd_path);

  // Records a frame written at simulated `time`, at `relative_file` (relative to the .pvd's
  // directory, '/'-separated), and rewrites the .pvd so the series on disk is always complete.
  // Throws OutputError if the .pvd cannot be written; the frame is then not recorded.
  void add(double time, const std::string& relative_file);

  // Writes the whole collection atomically (see write_file_atomically).
  void write() const;

  const std::filesystem::path& path() const { return path_; }

 private:
  struct Entry {
    double time;
    std::string file;
  };
  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace upf
