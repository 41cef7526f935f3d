#include "framework/run/simulation_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "framework/checkpoint/checkpoint_file.h"
#include "framework/checkpoint/state_stream.h"
#include "framework/core/errors.h"
#include "framework/core/stopwatch.h"
#include "framework/output/atomic_file.h"
#include "framework/output/mesh_ply_obj_writer.h"
#include "framework/output/mesh_vtp_writer.h"
#include "framework/output/ply_points_writer.h"
#include "framework/output/pvd_series.h"
#include "framework/output/vtp_writer.h"
#include "framework/run/metrics_log.h"
#include "framework/run/probes.h"
#include "framework/run/run_result_json.h"
#include "framework/scene/json_input.h"
#include "framework/scene/scene_builder.h"

namespace upf {

namespace {

// The fields to write in each frame: those the scene names, or every exported field when it
// names none. Only the solvers know which fields exist, so this runs after World::prepare(); a
// name that no solver exports is bad input, reported under its JSON path with the names there are
// (exported fields only: they are the ones kept in the last good state after an instability).
std::vector<std::string> check_output_fields(const SceneDescription& scene,
                                             const Particles& particles) {
  std::vector<std::string> available;
  for (const auto& [name, field] : particles.scalar_fields())
    if (field.exported) available.push_back(name);
  for (const auto& [name, field] : particles.vector_fields())
    if (field.exported) available.push_back(name);
  std::sort(available.begin(), available.end());
  if (!scene.output.fields) return available;

  std::string list;
  for (const auto& name : available) list += (list.empty() ? "" : ", ") + name;
  std::vector<InputProblem> problems;
  const auto& fields = *scene.output.fields;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (std::find(available.begin(), available.end(), fields[i]) != available.end()) continue;
    std::string msg = "no solver of this scene exports a field '" + fields[i] + "'";
    if (auto guess = did_you_mean(fields[i], available)) msg += " (did you mean '" + *guess + "'?)";
    msg += "; fields available: " + (list.empty() ? std::string("none") : list);
    problems.push_back(
        {scene.source.string() + ":" + JsonInput::child("/output/fields", i), std::move(msg)});
  }
  if (!problems.empty()) throw InputError(std::move(problems));
  return fields;
}

// Writes frame files and keeps the .pvd series that ParaView opens as a time series.
class FrameWriter {
 public:
  FrameWriter(const std::filesystem::path& out_dir, const SceneDescription& scene,
              std::vector<std::string> fields, bool enabled, World& world,
              SurfaceMesher surface_mesher)
      : out_dir_(out_dir),
        fields_(std::move(fields)),
        enabled_(enabled && scene.output.vtp),
        ply_(enabled && scene.output.ply),
        surface_(enabled && scene.output.surface),
        spacing_(scene.world.spacing),
        series_(out_dir / "particles.pvd"),
        world_(world),
        surface_mesher_(std::move(surface_mesher)) {
    if (surface_ && !surface_mesher_)
      throw InputError(scene.source.string() + ":/output/formats",
                       "\"surface\" needs a surface mesher: this program was built without "
                       "upf_surface (OpenVDB)");
    if (enabled_ || ply_ || surface_) ensure_directory(out_dir / "frames");
    for (auto& b : world_.body_systems()) b->open_outputs(out_dir, enabled_);
  }

  // Body systems add their own files (body meshes) as further parts of the frame.
  void write(const Particles& particles, double time) {
    std::vector<std::string> files;
    if (enabled_) {
      char name[64];
      std::snprintf(name, sizeof name, "frames/frame_%05d.vtp", frames_);
      write_vtp(out_dir_ / name, particles, fields_);
      files.push_back(name);
    }
    if (ply_) {  // for Blender and MeshLab; ParaView has the .vtp, so not in the .pvd
      char name[64];
      std::snprintf(name, sizeof name, "frames/frame_%05d.ply", frames_);
      write_ply_points(out_dir_ / name, particles, fields_);
    }
    for (auto& b : world_.body_systems())
      for (auto& f : b->write_frame(out_dir_, frames_, time)) files.push_back(std::move(f));
    if (surface_) files.push_back(write_surface(particles));  // the last part at every step
    if (enabled_ || surface_) series_.add(time, files);
    ++frames_;
  }
  int frames() const { return frames_; }
  void save_state(StateWriter& out) const {
    out.put(std::int32_t(frames_));
    series_.save_state(out);
  }
  void restore_state(StateReader& in) {
    frames_ = in.get<std::int32_t>();
    series_.restore_state(in);
  }

