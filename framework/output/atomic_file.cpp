// Atomic file replacement: write `path`.tmp, flush, check, rename. See atomic_file.h; formats
// written through it are described in the VTK XML file format documentation:
// https://docs.vtk.org/en/latest/vtk_file_formats/vtkxml_file_format.html
#include "framework/output/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>

#include "framework/core/errors.h"

namespace upf {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

// errno is only meaningful when the failing call set it; 0 means we do not know why.
std::string errno_reason(int err, const char* fallback) {
  return err != 0 ? std::string(std::strerror(err)) : std::string(fallback);
}

// Removes the temporary file unless the rename has consumed it, whichever way we leave.
class TempFileGuard {
 public:
  explicit TempFileGuard(fs::path p) : path_(std::move(p)) {}
  TempFileGuard(const TempFileGuard&) = delete;
  TempFileGuard& operator=(const TempFileGuard&) = delete;
  ~TempFileGuard() {
    if (armed_) {
      std::error_code ignored;
      fs::remove(path_, ignored);
    }
  }
  void release() { armed_ = false; }

 private:
  fs::path path_;
  bool armed_ = true;
};

}  // namespace

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  fs::path tmp = path;
  tmp += ".tmp";
  const std::string prefix = "cannot write " + quoted(path) + ": ";

  errno = 0;
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) {
    // Nothing was created, so there is nothing to remove (and `tmp` may be someone else's).
    throw OutputError(prefix + "cannot open temporary file " + quoted(tmp) + ": " +
                      errno_reason(errno, "open failed"));
  }
  TempFileGuard guard(tmp);

  errno = 0;
  write(out);
  // Buffered data reaches the disk only on flush/close, which is where a full disk shows up.
  out.flush();
  if (!out) throw OutputError(prefix + errno_reason(errno, "write failed"));
  errno = 0;
  out.close();
  if (out.fail()) throw OutputError(prefix + errno_reason(errno, "close failed"));

  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    throw OutputError(prefix + "cannot rename " + quoted(tmp) + " onto it: " + ec.message());
  }
  guard.release();
}

void ensure_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  // create_directories reports an existing non-directory inconsistently across library versions,
  // so check the outcome rather than the error code alone.
  if (!fs::is_directory(dir)) {
    if (fs::exists(dir)) {
      throw OutputError("cannot use output directory " + quoted(dir) +
                        ": it exists and is not a directory");
    }
    throw OutputError("cannot create output directory " + quoted(dir) + ": " +
                      (ec ? ec.message() : std::string("unknown error")));
  }
  // access() also reports a read-only file system (EROFS), which permission bits do not show.
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    const int err = errno;
    throw OutputError("output directory " + quoted(dir) +
                      " is not writable: " + errno_reason(err, "access denied"));
  }
}

}  // namespace upf
