#include "framework/checkpoint/checkpoint_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "framework/core/errors.h"
#include "framework/core/fnv1a.h"
#include "framework/core/real.h"
#include "framework/output/atomic_file.h"

namespace upf {

namespace {

constexpr char kMagic[8] = {'U', 'P', 'F', 'C', 'K', 'P', 'T', '\n'};

}  // namespace

std::string checkpoint_build_id() {
  return std::string("upf ") + UPF_VERSION + ", Real " + (sizeof(Real) == 8 ? "double" : "float");
}

void write_checkpoint(const std::filesystem::path& path, const std::vector<char>& payload) {
  StateWriter header;
  header.put(kCheckpointFormat);
  header.put_string(checkpoint_build_id());
  header.put(std::uint64_t(payload.size()));
  header.put(fnv1a(payload.data(), payload.size()));
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(kMagic, sizeof kMagic);
    out.write(header.bytes().data(), std::streamsize(header.bytes().size()));
    out.write(payload.data(), std::streamsize(payload.size()));
  });
}

namespace {

// Reads exactly `n` bytes at the file's position; false on a short read.
bool read_exactly(int fd, char* into, std::size_t n) {
  while (n > 0) {
    const ssize_t got = ::read(fd, into, n);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    into += got;
    n -= std::size_t(got);
  }
  return true;
}

// An open descriptor that closes itself.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

StateReader read_checkpoint(const std::filesystem::path& path) {
  const std::string name = path.string();
  // Non-blocking, so that a FIFO cannot hang the open; then only a regular file is read, and
  // never more than its size: a link to /dev/zero or a directory is an error, not a hang.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0)
    throw InputError(
        name, errno == ENOENT ? "cannot open the checkpoint (no checkpoint in this directory?)"
                              : "cannot open the checkpoint: " + std::string(std::strerror(errno)));
  struct stat info {};
  if (::fstat(file.fd, &info) != 0 || !S_ISREG(info.st_mode))
    throw InputError(name, S_ISDIR(info.st_mode)
                               ? "is a directory, not a checkpoint file"
                               : "is not a regular file (a device, a FIFO or a socket): not a "
                                 "checkpoint");
  const auto file_size = std::uint64_t(info.st_size);
  char magic[sizeof kMagic];
  if (file_size < sizeof kMagic || !read_exactly(file.fd, magic, sizeof magic) ||
      std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    throw InputError(name, "not a upf checkpoint (wrong magic bytes)");
  // The header: format, build id (a short string), payload size, checksum. Bounded before the
  // payload is read, so no count in the file can make the reader allocate beyond the file.
  constexpr std::size_t kLongestBuildId = 256;
  const std::uint64_t header_max =
      sizeof(std::uint32_t) + sizeof(std::uint64_t) + kLongestBuildId + 2 * sizeof(std::uint64_t);
  std::vector<char> head(std::size_t(std::min(header_max, file_size - sizeof kMagic)));
  if (!read_exactly(file.fd, head.data(), head.size()))
    throw InputError(name, "cannot read the checkpoint's header");
  StateReader header(std::move(head), name);
  const auto format = header.get<std::uint32_t>();
  if (format != kCheckpointFormat)
    throw InputError(name, "checkpoint format " + std::to_string(format) + ", this upf reads " +
                               std::to_string(kCheckpointFormat));
  const std::string build = header.get_string();
  if (build != checkpoint_build_id())
    throw InputError(name, "written by '" + build.substr(0, 80) + "', this is '" +
                               checkpoint_build_id() + "': resume with the build that wrote it");
  const auto size = header.get<std::uint64_t>();
  const auto checksum = header.get<std::uint64_t>();
  const std::uint64_t payload_at = sizeof kMagic + sizeof(std::uint32_t) + sizeof(std::uint64_t) +
                                   build.size() + 2 * sizeof(std::uint64_t);
  if (size != file_size - payload_at)
    throw InputError(name, "the payload is " + std::to_string(file_size - payload_at) +
                               " bytes, the header says " + std::to_string(size) +
                               " (truncated or damaged)");
  std::vector<char> payload(static_cast<std::size_t>(size));
  if (::lseek(file.fd, off_t(payload_at), SEEK_SET) != off_t(payload_at) ||
      !read_exactly(file.fd, payload.data(), payload.size()))
    throw InputError(name, "cannot read the checkpoint's payload (it changed while read?)");
  if (fnv1a(payload.data(), payload.size()) != checksum)
    throw InputError(name, "checksum mismatch: the checkpoint is damaged");
  return StateReader(std::move(payload), name);
}

}  // namespace upf
