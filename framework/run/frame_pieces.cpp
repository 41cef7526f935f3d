#include "framework/run/frame_pieces.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "framework/output/atomic_file.h"
#include "framework/output/vtp_writer.h"
#include "framework/particles/particles_of_types.h"

namespace upf {

namespace {

constexpr const char* kFrozenName = "frozen";

std::string piece_file(const std::string& name, int rank) {
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, "_p%04d.vtp", rank);
  return name + suffix;
}

// The particles of `types` in id order: a piece's bytes do not depend on the rank's memory order.
Particles in_id_order(const Particles& owned, TypeMask types) {
  Particles piece = particles_of_types(owned, types);
  std::vector<std::uint32_t> order(piece.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return piece.id[a] < piece.id[b]; });
  piece.permute(order);
  return piece;
}

}  // namespace

FramePieces::FramePieces(const std::filesystem::path& out_dir, const SceneDescription& scene,
                         std::vector<std::string> fields, const World& world, bool resuming)
    : out_dir_(out_dir),
      fields_(std::move(fields)),
      compress_(scene.output.compress),
      frozen_piece_(scene.output.frozen_once &&
                    in_mask(scene.output.vtp_types, ParticleType::Frozen) &&
                    world.count(ParticleType::Frozen) > 0),
      frozen_written_(resuming && std::filesystem::exists(out_dir / "frames" / "frozen.pvtp")),
      domain_(*world.domain()) {
  ensure_directory(out_dir / "frames");  // on every rank: rank 0's may not be there yet
  frame_types_ = frozen_piece_ ? TypeMask(scene.output.vtp_types & ~mask_of(ParticleType::Frozen))
                               : scene.output.vtp_types;
}

namespace {
std::string frame_name(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d", frame);
  return name;
}
}  // namespace

std::vector<std::string> FramePieces::files_of_frame(int frame) const {
  std::vector<std::string> files;
  auto add = [&](const std::string& name) {
    for (int r = 0; r < domain_.ranks(); ++r) files.push_back("frames/" + piece_file(name, r));
    files.push_back("frames/" + name + ".pvtp");
  };
  add(frame_name(frame));
  if (frozen_piece_ && !frozen_written_) add(kFrozenName);
  return files;
}

FramePieceNames FramePieces::write(const Particles& owned, int frame) {
  const std::string name = frame_name(frame);
  FramePieceNames names;
  names.particles = write_pieces(owned, frame_types_, name);
  if (frozen_piece_) {
    // Frozen particles never move: their positions at the first frame are those at every frame.
    if (!frozen_written_) write_pieces(owned, mask_of(ParticleType::Frozen), kFrozenName);
    frozen_written_ = true;
    names.frozen = std::string("frames/") + kFrozenName + ".pvtp";
  }
  return names;
}

std::string FramePieces::write_pieces(const Particles& owned, TypeMask types,
                                      const std::string& name) {
  const Particles piece = in_id_order(owned, types);
  const auto compression = compress_ ? vtk_xml::Compression::zlib : vtk_xml::Compression::none;
  write_vtp(out_dir_ / "frames" / piece_file(name, domain_.rank()), piece, fields_, compression);
  const std::string pvtp = "frames/" + name + ".pvtp";
  // Every piece is on disk before the file that names them: a collective, as a barrier.
  (void)domain_.max(0.0);
  if (domain_.rank() == 0) {
    std::vector<std::string> sources;
    for (int r = 0; r < domain_.ranks(); ++r) sources.push_back(piece_file(name, r));
    write_pvtp(out_dir_ / pvtp, piece, fields_, sources);
  }
  return pvtp;
}

}  // namespace upf
