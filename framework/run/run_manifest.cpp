#include "framework/run/run_manifest.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <system_error>

#include "framework/core/errors.h"
#include "framework/output/atomic_file.h"

namespace upf {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader = "upf run manifest 1";
// A manifest lists a few files per frame: far below this. A larger one is not ours.
constexpr std::uintmax_t kLargestManifest = std::uintmax_t(256) << 20;

// A relative path of plain components: no "", ".", "..", no leading '/', no '\\' or control
// characters. Only such entries are ever removed, so a hostile manifest cannot reach outside.
bool plain_relative(const std::string& path) {
  if (path.empty() || path.front() == '/') return false;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    const std::string part = path.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") return false;
    for (const char c : part)
      if (c == '\\' || static_cast<unsigned char>(c) < 0x20) return false;
    start = end + 1;
  }
  return true;
}

fs::file_status link_status(const fs::path& p) {
  std::error_code ec;
  return fs::symlink_status(p, ec);
}

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

// The first few entries of `dir`, for a message.
std::string some_entries(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    names.push_back(e.path().filename().string());
    if (names.size() > 4) break;
  }
  std::sort(names.begin(), names.end());
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < 4; ++i) list += (i ? ", " : "") + names[i];
  if (names.size() > 4) list += ", ...";
  return list;
}

}  // namespace

ManifestEntries parse_manifest(const std::string& text) {
  ManifestEntries entries;
  std::size_t start = 0;
  bool first = true;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) break;  // a torn last line: never completed, so not written
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    if (first) {
      entries.valid_header = line == kHeader;
      if (!entries.valid_header) return entries;
      first = false;
      continue;
    }
    if (line.size() < 3 || line[1] != ' ') continue;
    const std::string path = line.substr(2);
    if (!plain_relative(path)) continue;
    if (line[0] == 'f') entries.files.push_back(path);
    if (line[0] == 'd') entries.dirs.push_back(path);
  }
  return entries;
}

namespace {

// The previous manifest in `dir`, if there is one that is a regular file of sane size.
std::optional<ManifestEntries> read_manifest(const fs::path& dir) {
  const fs::path path = dir / RunManifest::kFileName;
  if (!fs::is_regular_file(link_status(path))) return std::nullopt;
  std::error_code ec;
  if (fs::file_size(path, ec) > kLargestManifest || ec) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ManifestEntries entries = parse_manifest(text);
  if (!entries.valid_header) return std::nullopt;
  return entries;
}

void check_is_folder(const fs::path& dir) {
  std::error_code ec;
  const auto status = fs::status(dir, ec);  // the folder given may itself be a link: it was told
  if (fs::exists(status) && !fs::is_directory(status))
    throw InputError(dir.string(), "the output folder is a file, not a folder");
}

}  // namespace

RunManifest RunManifest::for_new_run(const fs::path& dir, bool overwrite) {
  check_is_folder(dir);
  RunManifest manifest(dir, overwrite);
  std::error_code ec;
  if (fs::is_directory(dir, ec)) {
    if (auto previous = read_manifest(dir)) {
      manifest.had_previous_ = true;
      manifest.previous_.insert(previous->files.begin(), previous->files.end());
      manifest.previous_dirs_ = previous->dirs;
    } else if (!overwrite && !fs::is_empty(dir, ec)) {
      throw InputError(dir.string(),
                       "the output folder holds files that no upf run recorded (" +
                           some_entries(dir) + "; no " + kFileName +
                           "): choose a new or empty folder, or overwrite (upf run --overwrite, "
                           "Python overwrite=True), which replaces the files at the names the "
                           "run writes and deletes nothing else");
    }
  }
  ensure_directory(dir);
  return manifest;
}

RunManifest RunManifest::for_continued_run(const fs::path& dir) {
  check_is_folder(dir);
  ensure_directory(dir);
  if (auto previous = read_manifest(dir)) {
    RunManifest manifest(dir, false);
    manifest.listed_.insert(previous->files.begin(), previous->files.end());
    manifest.listed_.insert(previous->dirs.begin(), previous->dirs.end());
    manifest.started_ = true;
    return manifest;
  }
  // A run recorded before manifests existed: its files are the run's own, so they are adopted.
  RunManifest manifest(dir, true);
  manifest.start();
  return manifest;
}

