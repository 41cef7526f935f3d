#include "viewer/view_source.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "framework/core/errors.h"
#include "framework/scene/json_input.h"
#include "framework/scene/scene_builder.h"
#include "framework/scene/scene_reader.h"
#include "render/world_frame.h"

namespace upf::viewer {

namespace fs = std::filesystem;

RunFrames::RunFrames(const fs::path& run_dir) : frames_(render::read_run_frames(run_dir)) {
  facts_ =
      render::read_scene_facts(render::scene_record(run_dir), render::run_directory_name(run_dir));
  show(0);
}

void RunFrames::show(int k) {
  index_ = std::clamp(k, 0, count() - 1);
  frame_ = render::read_frame(frames_[std::size_t(index_)]);
}

LiveScene::LiveScene(const fs::path& scene_file, const Registry& registry, int threads)
    : registry_(registry), threads_(threads) {
  if (!fs::is_regular_file(scene_file))
    throw InputError(scene_file.string(), "no such scene file or run directory");
  edited_ = load_scene_file(scene_file, registry);
  facts_ = render::read_scene_facts(scene_file, edited_.name);
  facts_.spacing = double(edited_.world.spacing);
  const Vec3 g = edited_.world.gravity;
  const Eigen::Vector3d gravity(double(g.x), double(g.y), double(g.z));
  if (gravity.norm() > 0) facts_.up = -gravity.normalized();
  restart();
  if (!world_) throw InputError(scene_file.string(), error_);
}

void LiveScene::restart() {
  error_.clear();
  try {
    auto world = build_world(edited_, registry_, threads_);
    world->prepare();
    world_ = std::move(world);
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  if (world_) convert();
}

bool LiveScene::advance(double sim_seconds, double wall_seconds) {
  if (!world_ || !error_.empty()) return false;
  const auto start = std::chrono::steady_clock::now();
  const double until = world_->time() + sim_seconds;
  try {
    do {
      world_->step(world_->next_time_step());
    } while (world_->time() < until &&
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
                 wall_seconds);
  } catch (const InstabilityError& e) {
    error_ = e.what();
  }
  convert();
  return error_.empty();
}

void LiveScene::convert() {
  frame_ = render::world_frame(*world_);
}

}  // namespace upf::viewer
