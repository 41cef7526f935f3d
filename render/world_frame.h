// A world stepped live, in the form read_vtp gives for a saved frame, so one renderer
// (frame_picture.h) draws a live scene (upf view) and a saved run alike.
#pragma once

#include <vector>

#include "framework/output/mesh_vtp_writer.h"
#include "framework/particles/particles.h"
#include "framework/world/world.h"
#include "render/frame_picture.h"
#include "render/vtp_reader.h"

namespace upf::render {

// Points, "type", "material", "velocity" (3 components) and every exported field (a vector
// field with 3 components), as write_vtp writes them.
PolyData particles_poly_data(const Particles& particles);

// The pieces' triangles with the cell array "body" (the piece's index), as write_mesh_vtp
// writes a body frame; draw_frame then draws rigid bodies by their meshes.
PolyData meshes_poly_data(const std::vector<MeshPiece>& pieces);

// The world's time, particles and the surfaces of its bodies (one PolyData per body system
// that has meshes).
FrameData world_frame(const World& world);

}  // namespace upf::render