void RunManifest::start() {
  write_file_atomically(dir_ / kFileName, [](std::ostream& out) { out << kHeader << '\n'; });
  started_ = true;
}

std::size_t RunManifest::clear_previous() {
  std::size_t removed = 0;
  auto behind_link = [&](const std::string& relative) {
    fs::path at = dir_;
    const fs::path rel(relative);
    for (auto it = rel.begin(); it != rel.end() && std::next(it) != rel.end(); ++it) {
      at /= *it;
      if (!fs::is_directory(link_status(at))) return true;  // a link, a file, or missing
    }
    return false;
  };
  std::error_code ec;
  for (const std::string& file : previous_) {
    if (behind_link(file)) continue;
    const fs::path path = dir_ / file;
    fs::path tmp = path;
    tmp += ".tmp";  // a write the previous run never finished
    if (fs::is_regular_file(link_status(tmp))) fs::remove(tmp, ec);
    if (fs::is_regular_file(link_status(path)) && fs::remove(path, ec)) ++removed;
  }
  // Deepest first; fs::remove leaves a folder that still holds something (a user's file).
  std::vector<std::string> dirs = previous_dirs_;
  std::sort(dirs.begin(), dirs.end(), [](const std::string& a, const std::string& b) {
    return std::count(a.begin(), a.end(), '/') > std::count(b.begin(), b.end(), '/');
  });
  for (const std::string& d : dirs)
    if (!behind_link(d) && fs::is_directory(link_status(dir_ / d))) fs::remove(dir_ / d, ec);
  start();
  return removed;
}

namespace {
// Throws unless `at` is a real folder or missing (then the run makes it).
void expect_folder_or_nothing(const fs::path& at) {
  const auto status = link_status(at);
  if (fs::is_symlink(status))
    throw InputError(at.string(),
                     "is a symbolic link: upf never writes through links in its "
                     "output folder (it could reach another folder)");
  if (fs::exists(status) && !fs::is_directory(status))
    throw InputError(at.string(), "is a file where the run needs a folder");
}
}  // namespace

void RunManifest::check_no_link_on_the_way(const std::string& relative) const {
  fs::path at = dir_;
  const fs::path rel(relative);
  for (auto it = rel.begin(); it != rel.end() && std::next(it) != rel.end(); ++it)
    expect_folder_or_nothing(at /= *it);
}

void RunManifest::claim(const std::string& relative) {
  if (listed_.count(relative)) return;
  if (!plain_relative(relative))
    throw std::logic_error("RunManifest::claim: not a plain relative path: " + relative);
  check_no_link_on_the_way(relative);
  const fs::path path = dir_ / relative;
  const auto status = link_status(path);
  if (fs::is_symlink(status))
    throw InputError(path.string(), "is a symbolic link: upf never writes through links");
  if (fs::exists(status)) {
    const bool ours = previous_.count(relative) > 0 || overwrite_;
    if (!fs::is_regular_file(status) || !ours)
      throw InputError(path.string(), "is in the way and no upf run recorded writing it (" +
                                          std::string(kFileName) +
                                          "): move it, or choose another output folder");
  }
  append('f', relative);
}

void RunManifest::claim(const std::vector<std::string>& relatives) {
  for (const auto& r : relatives) claim(r);
}

void RunManifest::claim_directory(const std::string& relative) {
  if (!plain_relative(relative))
    throw std::logic_error("RunManifest::claim_directory: not a plain relative path: " + relative);
  check_no_link_on_the_way(relative);
  const fs::path path = dir_ / relative;
  expect_folder_or_nothing(path);
  if (!listed_.count(relative)) append('d', relative);
  ensure_directory(path);
}

void RunManifest::append(char kind, const std::string& relative) {
  if (!started_) start();
  const fs::path path = dir_ / kFileName;
  const std::string line = std::string(1, kind) + ' ' + relative + '\n';
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NOFOLLOW);
  const ssize_t written = fd >= 0 ? ::write(fd, line.data(), line.size()) : -1;
  const int err = errno;
  if (fd >= 0) ::close(fd);
  if (written != ssize_t(line.size()))
    throw OutputError("cannot write " + quoted(path) + ": " +
                      (err ? std::strerror(err) : "short write"));
  listed_.insert(relative);
}

}  // namespace upf
