#include "framework/output/vdb_frame_writers.h"

#include "framework/output/liquid_surface.h"
#include "framework/output/vdb_points_writer.h"

namespace upf {

namespace {

VdbPointsCodec codec_named(const std::string& name) {
  for (VdbPointsCodec c :
       {VdbPointsCodec::none, VdbPointsCodec::truncate, VdbPointsCodec::fixed_point})
    if (name == to_string(c)) return c;
  return VdbPointsCodec::none;  // the scene reader allows only the names above
}

}  // namespace

VdbFrameWriters vdb_frame_writers() {
  return {run_surface_mesher, [](const std::filesystem::path& file, const Particles& particles,
                                 const std::vector<std::string>& fields, double spacing,
                                 const std::string& compression) {
            write_vdb_points(file, particles, fields, spacing, codec_named(compression));
          }};
}

}  // namespace upf