 private:
  // The liquid's surface (output/liquid_surface.h) as frames/surface_NNNNN.ply for renderers and
  // .vtp for ParaView; returns the .vtp's name for the .pvd.
  std::string write_surface(const Particles& particles) const {
    const MeshPiece mesh = surface_mesher_(particles, spacing_, world_.executor().threads());
    char name[64];
    std::snprintf(name, sizeof name, "frames/surface_%05d.ply", frames_);
    write_mesh_ply(out_dir_ / name, mesh);
    std::snprintf(name, sizeof name, "frames/surface_%05d.vtp", frames_);
    write_mesh_vtp(out_dir_ / name, {mesh}, {});
    return name;
  }

  std::filesystem::path out_dir_;
  std::vector<std::string> fields_;
  bool enabled_;  // .vtp frames and the .pvd
  bool ply_;      // .ply point clouds
  bool surface_;  // liquid surface meshes: .ply, and .vtp in the .pvd
  double spacing_;
  PvdSeries series_;
  World& world_;
  SurfaceMesher surface_mesher_;
  int frames_ = 0;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Which solver moves each material, with its parameters: shows what `--solver` chose.
nlohmann::json materials_json(const SceneDescription& scene) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& m : scene.materials) {
    nlohmann::json& j = out[m.name];
    j["type"] = std::string(to_string(m.type));
    j["solver"] = m.solver.empty() ? nlohmann::json(nullptr) : nlohmann::json(m.solver);
    if (!m.solver.empty()) j["solver_params"] = m.solver_params.all();
  }
  return out;
}

