// PLY point-cloud writer for particles: one vertex per particle. Format: G. Turk's Polygon File
// Format (1994) as described by Paul Bourke, https://paulbourke.net/dataformats/ply/ ; the
// layout we write is in ply_points_writer.h.
#include "framework/output/ply_points_writer.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "framework/output/atomic_file.h"
#include "framework/output/type_palette.h"
#include "framework/particles/array_sizes.h"

namespace upf {

namespace {

static_assert(sizeof(ParticleType) == 1, "type is written as uint8");
static_assert(std::is_same_v<ParticleId, std::uint32_t>, "id is written as uint32");
static_assert(std::is_same_v<MaterialId, std::uint16_t>, "material is written as uint16");
static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559,
              "PLY float is an IEEE 754 single");

// Appends `value` to `out` in little-endian byte order, whatever the host's.
template <class T>
void put(char*& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::memcpy(out, &value, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(out, out + sizeof(T));
  out += sizeof(T);
}

void put_vec3(char*& out, const Vec3& v) {
  put(out, float(v.x));
  put(out, float(v.y));
  put(out, float(v.z));
}

// The extra properties after the fixed ones: a scalar or a vector field each.
struct Extra {
  const std::vector<Real>* scalar = nullptr;
  const std::vector<Vec3>* vector = nullptr;
};

// The header and the record layout of a file of `particles` with `fields`.
struct Layout {
  std::string header;
  std::size_t record = 0;  // bytes per vertex
  std::vector<Extra> extras;
};

Layout layout_for(const Particles& particles, const std::vector<std::string>& fields);

}  // namespace

std::string ply_property_name(std::string_view name) {
  std::string out(name);
  for (char& c : out)
    if (c <= ' ' || c >= 127) c = '_';  // char may be signed: bytes >= 128 are negative
  return out.empty() ? std::string("_") : out;
}

namespace {

Layout layout_for(const Particles& particles, const std::vector<std::string>& fields) {
  const std::size_t n = particles.size();
  std::string header =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment upf particles: one vertex per particle, coloured by type\n"
      "element vertex " +
      std::to_string(n) +
      "\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "property uint8 red\n"
      "property uint8 green\n"
      "property uint8 blue\n"
      "property uint32 id\n"
      "property uint8 type\n"
      "property uint16 material\n"
      "property float vx\n"
      "property float vy\n"
      "property float vz\n";
  std::size_t record = 3 * 4 + 3 + 4 + 1 + 2 + 3 * 4;

  // Same skipping rules as write_vtp, plus PLY's own: one property per name in the header.
  std::set<std::string> written = {"id", "type", "material", "velocity"};
  std::set<std::string> properties = {"x",  "y",    "z",        "red", "green", "blue",
                                      "id", "type", "material", "vx",  "vy",    "vz"};
  std::vector<Extra> extras;
  for (const std::string& name : fields) {
    if (written.count(name)) continue;
    const std::string base = ply_property_name(name);
    if (const auto* s = particles.find_scalar(name)) {
      if (properties.count(base)) continue;
      written.insert(name);
      properties.insert(base);
      header += "property float " + base + "\n";
      extras.push_back({s, nullptr});
      record += 4;
    } else if (const auto* v = particles.find_vector(name)) {
      const std::string names[3] = {base + "_x", base + "_y", base + "_z"};
      if (properties.count(names[0]) || properties.count(names[1]) || properties.count(names[2]))
        continue;
      written.insert(name);
      for (const std::string& p : names) {
        properties.insert(p);
        header += "property float " + p + "\n";
      }
      extras.push_back({nullptr, v});
      record += 3 * 4;
    }
  }
  header += "end_header\n";
  return {std::move(header), record, std::move(extras)};
}

}  // namespace

std::size_t ply_points_bytes(const Particles& particles, const std::vector<std::string>& fields) {
  const Layout layout = layout_for(particles, fields);
  return layout.header.size() + particles.size() * layout.record;
}

void write_ply_points(const std::filesystem::path& path, const Particles& particles,
                      const std::vector<std::string>& fields) {
  const std::size_t n = particles.size();
  check_array_sizes(particles, "write_ply_points");
  // A named layout, not a structured binding: clang 14 cannot capture bindings in the lambda.
  const Layout layout = layout_for(particles, fields);
  const std::string& header = layout.header;
  const std::size_t record = layout.record;
  const std::vector<Extra>& extras = layout.extras;

  write_file_atomically(path, [&](std::ostream& out) {
    out.write(header.data(), std::streamsize(header.size()));
    // Records are packed (19 bytes before the velocity), so they go through a byte buffer,
    // a block of vertices at a time.
    constexpr std::size_t kBlock = 4096;
    std::vector<char> buffer(std::min(n, kBlock) * record);
    for (std::size_t first = 0; first < n; first += kBlock) {
      const std::size_t last = std::min(n, first + kBlock);
      char* at = buffer.data();
      for (std::size_t i = first; i < last; ++i) {
        put_vec3(at, particles.position[i]);
        const Rgb8 c = type_colour(particles.type[i]);
        put(at, c.r);
        put(at, c.g);
        put(at, c.b);
        put(at, particles.id[i]);
        put(at, static_cast<std::uint8_t>(particles.type[i]));
        put(at, particles.material[i]);
        put_vec3(at, particles.velocity[i]);
        for (const Extra& e : extras) {
          if (e.scalar)
            put(at, float((*e.scalar)[i]));
          else
            put_vec3(at, (*e.vector)[i]);
        }
      }
      out.write(buffer.data(), at - buffer.data());
    }
  });
}

}  // namespace upf
