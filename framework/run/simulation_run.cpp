#include "framework/run/simulation_run.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>

#include "framework/checkpoint/checkpoint_file.h"
#include "framework/core/errors.h"
#include "framework/core/fnv1a.h"
#include "framework/core/state_stream.h"
#include "framework/core/stopwatch.h"
#include "framework/output/atomic_file.h"
#include "framework/run/metrics_log.h"
#include "framework/run/output_fields.h"
#include "framework/run/probes.h"
#include "framework/run/run_manifest.h"
#include "framework/run/run_totals.h"
#include "framework/run/solver_tables.h"
#include "framework/run/surface_memory.h"
#include "framework/run/thread_share_watch.h"
#include "framework/scene/scene_builder.h"

namespace upf {

namespace {

// The caller's header that opens every checkpoint (RunOptions::checkpoint_header).
std::string read_header(StateReader& in) {
  in.section("header");
  return in.get_string();
}

// What names the scene in a checkpoint: FNV-1a 64 of the scene's text as the run was given it.
std::uint64_t scene_identity(const std::string& scene_text) {
  return fnv1a(scene_text.data(), scene_text.size());
}

// After the header: the scene's identity, checked before the world is touched.
void read_scene_identity(StateReader& in, const std::string& scene_text) {
  in.section("scene");
  in.expect(in.get<std::uint64_t>() == scene_identity(scene_text), "the scene's text");
}

// A resumed run continues the run recorded in its folder: a checkpoint of another scene (copied
// there, or a folder reused) would splice two runs' files together.
void check_folder_records_scene(const std::filesystem::path& dir, const std::string& scene_text) {
  const auto record = dir / kSceneRecordFile;
  std::error_code ec;
  if (scene_text.empty() || !std::filesystem::is_regular_file(record, ec)) return;
  std::ifstream in(record, std::ios::binary);
  const std::string recorded((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  if (recorded != scene_text)
    throw InputError((dir / kCheckpointFileName).string(),
                     "is a checkpoint of another scene than the run recorded in this folder (" +
                         record.string() +
                         " differs from the checkpoint's scene): resuming would mix two runs");
}

// A liquid's viscosity is solved implicitly (metrics.csv then has viscosity_iterations).
bool has_viscosity_solve(const SceneDescription& scene) {
  for (const Material& m : scene.materials)
    if (m.type == ParticleType::Liquid && m.param("implicit_viscosity") > 0) return true;
  return false;
}

std::vector<std::string> probe_names(const SceneDescription& scene) {
  std::vector<std::string> names;
  for (const auto& p : scene.probes) names.push_back(p.name);
  return names;
}

// Frame n falls at n / fps: the run loop stops a step there (World::step_towards). Every rank
// keeps the clock; only rank 0 records.
class FrameClock {
 public:
  explicit FrameClock(double fps) : fps_(fps) {}
  double next_frame_time() const { return double(next_frame_) / fps_; }
  // A run that starts from a world already stepped (Simulation.run in Python): its first frame is
  // the state now, the next one the first n / fps after it.
  void start_at(double time) { next_frame_ = std::int32_t(std::floor(time * fps_ + 1e-9)) + 1; }
  bool due(double time) const { return time >= next_frame_time() - 1e-12; }
  void passed(double time) {
    while (next_frame_time() <= time + 1e-12) ++next_frame_;
  }
  // The frames still to come up to `end`: those on the clock, and one at the end when it falls
  // between them.
  int frames_until(double end) const {
    const auto last_on_clock = std::int64_t(std::floor(end * fps_ + 1e-9));
    int frames = int(std::max<std::int64_t>(0, last_on_clock - next_frame_ + 1));
    if (std::abs(double(last_on_clock) / fps_ - end) > 1e-12) ++frames;
    return frames;
  }
  void save_state(StateWriter& out) const { out.put(next_frame_); }
  void restore_state(StateReader& in) { next_frame_ = in.get<std::int32_t>(); }

 private:
  double fps_;
  std::int32_t next_frame_ = 1;
};

// The metrics row of the world's last step. Through the world, not its particles: with a device
// pipeline these are reductions on the device, and across ranks sums over every rank (so every
// rank computes them, and rank 0 records them).
StepMetrics step_metrics(const World& world) {
  StepMetrics m;
  m.step = world.step_count();
  m.time = world.time();
  m.kinetic_energy = world.kinetic_energy();
  for (int t = 0; t < kParticleTypeCount; ++t)
    m.count_by_type[t] = world.count(static_cast<ParticleType>(t));
  return m;
}

// Everything a run records: frames on the frame clock, metrics.csv per step, probes.csv,
// body_forces.csv and the solvers' tables (solver_tables.h) per step (or every
// /output/probe_every steps) and per frame, and the totals
// behind summary.json; all of it saved in and restored from checkpoints. It records the state it
// is handed: the world's particles, or on a split world all ranks' particles gathered.
class RunRecorder {
 public:
  RunRecorder(const SceneDescription& scene, const RunOptions& options, const World& world,
              std::vector<std::string> fields, std::size_t frozen_count, RunResult& result,
              FrameClock& clock, RunManifest& manifest)
      : scene_(scene),
        world_(world),
        result_(result),
        clock_(clock),
        manifest_(manifest),
        out_dir_(options.out_dir),
        frames_(options.out_dir, scene, std::move(fields), options.write_frames, world,
                frozen_count, options.vdb_writers, options.resume),
        metrics_(options.out_dir / "metrics.csv", world.stage_names(), options.resume,
                 !world.sources().empty(), has_viscosity_solve(scene)),
        probes_(options.out_dir / "probes.csv", probe_names(scene), options.resume),
        tables_(world, options.out_dir, options.resume) {}

  // A frame of `state` (the world's particles, or its last good state) at `time`; `pieces`: the
  // .vtp frame went out as pieces per rank.
  void frame(const Particles& state, double time, const FramePieceNames& pieces = {}) {
    manifest_.claim(frames_.files_of_frame(pieces));
    frames_.write(state, time, pieces);
    sample_probes(state, time);
    metrics_.flush();
  }

  // A row of probes.csv: every probe evaluated on `state` at `time`; and of each solver table.
  void sample_probes(const Particles& state, double time) {
    tables_.add(state, time);
    std::vector<double> values;
    for (const auto& p : scene_.probes)
      values.push_back(evaluate_probe(p, state, scene_.world.spacing));
    probes_.add(time, values);
    result_.final_probes.clear();
    for (std::size_t i = 0; i < values.size(); ++i)
      result_.final_probes.emplace_back(scene_.probes[i].name, values[i]);
  }

  // The metrics row of the world's last step (step_metrics).
  void step_row(const StepMetrics& m) {
    metrics_.add(m, world_.last_step());
    totals_.add_step(world_.last_step(), result_, m.count_by_type[int(ParticleType::Liquid)]);
    // The counts at the end: emitters and sinks change them from step to step.
    result_.liquid_particles = m.count_by_type[int(ParticleType::Liquid)];
    result_.total_particles = 0;
    for (const std::size_t c : m.count_by_type) result_.total_particles += c;
  }
  int frames() const { return frames_.frames(); }
  // Whether a frame reads the particles beyond the .vtp pieces: probes, tables, PLY, surfaces.
  bool frame_reads_particles() const {
    return samples_between_frames() || frames_.reads_particles_beside_pieces();
  }
  // Whether a step with this count records probes and tables between frames.
  bool samples_between_frames() const { return !scene_.probes.empty() || !tables_.empty(); }
  void record_step(double time, bool with_state) {
    frames_.record_step(time, world_.last_step().dt, with_state);
  }

  // The frames still to come up to `end` of `state`, with `first` the frame of the state now.
  OutputEstimate estimate(const Particles& state, double end, bool first) const {
    OutputEstimate e;
    e.frames = clock_.frames_until(end) + (first ? 1 : 0);
    e.bytes_per_frame = frames_.bytes_per_frame(state);
    e.bytes_once = frames_.bytes_once(state);
    e.total_bytes = e.bytes_once + std::uint64_t(e.frames) * e.bytes_per_frame;
    e.compressed = frames_.compressed();
    e.surface = scene_.output.surface;
    return e;
  }

  // The result's totals and summary.json.
  void finish(double wall_seconds) {
    result_.wall_seconds = wall_seconds;
    result_.steps = world_.step_count();
    result_.simulated_time = world_.time();
    result_.frames = frames_.frames();
    totals_.finish(result_);
    totals_.write_summary(out_dir_ / "summary.json", scene_, result_);
  }

  double wall_seconds_before() const { return totals_.wall_seconds_before(); }
  // The clock comes first in the run section: ranks that record nothing read only it.
  void save_state(StateWriter& out, double wall_seconds) {
    clock_.save_state(out);
    frames_.save_state(out);
    metrics_.save_state(out);
    probes_.save_state(out);
    tables_.save_state(out);
    totals_.save_state(out, result_, wall_seconds);
  }
  void restore_state(StateReader& in) {
    clock_.restore_state(in);
    frames_.restore_state(in);
    metrics_.restore_state(in);
    probes_.restore_state(in);
    tables_.restore_state(in);
    totals_.restore_state(in, result_);
  }

 private:
  const SceneDescription& scene_;
  const World& world_;
  RunResult& result_;
  FrameClock& clock_;
  RunManifest& manifest_;
  std::filesystem::path out_dir_;
  FrameWriter frames_;
  MetricsLog metrics_;
  ProbeLog probes_;
  SolverTableLogs tables_;
  RunTotals totals_;
};

// When the next checkpoint is due, on the wall clock or the simulated clock. Simulated-time
// checkpoints fall on multiples of the interval, so a resumed run keeps the schedule of the one
// it continues.
class CheckpointSchedule {
 public:
  CheckpointSchedule(const CheckpointPolicy& policy, double simulated_time) : policy_(policy) {
    next_ = policy.wall_clock
                ? policy.every
                : (std::floor(simulated_time / policy.every + 1e-9) + 1) * policy.every;
  }
  // True once per interval; `wall_seconds` counts this process only.
  bool due(double wall_seconds, double simulated_time) {
    if (policy_.every <= 0) return false;
    const double now = policy_.wall_clock ? wall_seconds : simulated_time;
    if (now < next_ - 1e-12) return false;
    // The first multiple of `every` after now, computed: stepping to it by additions took
    // now / every of them (for ever at 1e-300 s, deaf to Ctrl-C between steps). One more
    // multiple when the division rounded down onto now; and when `every` is too small to move
    // past now at all, the next step is due.
    const double after = now + 1e-12;
    const double k = std::floor(after / policy_.every) + 1;
    next_ = k * policy_.every;
    if (!(next_ > after)) next_ = (k + 1) * policy_.every;
    if (!(next_ > after) || !std::isfinite(next_)) next_ = std::nextafter(after, HUGE_VAL);
    return true;
  }

 private:
  CheckpointPolicy policy_;
  double next_;
};

// The files a run writes whatever happens, claimed before any of them is opened: the logs,
// the series, the summary, the checkpoint, the scene's record and the solvers' tables.
std::vector<std::string> fixed_run_files(const World& world) {
  std::vector<std::string> files = {"particles.pvd",  "metrics.csv",      "probes.csv",
                                    "summary.json",   "bodies.csv",       "body_forces.csv",
                                    kSceneRecordFile, kCheckpointFileName};
  for (const std::string& table : SolverTableLogs::file_names(world)) files.push_back(table);
  return files;
}

}  // namespace

std::string read_checkpoint_header(const std::filesystem::path& run_dir) {
  StateReader in = read_checkpoint(run_dir / kCheckpointFileName);
  return read_header(in);
}

RunResult run_simulation(const SceneDescription& scene, const Registry& registry,
                         const RunOptions& options) {
  auto world = build_world(scene, registry, options.threads);
  world->prepare();
  if (options.make_device) world->set_device(options.make_device(*world));
  if (options.make_domain) world->set_domain(options.make_domain(*world));
  return run_world(*world, scene, options);
}

RunResult run_world(World& world, const SceneDescription& scene, const RunOptions& options) {
  // On a split world every rank runs this loop (the same steps, the same collectives); rank 0
  // alone records, from the particles every rank sends it.
  const ParticleDomain* domain = world.domain();
  const bool records = !domain || domain->rank() == 0;
  // One decision for every rank (a signal or a wall clock may differ between them).
  auto agreed = [&](bool mine) { return domain ? domain->max(mine ? 1.0 : 0.0) > 0 : mine; };
  Particles gathered;
  // The state to record: this rank's particles, or on a split world every rank's on rank 0.
  auto whole = [&](const Particles& mine) -> const Particles& {
    if (!domain) return mine;
    domain->gather(mine, gathered);
    return gathered;
  };

  const std::filesystem::path checkpoint_path = options.out_dir / kCheckpointFileName;
  // What the run owns in its folder (run_manifest.h); only rank 0 writes there. A folder of
  // someone else's files is refused here, before anything is written.
  std::optional<RunManifest> manifest;
  if (records) {
    if (options.resume) check_folder_records_scene(options.out_dir, options.scene_text);
    manifest.emplace(options.resume ? RunManifest::for_continued_run(options.out_dir)
                                    : RunManifest::for_new_run(options.out_dir, options.overwrite));
  }
  // Before anything is written: a misspelt field stops the run with nothing but the directory.
  std::vector<std::string> fields = check_output_fields(scene, world.particles());
  if (options.write_frames)
    check_surface_memory(scene, world.count(ParticleType::Liquid));  // every rank: a collective
  std::size_t replaced = 0;
  const bool writes_frames =
      options.write_frames && (scene.output.vtp || scene.output.ply || scene.output.surface);
  if (manifest) {
    // The checks passed: an earlier run in the same directory goes now, not before (a refused run
    // leaves it as it was), and only the files its manifest lists.
    if (!options.resume) replaced = manifest->clear_previous();
    manifest->claim(fixed_run_files(world));
    if (writes_frames) manifest->claim_directory("frames");
    if (!options.resume && !options.scene_text.empty())
      write_file_atomically(options.out_dir / kSceneRecordFile,
                            [&](std::ostream& out) { out << options.scene_text; });
  }
  const double end = options.end_time.value_or(scene.world.time.end);

  RunResult result;
  result.replaced_files = replaced;
  result.liquid_particles = world.count(ParticleType::Liquid);
  result.total_particles = world.executor().total(world.particles().owned_size());
  result.threads = world.executor().threads();
  FrameClock clock(scene.output.fps);
  std::optional<FramePieces> pieces;
  if (domain && scene.output.pieces_per_rank && scene.output.vtp && options.write_frames) {
    (void)domain->max(0.0);  // a barrier: rank 0 has cleared an earlier run's files
    pieces.emplace(options.out_dir, scene, fields, world, options.resume);
  }
  const std::size_t frozen_count = world.count(ParticleType::Frozen);  // every rank: a collective
  std::optional<RunRecorder> recorder;
  if (records)
    recorder.emplace(scene, options, world, std::move(fields), frozen_count, result, clock,
                     *manifest);
  // Whether a frame gathers every rank's particles on rank 0: always, unless the .vtp frames go
  // out as pieces per rank and nothing else in a frame reads the particles.
  const bool frames_gather = !pieces || agreed(recorder && recorder->frame_reads_particles());
  // A frame of `mine` (this rank's particles, or its last good state) at `time`.
  // Frame `frame`'s pieces of every rank, recorded by rank 0 before any rank writes them: the
  // collective that follows is the barrier.
  auto claim_pieces = [&](int frame) {
    if (manifest) manifest->claim(pieces->files_of_frame(frame));
    return int(domain->max(double(frame)));
  };
  auto write_frame = [&](const Particles& mine, double time) {
    FramePieceNames names;
    if (pieces) names = pieces->write(mine, claim_pieces(recorder ? recorder->frames() : 0));
    const Particles& state = frames_gather ? whole(mine) : mine;
    if (recorder) recorder->frame(state, time, names);
  };
  if (options.resume) {
    StateReader in = read_checkpoint(checkpoint_path);
    (void)read_header(in);
    read_scene_identity(in, options.scene_text);
    world.restore_state(in);
    in.section("run");
    if (recorder) {
      recorder->restore_state(in);
      if (!in.at_end()) in.fail("unread bytes at the end");
    } else {
      clock.restore_state(in);
    }
  } else {
    clock.start_at(world.time());
  }
  if (!options.resume) {
    // Gathered once, for the size estimate, even when the frames go out as pieces.
    const Particles& first = whole(world.particles());
    if (recorder && options.write_frames && options.on_output_estimate &&
        world.time() < end - 1e-12)
      options.on_output_estimate(recorder->estimate(first, end, true));
    const FramePieceNames names =
        pieces ? pieces->write(world.particles(), claim_pieces(0)) : FramePieceNames{};
    if (recorder) recorder->frame(first, world.time(), names);
  }

  if (options.resume && world.time() >= end - 1e-12) {
    // Complete already (its final checkpoint is at the end): nothing to simulate, nothing to
    // rewrite. `--end` beyond it extends the run.
    result.already_complete = true;
    result.steps = world.step_count();
    result.simulated_time = world.time();
    return result;
  }
  const double start_time = world.time();
  const std::uint64_t start_steps = world.step_count();
  Stopwatch wall;
  auto wall_seconds = [&] {
    return (recorder ? recorder->wall_seconds_before() : 0.0) + wall.elapsed_ms() / 1000.0;
  };
  // Writes the checkpoint, then continues from exactly what it wrote, as a resumed run would. On
  // a split world rank 0 writes the gathered world, and every rank continues from its bytes.
  auto write_checkpoint_now = [&] {
    StateWriter out;
    out.section("header");
    out.put_string(options.checkpoint_header);
    out.section("scene");
    out.put(scene_identity(options.scene_text));
    world.save_state(out);
    out.section("run");
    if (recorder) {
      recorder->save_state(out, wall_seconds());
      write_checkpoint(checkpoint_path, out.bytes());
    }
    ++result.checkpoints;
    result.checkpoint_file = checkpoint_path;
    std::vector<char> bytes = out.bytes();
    if (domain) domain->broadcast(bytes);
    StateReader again(std::move(bytes), checkpoint_path.string());
    (void)read_header(again);
    read_scene_identity(again, options.scene_text);
    world.restore_state(again);
  };
  CheckpointSchedule checkpoints(options.checkpoint, world.time());
  // The device pipeline keeps the thread count it was made with. The world leaves the run with
  // the count it came with (the Python module steps it on).
  const bool follows_cores = options.follow_free_cores && !world.device();
  ThreadShareWatch free_cores(follows_cores ? world.executor().threads() : 1);
  const ThreadCountKeeper keep_threads(world);
  double thread_steps = 0;
  const int probe_every = scene.output.probe_every;

  try {
    while (world.time() < end - 1e-12) {
      // Steps land on every frame time, split evenly between frames (never a sliver of a step):
      // the steps up to any time are the same whatever `end` is, so a preview's frames are the
      // first frames of the full shot, and `--resume --end` extends a run bit for bit.
      world.step_towards(std::min(end, clock.next_frame_time()));
      const bool at_end = world.time() >= end - 1e-12;
      const StepMetrics metrics = step_metrics(world);
      if (recorder) recorder->step_row(metrics);
      const double t = world.time();
      const bool at_frame = clock.due(t) || at_end;
      // Between frames too: an impact lasts a few steps, not a few frames.
      const bool row_due = probe_every > 0 && world.step_count() % std::uint64_t(probe_every) == 0;
      if (recorder) recorder->record_step(t, at_frame || row_due);
      if (at_frame) {
        write_frame(world.particles(), t);
        clock.passed(t);
      } else if (row_due && agreed(recorder && recorder->samples_between_frames())) {
        const Particles& state = whole(world.particles());
        if (recorder) recorder->sample_probes(state, t);
      }
      if (options.on_step) options.on_step(world);
      thread_steps += world.executor().threads();
      result.mean_threads = thread_steps / double(world.step_count() - start_steps);
      world.set_threads(free_cores.threads_after_step(world.executor().threads()));
      if (options.on_progress && records)
        options.on_progress({world.time(), end, world.step_count(), start_time,
                             world.step_count() - start_steps, wall.elapsed_ms() / 1000.0,
                             world.executor().threads()});
      if (at_end) break;
      if (agreed(options.stop_requested && options.stop_requested())) {
        write_checkpoint_now();
        result.status = "interrupted";
        if (recorder) recorder->finish(wall_seconds());
        return result;
      }
      if (agreed(checkpoints.due(wall.elapsed_ms() / 1000.0, world.time()))) write_checkpoint_now();
    }
  } catch (const InstabilityError& e) {
    // The state before the failed step is the last good one: keep it on disk, then report. Every
    // rank is here: the stability check is global.
    write_frame(world.last_good(), world.time() - world.last_step().dt);
    result.status = "unstable";
    result.failure = e.what();
    if (recorder) recorder->finish(wall_seconds());
    if (options.throw_on_instability) throw;
    return result;
  }
  // The final state is a checkpoint too: `upf run --resume DIR --end T` extends a finished run
  // exactly as a run planned to T from the start would have gone on.
  if (options.final_checkpoint) write_checkpoint_now();
  if (recorder) recorder->finish(wall_seconds());
  return result;
}

}  // namespace upf
