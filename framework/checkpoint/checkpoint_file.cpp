#include "framework/checkpoint/checkpoint_file.h"

#include <cstring>
#include <fstream>
#include <iterator>

#include "framework/core/errors.h"
#include "framework/core/real.h"
#include "framework/output/atomic_file.h"

namespace upf {

namespace {

constexpr char kMagic[8] = {'U', 'P', 'F', 'C', 'K', 'P', 'T', '\n'};

std::uint64_t fnv1a(const std::vector<char>& bytes, std::size_t from) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = from; i < bytes.size(); ++i) {
    h ^= std::uint8_t(bytes[i]);
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

std::string checkpoint_build_id() {
  return std::string("upf ") + UPF_VERSION + ", Real " + (sizeof(Real) == 8 ? "double" : "float");
}

void write_checkpoint(const std::filesystem::path& path, const std::vector<char>& payload) {
  StateWriter header;
  header.put(kCheckpointFormat);
  header.put_string(checkpoint_build_id());
  header.put(std::uint64_t(payload.size()));
  header.put(fnv1a(payload, 0));
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(kMagic, sizeof kMagic);
    out.write(header.bytes().data(), std::streamsize(header.bytes().size()));
    out.write(payload.data(), std::streamsize(payload.size()));
  });
}

StateReader read_checkpoint(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name, "cannot open the checkpoint (no checkpoint in this directory?)");
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(name, "not a upf checkpoint (wrong magic bytes)");
  StateReader header(std::vector<char>(bytes.begin() + sizeof kMagic, bytes.end()), name);
  const auto format = header.get<std::uint32_t>();
  if (format != kCheckpointFormat)
    throw InputError(name, "checkpoint format " + std::to_string(format) + ", this upf reads " +
                               std::to_string(kCheckpointFormat));
  const std::string build = header.get_string();
  if (build != checkpoint_build_id())
    throw InputError(name, "written by '" + build + "', this is '" + checkpoint_build_id() +
                               "': resume with the build that wrote it");
  const auto size = header.get<std::uint64_t>();
  const auto checksum = header.get<std::uint64_t>();
  if (size != header.remaining())
    throw InputError(name, "the payload is " + std::to_string(header.remaining()) +
                               " bytes, the header says " + std::to_string(size) +
                               " (truncated or damaged)");
  std::vector<char> payload(bytes.end() - std::ptrdiff_t(size), bytes.end());
  if (fnv1a(payload, 0) != checksum)
    throw InputError(name, "checksum mismatch: the checkpoint is damaged");
  return StateReader(std::move(payload), name);
}

}  // namespace upf
