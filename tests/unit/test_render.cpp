// The picture pipeline (render/): reading frames back, the camera, the ray tracer and the
// colouring. References: the VTK XML format (what write_vtp writes, read_vtp must read back
// exactly), pinhole projection (a box framed by frame_box projects inside the picture), and
// matplotlib's viridis (low values dark blue-violet, high values yellow).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "framework/core/errors.h"
#include "framework/output/mesh_vtp_writer.h"
#include "framework/output/vtp_writer.h"
#include "framework/particles/particles.h"
#include "framework/particles/particles_of_types.h"
#include "framework/world/body_system.h"
#include "framework/world/world.h"
#include "render/camera.h"
#include "render/frame_picture.h"
#include "render/ray_tracer.h"
#include "render/run_frames.h"
#include "render/vtp_reader.h"
#include "render/world_frame.h"
#include "render/xml_tags.h"

namespace upf::render {
namespace {

namespace fs = std::filesystem;

class RenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("upf_render_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

Particles two_liquid_particles(double left_value, double right_value) {
  Particles p;
  p.add({-0.3f, 0, 0}, {0, 0, 0}, 1, ParticleType::Liquid, 0);
  p.add({0.3f, 0, 0}, {3, 4, 0}, 1, ParticleType::Liquid, 0);
  auto& f = p.scalar_field("heat", 0, true);
  f[0] = Real(left_value);
  f[1] = Real(right_value);
  return p;
}

TEST_F(RenderTest, ReadsBackWhatWriteVtpWrote) {
  Particles p = two_liquid_particles(0.25, 0.75);
  p.add({1, 2, 3}, {0, 0, 0}, 1, ParticleType::Frozen, 1);
  write_vtp(dir_ / "f.vtp", p, {"heat"});
  const PolyData d = read_vtp(dir_ / "f.vtp");
  ASSERT_EQ(d.points.size(), 3u);
  EXPECT_EQ(d.points[2], Eigen::Vector3f(1, 2, 3));
  EXPECT_EQ(d.point_array("type")->values, (std::vector<double>{0, 0, 3}));
  EXPECT_EQ(d.point_array("material")->values, (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(d.point_array("heat")->values, (std::vector<double>{0.25, 0.75, 0}));
  EXPECT_EQ(d.point_array("velocity")->components, 3);
  EXPECT_DOUBLE_EQ(*field_value(d, "speed", 1), 5.0);  // |(3, 4, 0)|
  EXPECT_FALSE(field_value(d, "no_such_field", 0).has_value());
}

// A split run's frame as pieces per rank (write_pvtp, framework/run/frame_pieces.h) reads as one
// data set, the pieces' particles in the .pvtp's order; an empty piece (a rank without
// particles of the frame's types) is allowed, a missing one is an error naming it.
TEST_F(RenderTest, ReadsAFrameWrittenAsPiecesAsOne) {
  Particles first = two_liquid_particles(0.25, 0.75);
  Particles second;
  second.add({1, 2, 3}, {0, 0, 0}, 1, ParticleType::Frozen, 1);
  second.scalar_field("heat", Real(0.5), true);
  write_vtp(dir_ / "f_p0000.vtp", first, {"heat"});
  write_vtp(dir_ / "f_p0001.vtp", particles_of_types(first, mask_of(ParticleType::Rigid)),
            {"heat"});
  write_vtp(dir_ / "f_p0002.vtp", second, {"heat"});
  write_pvtp(dir_ / "f.pvtp", first, {"heat"}, {"f_p0000.vtp", "f_p0001.vtp", "f_p0002.vtp"});
  const PolyData d = read_vtp(dir_ / "f.pvtp");
  ASSERT_EQ(d.points.size(), 3u);
  EXPECT_EQ(d.points[2], Eigen::Vector3f(1, 2, 3));
  EXPECT_EQ(d.point_array("type")->values, (std::vector<double>{0, 0, 3}));
  EXPECT_EQ(d.point_array("heat")->values, (std::vector<double>{0.25, 0.75, 0.5}));
  EXPECT_EQ(d.point_array("velocity")->values.size(), 9u);

  write_pvtp(dir_ / "g.pvtp", first, {"heat"}, {"f_p0000.vtp", "gone.vtp"});
  try {
    read_vtp(dir_ / "g.pvtp");
    ADD_FAILURE() << "a missing piece was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gone.vtp"), std::string::npos) << e.what();
  }
}

TEST_F(RenderTest, ReadsBackBodyMeshes) {
  MeshPiece tri{"t", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  write_mesh_vtp(dir_ / "m.vtp", {tri, tri}, {{"speed", {1.0, 2.0}}});
  const PolyData d = read_vtp(dir_ / "m.vtp");
  ASSERT_EQ(d.points.size(), 6u);
  ASSERT_EQ(d.triangles.size(), 2u);
  EXPECT_EQ(d.triangles[1], (std::array<std::uint32_t, 3>{3, 4, 5}));
  EXPECT_EQ(d.cell_array("body")->values, (std::vector<double>{0, 1}));
}

// A body system with fixed surfaces, standing in for the Bullet bodies of coupling/.
class FixedMeshes : public BodySystem {
 public:
  explicit FixedMeshes(std::vector<MeshPiece> pieces) : pieces_(std::move(pieces)) {}
  std::string_view name() const override { return "fixed"; }
  void prepare(World&) override {}
  void place_particles(World&, double) override {}
  void advance(World&, double) override {}
  std::vector<NamedBodyState> body_states() const override {
    std::vector<NamedBodyState> states;
    for (const auto& piece : pieces_) states.push_back({piece.name, {}});
    return states;
  }
  std::vector<MeshPiece> surface_meshes() const override { return pieces_; }

 private:
  std::vector<MeshPiece> pieces_;
};

// A world stepped live (upf view) is drawn from exactly what its saved frame would read back
// as: the particles' arrays and the bodies' triangles with their "body" cell array.
TEST_F(RenderTest, LiveWorldFrameIsWhatTheSavedFrameReadsBackAs) {
  World world(WorldSettings{}, 1);
  world.particles() = two_liquid_particles(0.25, 0.75);
  world.particles().add({1, 2, 3}, {0, 1, 0}, 1, ParticleType::Rigid, 1, 0);
  const MeshPiece tri{"t", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  const MeshPiece moved{"u", {{0, 0, 1}, {1, 0, 1}, {0, 1, 1.5}}, {{0, 2, 1}}};
  world.add_body_system(std::make_unique<FixedMeshes>(std::vector<MeshPiece>{tri, moved}));

  const FrameData live = world_frame(world);
  write_vtp(dir_ / "f.vtp", world.particles(), {"heat"});
  write_mesh_vtp(dir_ / "m.vtp", {tri, moved}, {});
  const PolyData saved = read_vtp(dir_ / "f.vtp"), saved_mesh = read_vtp(dir_ / "m.vtp");

  EXPECT_EQ(live.time, world.time());
  EXPECT_EQ(live.particles.points, saved.points);
  for (const char* name : {"type", "material", "velocity", "heat"}) {
    ASSERT_NE(live.particles.point_array(name), nullptr) << name;
    EXPECT_EQ(live.particles.point_array(name)->values, saved.point_array(name)->values) << name;
  }
  ASSERT_EQ(live.meshes.size(), 1u);
  EXPECT_EQ(live.meshes[0].points, saved_mesh.points);
  EXPECT_EQ(live.meshes[0].triangles, saved_mesh.triangles);
  EXPECT_EQ(live.meshes[0].cell_array("body")->values, saved_mesh.cell_array("body")->values);
}

TEST_F(RenderTest, DamagedFramesAreBadInputNamingTheFile) {
  Particles p = two_liquid_particles(0, 1);
  write_vtp(dir_ / "f.vtp", p, {"heat"});
  std::ifstream in(dir_ / "f.vtp", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir_ / "cut.vtp", std::ios::binary) << bytes.substr(0, bytes.size() - 60);
  std::ofstream(dir_ / "text.vtp") << "hello";
  for (const char* name : {"cut.vtp", "text.vtp", "missing.vtp"}) {
    try {
      read_vtp(dir_ / name);
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(read_xml_tags("<a b=\"1"), std::runtime_error);
  EXPECT_THROW(read_run_frames(dir_), InputError);  // no particles.pvd
}

TEST_F(RenderTest, ReadsTheRunsFrameListWithItsParts) {
  std::ofstream(dir_ / "particles.pvd")
      << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\"><Collection>\n"
         "<DataSet timestep=\"0\" part=\"0\" file=\"frames/a.vtp\"/>\n"
         "<DataSet timestep=\"0\" part=\"1\" file=\"frames/b.vtp\"/>\n"
         "<DataSet timestep=\"0.5\" part=\"0\" file=\"frames/c.vtp\"/>\n"
         "</Collection></VTKFile>\n";
  const auto frames = read_run_frames(dir_);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].parts.size(), 2u);
  EXPECT_EQ(frames[1].time, 0.5);
  EXPECT_EQ(frames[1].parts[0], dir_ / "frames/c.vtp");
}

// Pinhole projection: every corner of the framed box lands inside the picture.
TEST(RenderCamera, FrameBoxShowsTheWholeBox) {
  const Eigen::Vector3d lo(0, 0, 0), hi(1.6, 1.0, 0.4);
  const int w = 1280, h = 720;
  const Camera c = frame_box(lo, hi, Eigen::Vector3d::UnitY(), double(w) / h);
  const CameraRays rays(c, w, h);
  const Eigen::Vector3f f = rays.forward(), r = rays.right(), u = rays.up();
  const double tan_h = std::tan(c.fov_degrees * M_PI / 360.0), tan_w = tan_h * w / h;
  double widest = 0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                 (k & 4) ? hi.z() : lo.z());
    const Eigen::Vector3f q = (corner - c.position).cast<float>();
    ASSERT_GT(q.dot(f), 0) << "corner behind the camera";
    const double x = q.dot(r) / q.dot(f) / tan_w, y = q.dot(u) / q.dot(f) / tan_h;
    EXPECT_LE(std::abs(x), 1.0);
    EXPECT_LE(std::abs(y), 1.0);
    widest = std::max({widest, std::abs(x), std::abs(y)});
  }
  EXPECT_GT(widest, 0.8) << "the box should fill the picture, not sit small in it";
}

TEST(RenderTracer, OneSphereCoversTheCentreAndNotTheCorners) {
  RenderScene scene;
  scene.opaque.radius = 0.5f;
  scene.opaque.centres = {Eigen::Vector3f::Zero()};
  scene.opaque.colours = {Colour(1, 0, 0)};
  Camera camera;
  camera.position = {0, 0, 5};
  camera.target = {0, 0, 0};
  TraceSettings s;
  s.width = 64;
  s.height = 48;
  const Image image = ray_trace(scene, camera, s);
  ASSERT_EQ(image.width(), 64);
  ASSERT_EQ(image.height(), 48);
  const Colour centre = image.at(32, 24), corner = image.at(0, 0);
  EXPECT_GT(centre.x(), 0.3f);                // red sphere, lit
  EXPECT_LT(centre.y() + centre.z(), 0.6f);   // ... and not grey
  EXPECT_NEAR(corner.x(), corner.z(), 0.1f);  // background: a pale grey-blue
  // The sphere's silhouette: radius 0.5 at distance 5 under a 40 degree field of view spans
  // 2 atan(0.5 / 5) = 11.4 degrees: 11.4 / 40 * 48 = 13.7 pixels across.
  int covered = 0;
  for (int x = 0; x < 64; ++x) covered += image.at(x, 24).x() > image.at(x, 24).z() + 0.2f;
  EXPECT_NEAR(covered, 13.7, 1.5);
}

TEST(RenderTracer, SameImageForAnyThreadCount) {
  RenderScene scene;
  scene.opaque.radius = 0.1f;
  for (int i = 0; i < 200; ++i) {
    scene.opaque.centres.emplace_back(float(i % 10) * 0.15f - 0.7f, float(i / 10) * 0.07f - 0.7f,
                                      float(i % 7) * 0.05f);
    scene.opaque.colours.emplace_back(0.2f, 0.5f, 0.9f);
  }
  Camera camera;
  camera.position = {1, 1, 4};
  camera.target = {0, 0, 0};
  TraceSettings s;
  s.width = 80;
  s.height = 60;
  s.threads = 1;
  const auto one = ray_trace(scene, camera, s).rgb8();
  s.threads = 2;
  EXPECT_EQ(ray_trace(scene, camera, s).rgb8(), one);
}

// Colours follow the chosen field: viridis puts low values in blue-violet and high ones in
// yellow, so the low particle is bluer than red and the high one redder than blue.
TEST_F(RenderTest, ColoursFollowTheChosenField) {
  write_vtp(dir_ / "f.vtp", two_liquid_particles(0.0, 1.0), {"heat"});
  FrameData frame;
  frame.particles = read_vtp(dir_ / "f.vtp");
  PictureContext context;
  context.settings.width = 160;
  context.settings.height = 90;
  context.particle_spacing = 0.4;
  context.camera.position = {0, 0, 3};
  context.camera.target = {0, 0, 0};
  context.scale = ColourScale{"heat", 0.0, 1.0};
  auto centre_colour = [&](const Image& image, const Eigen::Vector3f& x) {
    const CameraRays rays(context.camera, image.width(), image.height());
    const Eigen::Vector3f q = x - context.camera.position.cast<float>();
    const double tan_h = std::tan(context.camera.fov_degrees * M_PI / 360.0);
    const double tan_w = tan_h * image.width() / image.height();
    const double px =
        (q.dot(rays.right()) / q.dot(rays.forward()) / tan_w + 1) * 0.5 * image.width();
    const double py = (1 - q.dot(rays.up()) / q.dot(rays.forward()) / tan_h) * 0.5 * image.height();
    return image.at(int(px), int(py));
  };
  Image image = draw_frame(frame, context);
  Colour low = centre_colour(image, frame.particles.points[0]);
  Colour high = centre_colour(image, frame.particles.points[1]);
  EXPECT_GT(low.z(), low.x()) << low.transpose();
  EXPECT_GT(high.x(), high.z()) << high.transpose();
  EXPECT_GT(high.y(), low.y() + 0.3f);

  // Swapping the values swaps the colours.
  write_vtp(dir_ / "f.vtp", two_liquid_particles(1.0, 0.0), {"heat"});
  frame.particles = read_vtp(dir_ / "f.vtp");
  image = draw_frame(frame, context);
  EXPECT_GT(centre_colour(image, frame.particles.points[0]).x(),
            centre_colour(image, frame.particles.points[0]).z());
  EXPECT_GT(centre_colour(image, frame.particles.points[1]).z(),
            centre_colour(image, frame.particles.points[1]).x());
}

}  // namespace
}  // namespace upf::render
