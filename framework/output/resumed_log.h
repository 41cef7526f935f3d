// Text logs a run appends to (metrics.csv, probes.csv, bodies.csv). A checkpoint keeps each
// log's length; a resumed run cuts the file back to it and appends from there, so the rows
// written after the checkpoint are written again, once.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace upf {

class StateWriter;
class StateReader;

class ResumableLog {
 public:
  // Starts the file anew with `header` (a whole line), or, when `resuming`, leaves the file
  // alone until restore_state opens it. Throws OutputError naming the file.
  ResumableLog(std::filesystem::path path, const std::string& header, bool resuming);
  // Numbers go out with 9 significant digits.
  std::ostream& out() { return out_; }
  // Throws OutputError naming the file when a write failed (disk full).
  void flush();
  // The length after a flush.
  void save_state(StateWriter& out);
  // Cuts the file back to the saved length (refusing a file shorter than that) and reopens it.
  void restore_state(StateReader& in);

 private:
  std::filesystem::path path_;
  std::ofstream out_;
};

}  // namespace upf
