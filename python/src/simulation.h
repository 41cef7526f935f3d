// The Python module's simulation: a scene's world, stepped on the scene's frame clock so that
// stepping from Python takes exactly the steps `upf run` takes, and run into an output folder
// through the same run loop (run_world). It owns the world; Python's views of its arrays check
// generation() before every use, and every step, run or restore moves it on.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "framework/core/state_stream.h"
#include "framework/run/simulation_run.h"
#include "framework/scene/scene.h"
#include "framework/solver/registry.h"
#include "framework/world/world.h"

namespace upf::python {

class Simulation {
 public:
  // Builds the world (particles, solvers, bodies); it is prepared on first use, so that forces
  // can still be added (add_solver), and then steps on the scene's device (`device_where` names
  // where the device was chosen, for errors). A device that does not exist or cannot run the
  // scene is an InputError here.
  Simulation(SceneDescription scene, std::shared_ptr<const Registry> registry, int threads,
             std::string scene_text, std::string device_where);

  const SceneDescription& scene() const { return scene_; }
  // The prepared world.
  World& world();
  bool prepared() const { return prepared_; }
  // A solver added to the world before it is prepared (Python forces). InputError once prepared.
  void add_solver(std::unique_ptr<Solver> solver, CouplingUse use);

  // One step towards the next frame time (World::step_towards): the steps `upf run` takes.
  void step();
  // Steps until time() == t, stopping on every frame time n / fps on the way as `upf run` does.
  // `between_steps` runs after each step (Python checks for Ctrl-C there); what it throws ends
  // the call with the world whole, at the step it reached.
  void advance_to(double t, const std::function<void()>& between_steps = {});
  // Runs into `out` (everything `upf run` writes) from the current time to `end` (default: the
  // scene's end). `overwrite`: as `upf run --overwrite` (run_manifest.h).
  RunResult run(const std::filesystem::path& out, std::optional<double> end, bool frames,
                bool overwrite = false);

  double time() const { return world_->time(); }
  std::uint64_t step_count() const { return world_->step_count(); }
  // Moves on whenever the particle arrays may move or change meaning.
  std::uint64_t generation() const { return generation_; }
  // After an exception inside a step the world is half-stepped: every later step refuses.
  const std::string& failure() const { return failure_; }

 private:
  double next_frame_time() const;
  // work(world) on the prepared world. An exception from inside a step leaves the world
  // half-stepped: it is remembered, and every later step or run refuses. Three kinds leave it
  // usable: InputError and OutputError (checks and files, between steps: the world does no I/O)
  // and a Ctrl-C in a Python callback (CallbackInterrupted), after which the state saved before
  // the step is put back.
  template <class Work>
  auto guarded(Work&& work);
  // The state before the step about to run, kept when a Python callback could be interrupted
  // in it (a Python force or solver): a copy of the world per step, so only then.
  void save_before_step(const World& w);
  // Refuses a step, advance or run that starts while another is going (a Python callback of the
  // step calling back into it, or another thread): the world is mid-step.
  class Busy;

  SceneDescription scene_;
  std::shared_ptr<const Registry> registry_;
  std::string scene_text_;
  std::string device_where_;
  std::unique_ptr<World> world_;
  bool prepared_ = false;
  bool preparing_ = false;  // a Python solver's prepare may call back in
  std::atomic<bool> busy_{false};
  bool interruptible_ = false;  // has Python callbacks; known once prepared
  StateWriter before_step_;     // save_before_step's state; empty: none
  std::uint64_t generation_ = 0;
  std::string failure_;
};

}  // namespace upf::python