void write_summary(const std::filesystem::path& path, const SceneDescription& scene,
                   const RunResult& r, const std::vector<double>& step_ms,
                   const std::vector<std::pair<std::string, std::vector<double>>>& stages) {
  nlohmann::json j = run_result_json(r);
  j["scene"] = scene.name;
  j["source"] = scene.source.string();
  j["materials"] = materials_json(scene);
  j["median_step_ms"] = median(step_ms);
  nlohmann::json stage_json = nlohmann::json::object();
  for (const auto& [name, values] : stages) stage_json[name] = median(values);
  j["median_stage_ms"] = stage_json;
  write_file_atomically(path, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

// The figures a run adds up step by step for its summary, kept across checkpoints.
struct RunTotals {
  std::vector<double> step_ms;
  std::vector<std::pair<std::string, std::vector<double>>> stages;
  double sum_dt = 0, sum_iterations = 0, sum_avg_error = 0;
  double wall_seconds_before = 0;  // spent by the runs this one resumes

  void add_stage(const std::string& name, double ms) {
    for (auto& [n, v] : stages)
      if (n == name) {
        v.push_back(ms);
        return;
      }
    stages.push_back({name, {ms}});
  }
  void save_state(StateWriter& out, const RunResult& r, double wall_seconds) const {
    out.put_vector(step_ms);
    out.put(std::uint64_t(stages.size()));
    for (const auto& [name, v] : stages) {
      out.put_string(name);
      out.put_vector(v);
    }
    out.put(sum_dt);
    out.put(sum_iterations);
    out.put(sum_avg_error);
    out.put(wall_seconds);
    out.put(std::int32_t(r.max_iterations));
    out.put(r.max_density_error);
    out.put(std::uint64_t(r.final_probes.size()));
    for (const auto& [name, value] : r.final_probes) {
      out.put_string(name);
      out.put(value);
    }
  }
  void restore_state(StateReader& in, RunResult& r) {
    in.get_vector(step_ms);
    const auto n = in.get<std::uint64_t>();
    if (n > in.remaining()) in.fail("more stages than the file can hold");
    stages.resize(std::size_t(n));
    for (auto& [name, v] : stages) {
      name = in.get_string();
      in.get_vector(v);
    }
    sum_dt = in.get<double>();
    sum_iterations = in.get<double>();
    sum_avg_error = in.get<double>();
    wall_seconds_before = in.get<double>();
    r.max_iterations = in.get<std::int32_t>();
    r.max_density_error = in.get<double>();
    const auto probes = in.get<std::uint64_t>();
    if (probes > in.remaining()) in.fail("more probes than the file can hold");
    r.final_probes.resize(std::size_t(probes));
    for (auto& [name, value] : r.final_probes) {
      name = in.get_string();
      value = in.get<double>();
    }
  }
};

// The caller's header that opens every checkpoint (RunOptions::checkpoint_header).
std::string read_header(StateReader& in) {
  in.section("header");
  return in.get_string();
}

}  // namespace

std::string read_checkpoint_header(const std::filesystem::path& run_dir) {
  StateReader in = read_checkpoint(run_dir / kCheckpointFileName);
  return read_header(in);
}

RunResult run_simulation(const SceneDescription& scene, const Registry& registry,
                         const RunOptions& options) {
  ensure_directory(options.out_dir);
  const std::filesystem::path checkpoint_path = options.out_dir / kCheckpointFileName;
  auto world = build_world(scene, registry, options.threads);
  world->prepare();
  const Particles& particles = world->particles();
  // Before anything is written: a misspelt field stops the run with nothing but the directory.
  std::vector<std::string> fields = check_output_fields(scene, particles);
  if (!options.resume && !options.scene_text.empty())
    write_file_atomically(options.out_dir / "scene.json",
                          [&](std::ostream& out) { out << options.scene_text; });
  const double end = options.end_time.value_or(scene.world.time.end);
  const Real spacing = scene.world.spacing;

  RunResult result;
  result.liquid_particles = particles.count(ParticleType::Liquid);
  result.total_particles = particles.size();
  result.threads = world->executor().threads();

  // A resumed run restores the world before the outputs open: body systems then append to their
  // files from where the checkpoint left them instead of starting them again.
  std::optional<StateReader> resume;
  if (options.resume) {
    resume.emplace(read_checkpoint(checkpoint_path));
    (void)read_header(*resume);
    world->restore_state(*resume);
  }
  FrameWriter frames(options.out_dir, scene, std::move(fields), options.write_frames, *world,
                     options.surface_mesher);
  MetricsLog metrics(options.out_dir / "metrics.csv", world->stage_names(), options.resume);
  std::vector<std::string> probe_names;
  for (const auto& p : scene.probes) probe_names.push_back(p.name);
  ProbeLog probe_log(options.out_dir / "probes.csv", probe_names, options.resume);
  auto probe_values = [&](const Particles& state) {
    std::vector<double> values;
    for (const auto& p : scene.probes) values.push_back(evaluate_probe(p, state, spacing));
    return values;
  };
  auto record_frame = [&](const Particles& state, double time) {
    frames.write(state, time);
    const auto values = probe_values(state);
    probe_log.add(time, values);
    metrics.flush();
    result.final_probes.clear();
    for (std::size_t i = 0; i < values.size(); ++i)
      result.final_probes.emplace_back(probe_names[i], values[i]);
  };

  const double frame_interval = 1.0 / scene.output.fps;
  std::int32_t next_frame = 1;
  RunTotals totals;
  if (resume) {
    resume->section("run");
    next_frame = resume->get<std::int32_t>();
    frames.restore_state(*resume);
    metrics.restore_state(*resume);
    probe_log.restore_state(*resume);
    totals.restore_state(*resume, result);
    if (!resume->at_end()) resume->fail("unread bytes at the end");
  } else {
    record_frame(particles, 0.0);
  }

  Stopwatch wall;
  auto wall_seconds = [&] { return totals.wall_seconds_before + wall.elapsed_ms() / 1000.0; };
  // Writes the checkpoint, then continues from exactly what it wrote, as a resumed run would.
  auto write_checkpoint_now = [&] {
    StateWriter out;
    out.section("header");
    out.put_string(options.checkpoint_header);
    world->save_state(out);
    out.section("run");
    out.put(next_frame);
    frames.save_state(out);
    metrics.save_state(out);
    probe_log.save_state(out);
    totals.save_state(out, result, wall_seconds());
    write_checkpoint(checkpoint_path, out.bytes());
    ++result.checkpoints;
    result.checkpoint_file = checkpoint_path;
    StateReader again(out.bytes(), checkpoint_path.string());
    (void)read_header(again);
    world->restore_state(again);
  };
  const CheckpointPolicy& policy = options.checkpoint;
  auto clock_now = [&] { return policy.wall_clock ? wall.elapsed_ms() / 1000.0 : world->time(); };
  // Simulated-time checkpoints fall on multiples of the interval, so a resumed run keeps the
  // schedule of the one it continues.
  double next_checkpoint =
      policy.wall_clock ? policy.every
                        : (std::floor(world->time() / policy.every + 1e-9) + 1) * policy.every;

  auto finish = [&] {
    result.wall_seconds = wall_seconds();
    result.steps = world->step_count();
    result.simulated_time = world->time();
    result.frames = frames.frames();
    // Means over the steps that were recorded: an unstable run's failed step counts in
    // `steps` but has no figures.
    if (const double recorded = double(totals.step_ms.size()); recorded > 0) {
      result.mean_dt = totals.sum_dt / recorded;
      result.mean_iterations = totals.sum_iterations / recorded;
      result.mean_avg_density_error = totals.sum_avg_error / recorded;
    }
    double compute_s = 0;
    for (double ms : totals.step_ms) compute_s += ms / 1000.0;
    if (compute_s > 0)
      result.fluid_particle_steps_per_second =
          double(result.liquid_particles) * double(result.steps) / compute_s;
    write_summary(options.out_dir / "summary.json", scene, result, totals.step_ms, totals.stages);
  };

  try {
    while (world->time() < end - 1e-12) {
      // Land on the end time with evenly split steps, never a sliver of a step.
      const double dt = world->next_time_step_until(end);
      world->step(dt);
      const StepReport& r = world->last_step();
      StepMetrics m;
      m.step = world->step_count();
      m.time = world->time();
      m.kinetic_energy = kinetic_energy(particles, world->executor());
      for (int t = 0; t < kParticleTypeCount; ++t)
        m.count_by_type[t] = particles.count(static_cast<ParticleType>(t));
      metrics.add(m, r);
      totals.step_ms.push_back(r.total_ms);
      totals.add_stage("neighbours", r.neighbour_ms);
      for (const auto& [name, ms] : r.stage_ms) totals.add_stage(name, ms);
      totals.sum_dt += dt;
      totals.sum_iterations += r.solver.iterations;
      totals.sum_avg_error += r.solver.avg_density_error;
      result.max_iterations = std::max(result.max_iterations, r.solver.iterations);
      result.max_density_error = std::max(result.max_density_error, r.solver.max_density_error);

      const bool at_end = world->time() >= end - 1e-12;
      if (world->time() >= next_frame * frame_interval - 1e-12 || at_end) {
        record_frame(particles, world->time());
        while (next_frame * frame_interval <= world->time() + 1e-12) ++next_frame;
      }
      if (options.on_step) options.on_step(*world);
      if (options.on_progress)
        options.on_progress({world->time(), end, world->step_count(), wall.elapsed_ms() / 1000.0});
      if (at_end) break;
      if (options.stop_requested && options.stop_requested()) {
        write_checkpoint_now();
        result.status = "interrupted";
        finish();
        return result;
      }
      if (policy.every > 0 && clock_now() >= next_checkpoint - 1e-12) {
        write_checkpoint_now();
        while (next_checkpoint <= clock_now() + 1e-12) next_checkpoint += policy.every;
      }
    }
  } catch (const InstabilityError& e) {
    // The state before the failed step is the last good one: keep it on disk, then report.
    const double last_good_time = world->time() - world->last_step().dt;
    record_frame(world->last_good(), last_good_time);
    result.status = "unstable";
    result.failure = e.what();
    finish();
    if (options.throw_on_instability) throw;
    return result;
  }
  finish();
  return result;
}

}  // namespace upf
