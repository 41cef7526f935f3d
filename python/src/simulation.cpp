#include "simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "device/device_pipelines.h"
#include "framework/core/errors.h"
#include "framework/output/vdb_frame_writers.h"
#include "framework/scene/scene_builder.h"
#include "python_callback.h"
#include "python_force.h"
#include "python_solver.h"

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

class Simulation::Busy {
 public:
  Busy(Simulation& s, const char* call) : s_(s) {
    if (s_.busy_.exchange(true))
      throw std::runtime_error(
          std::string("Simulation.") + call +
          "(): the simulation is in the middle of a step; a Python force or solver must not "
          "step, advance or run the simulation that calls it (nor may another thread while it "
          "steps)");
  }
  ~Busy() { s_.busy_ = false; }
  Busy(const Busy&) = delete;
  Busy& operator=(const Busy&) = delete;

 private:
  Simulation& s_;
};

World& Simulation::world() {
  if (!prepared_) {
    if (preparing_)
      throw std::runtime_error(
          "the simulation is being prepared: a Python solver's prepare() must not use the "
          "simulation it belongs to");
    if (!failure_.empty())
      throw std::runtime_error("the simulation cannot start: preparing it failed (" + failure_ +
                               "); load the scene again");
    ++generation_;
    preparing_ = true;
    try {
      world_->prepare();
      // Python forces added since the check may take the scene out of the device's reach: the
      // pipeline says so here, before the first step.
      world_->set_device(make_device_pipeline(scene_.device, *world_, device_where_));
    } catch (const std::exception& e) {
      preparing_ = false;
      failure_ = e.what();
      throw;
    }
    preparing_ = false;
    prepared_ = true;
    for (const auto& s : world_->solvers())
      if (dynamic_cast<const PythonForce*>(s.get()) || dynamic_cast<const PythonSolver*>(s.get()))
        interruptible_ = true;
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

void Simulation::save_before_step(const World& w) {
  if (!interruptible_) return;
  before_step_ = StateWriter{};
  w.save_state(before_step_);
}

template <class Work>
auto Simulation::guarded(Work&& work) {
  if (!failure_.empty())
    throw std::runtime_error("the simulation cannot go on: a step failed earlier (" + failure_ +
                             "); load the scene again");
  World& w = world();
  ++generation_;
  before_step_ = StateWriter{};
  try {
    return work(w);
  } catch (const CallbackInterrupted&) {
    // Ctrl-C while a Python callback ran: the docs promise a world that can go on, so the step
    // is undone (the same checkpoint bytes a resumed run starts from).
    if (before_step_.bytes().empty()) {
      failure_ = "a step interrupted by Ctrl-C";
      throw;
    }
    try {
      StateReader in(before_step_.bytes(), "the state before the interrupted step");
      w.restore_state(in);
      ++generation_;
    } catch (const std::exception& e) {
      failure_ = e.what();
    }
    throw;
  } catch (const InputError&) {
    throw;  // a check before the first step (output fields, the output folder): nothing ran
  } catch (const OutputError&) {
    throw;  // files are written between steps (the world does no I/O): the world is whole
  } catch (const std::exception& e) {
    failure_ = e.what();
    throw;
  } catch (...) {
    failure_ = "an exception from Python";
    throw;
  }
}

void Simulation::step() {
  const Busy busy(*this, "step");
  guarded([&](World& w) {
    save_before_step(w);
    w.step_towards(next_frame_time());
  });
}

void Simulation::advance_to(double t, const std::function<void()>& between_steps) {
  const Busy busy(*this, "advance_to");
  if (!std::isfinite(t)) throw InputError("advance_to", "the time must be finite");
  world();
  while (world_->time() < t - 1e-12) {
    guarded([&](World& w) {
      save_before_step(w);
      w.step_towards(std::min(t, next_frame_time()));
    });
    if (between_steps) between_steps();
  }
}

RunResult Simulation::run(const std::filesystem::path& out, std::optional<double> end, bool frames,
                          bool overwrite) {
  RunOptions options;
  options.out_dir = out;
  options.overwrite = overwrite;
  options.end_time = end;
  options.write_frames = frames;
  options.scene_text = scene_text_;
  options.vdb_writers = vdb_frame_writers();
  // A checkpoint names the command line that made it; a Python run (its forces and solvers
  // included) cannot be resumed by `upf run --resume`, so it writes none.
  options.final_checkpoint = false;
  // The state before each step, for a Ctrl-C in a Python callback of the run's steps.
  options.on_step = [this](const World& w) { save_before_step(w); };
  const Busy busy(*this, "run");
  RunResult r = guarded([&](World& w) {
    save_before_step(w);
    return run_world(w, scene_, options);
  });
  ++generation_;
  return r;
}

}  // namespace upf::python
