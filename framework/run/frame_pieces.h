// A split run's frames as one piece per rank (/output/pieces "per_rank", docs/mpi.md): every rank
// writes its own particles of a frame as frames/frame_NNNNN_pRRRR.vtp, in id order, and rank 0
// writes frames/frame_NNNNN.pvtp, VTK's parallel PolyData file that joins them, which
// particles.pvd lists. No rank gathers the frame, so a frame is never bounded by what one rank
// holds. The frozen piece (written once) goes the same way: frames/frozen.pvtp. Format: VTK XML
// file format documentation (Parallel files, PPolyData).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "framework/scene/scene.h"
#include "framework/world/particle_domain.h"
#include "framework/world/world.h"

namespace upf {

// The .pvtp files of a frame (relative to the run directory); empty: not written as pieces.
struct FramePieceNames {
  std::string particles;
  std::string frozen;
};

class FramePieces {
 public:
  // `fields`: the exported fields, as the frames write them. `resuming`: the frozen piece the run
  // being resumed wrote stays.
  FramePieces(const std::filesystem::path& out_dir, const SceneDescription& scene,
              std::vector<std::string> fields, const World& world, bool resuming);

  // The files write() makes for frame `frame` on every rank together (the pieces, the .pvtp,
  // and the frozen ones the first time), for rank 0's manifest to record first.
  std::vector<std::string> files_of_frame(int frame) const;
  // Every rank calls it with its own particles (no ghosts) for frame number `frame`.
  FramePieceNames write(const Particles& owned, int frame);

 private:
  // This rank's piece of `name` (frames/NAME_pRRRR.vtp) with the particles of `types`, and on
  // rank 0 frames/NAME.pvtp; returns the .pvtp's name.
  std::string write_pieces(const Particles& owned, TypeMask types, const std::string& name);

  std::filesystem::path out_dir_;
  std::vector<std::string> fields_;
  bool compress_;
  TypeMask frame_types_;  // the types of the frame pieces (the frozen ones apart, see below)
  bool frozen_piece_;     // the frozen particles go once into frames/frozen.pvtp
  bool frozen_written_;
  const ParticleDomain& domain_;
};

}  // namespace upf
