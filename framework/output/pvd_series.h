// A ParaView data-set collection (.pvd) that lists the frames of a run with their times, so
// ParaView plays the frames at their simulated times. Format: VTK XML file format documentation,
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html (and ParaView's
// "Collection" reader, vtkPVDReader).
//
// A time step may hold several files, one per part (the particles, the rigid bodies' meshes):
// each is a DataSet with the same timestep and its own part number, and ParaView groups the
// DataSets by part, showing each part as one block that plays through the time steps.
#pragma once

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace upf {

class StateWriter;
class StateReader;

class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvd_path);

  // Records a frame written at simulated `time`, at `relative_file` (relative to the .pvd's
  // directory, '/'-separated), and rewrites the .pvd so the series on disk is always complete.
  // Throws OutputError if the .pvd cannot be written; the frame is then not recorded. The file
  // is part 0 (see the list form below).
  void add(double time, const std::string& relative_file);

  // Records a time step made of `relative_files`, as parts 0, 1, ... in order; callers keep the
  // same kind of data at the same position at every step (say particles, then meshes), since
  // ParaView matches a part across time by its number. Throws std::invalid_argument if
  // `relative_files` is empty; otherwise as the single-file add, all files or none recorded.
  void add(double time, const std::vector<std::string>& relative_files);

  // Lets add(t, {frame, mesh}) compile: without it the braced list is ambiguous between the
  // vector and the single std::string (whose iterator-pair constructor takes two literals).
  void add(double time, std::initializer_list<std::string> relative_files) {
    add(time, std::vector<std::string>(relative_files));
  }

  // Writes the whole collection atomically (see write_file_atomically).
  void write() const;

  const std::filesystem::path& path() const { return path_; }

  // Checkpoints: the entries; restore_state rewrites the .pvd with them.
  void save_state(StateWriter& out) const;
  void restore_state(StateReader& in);

 private:
  struct Entry {
    double time;
    std::size_t part;
    std::string file;
  };
  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace upf
