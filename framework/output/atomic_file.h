// Atomic file replacement for every output writer (frames, series indexes, metrics).
//
// A reader (ParaView following a .pvd while the run goes on, or a user after a crash or a full
// disk) must never see a half-written file: we write `path`.tmp in the same directory and rename
// it onto `path`, which POSIX makes atomic within one file system. The formats written this way
// are described in the VTK XML file format documentation:
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace upf {

// Writes `path` through `write`, which receives a binary stream on `path`.tmp. On success the
// temporary file replaces `path` atomically. On any failure (cannot open, write error such as a
// full disk, rename error) throws OutputError naming `path` and the reason, removes the temporary
// file and leaves any existing file at `path` untouched. Exceptions thrown by `write` itself
// propagate unchanged, after the same clean-up.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

// Creates `dir` and its parents if needed. Throws OutputError naming `dir` if it cannot be
// created, is not a directory, or is not writable.
void ensure_directory(const std::filesystem::path& dir);

}  // namespace upf
