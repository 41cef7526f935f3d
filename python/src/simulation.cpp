#include "simulation.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "device/device_pipelines.h"
#include "framework/core/errors.h"
#include "framework/output/liquid_surface.h"
#include "framework/scene/scene_builder.h"

namespace upf::python {

Simulation::Simulation(SceneDescription scene, std::shared_ptr<const Registry> registry,
                       int threads, std::string scene_text, std::string device_where)
    : scene_(std::move(scene)),
      registry_(std::move(registry)),
      scene_text_(std::move(scene_text)),
      device_where_(std::move(device_where)),
      world_(build_world(scene_, *registry_, threads)) {
  if (scene_.device != "cpu") check_device(scene_.device, *world_, device_where_);
}

World& Simulation::world() {
  if (!prepared_) {
    if (!failure_.empty())
      throw std::runtime_error("the simulation cannot start: preparing it failed (" + failure_ +
                               "); load the scene again");
    ++generation_;
    try {
      world_->prepare();
      // Python forces added since the check may take the scene out of the device's reach: the
      // pipeline says so here, before the first step.
      world_->set_device(make_device_pipeline(scene_.device, *world_, device_where_));
    } catch (const std::exception& e) {
      failure_ = e.what();
      throw;
    }
    prepared_ = true;
  }
  return *world_;
}

void Simulation::add_solver(std::unique_ptr<Solver> solver, CouplingUse use) {
  if (prepared_)
    throw InputError("add_force",
                     "the simulation has started (stepped, or its arrays were read): add forces "
                     "right after loading the scene");
  world_->add_solver(std::move(solver), std::move(use));
}

double Simulation::next_frame_time() const {
  // The run loop's frame clock (simulation_run.cpp): frame n at n / fps, the next one after now.
  const double fps = scene_.output.fps;
  const double n = std::floor(world_->time() * fps + 1e-9) + 1;
  return n / fps;
}

template <class Work>
auto Simulation::guarded(Work&& work) {
  if (!failure_.empty())
    throw std::runtime_error("the simulation cannot go on: a step failed earlier (" + failure_ +
                             "); load the scene again");
  World& w = world();
  ++generation_;
  try {
    return work(w);
  } catch (const std::exception& e) {
    failure_ = e.what();
    throw;
  } catch (...) {
    failure_ = "an exception from Python";
    throw;
  }
}

void Simulation::step() {
  guarded([&](World& w) { w.step_towards(next_frame_time()); });
}

void Simulation::advance_to(double t, const std::function<void()>& between_steps) {
  if (!std::isfinite(t)) throw InputError("advance_to", "the time must be finite");
  world();
  while (world_->time() < t - 1e-12) {
    guarded([&](World& w) { w.step_towards(std::min(t, next_frame_time())); });
    if (between_steps) between_steps();
  }
}

RunResult Simulation::run(const std::filesystem::path& out, std::optional<double> end,
                          bool frames) {
  RunOptions options;
  options.out_dir = out;
  options.end_time = end;
  options.write_frames = frames;
  options.scene_text = scene_text_;
  options.surface_mesher = run_surface_mesher;
  // A checkpoint names the command line that made it; a Python run (its forces and solvers
  // included) cannot be resumed by `upf run --resume`, so it writes none.
  options.final_checkpoint = false;
  RunResult r = guarded([&](World& w) { return run_world(w, scene_, options); });
  ++generation_;
  return r;
}

}  // namespace upf::python
