#include "framework/world/world.h"

#include "framework/core/state_stream.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "framework/boundary/akinci_volume.h"
#include "framework/boundary/slip_normal.h"
#include "framework/core/deterministic_sum.h"
#include "framework/core/errors.h"
#include "framework/core/stopwatch.h"
#include "framework/particles/kinetic_energy.h"
#include "framework/particles/particle_checks.h"
#include "framework/particles/particle_identity.h"
#include "framework/world/periodic_domain.h"

namespace upf {

World::World(WorldSettings settings, int threads)
    : settings_(settings), executor_(threads), grid_(settings.support_radius()) {}

void World::add_solver(std::unique_ptr<Solver> solver, CouplingUse use) {
  solvers_.push_back(std::move(solver));
  solver_uses_.push_back(std::move(use));
}

void World::order_solvers() {
  std::vector<DeclaredSolver> declared;
  for (std::size_t s = 0; s < solvers_.size(); ++s)
    declared.push_back({std::string(solvers_[s]->name()), solver_uses_[s]});
  const std::vector<std::size_t> order = coupling_order(declared);
  std::vector<std::unique_ptr<Solver>> solvers;
  std::vector<CouplingUse> uses;
  for (std::size_t s : order) {
    solvers.push_back(std::move(solvers_[s]));
    uses.push_back(std::move(solver_uses_[s]));
  }
  solvers_ = std::move(solvers);
  solver_uses_ = std::move(uses);
  // An array is kept only where someone reads it: the body systems read the boundary forces.
  auto read = [&](CouplingArray a) {
    if (a == CouplingArray::BoundaryForce && !bodies_.empty()) return true;
    for (const CouplingUse& u : solver_uses_)
      for (const auto* list : {&u.reads, &u.reads_if_written})
        if (std::find(list->begin(), list->end(), a) != list->end()) return true;
    return false;
  };
  for (const CouplingUse& u : solver_uses_)
    for (CouplingArray a : u.writes)
      if (read(a)) coupling_.activate(a);
}

void World::add_body_system(std::unique_ptr<BodySystem> system) {
  bodies_.push_back(std::move(system));
}

void World::add_source(std::unique_ptr<ParticleSource> source) {
  sources_.push_back(std::move(source));
}

void World::apply_sources(double dt) {
  sources_done_ = SourceChange{};
  bool any = false;
  for (const auto& s : sources_) any = any || s->may_change(time_, dt);
  if (!any) return;
  // From a device: downloaded here, and uploaded whole before the step (device_stale_), so
  // the pipeline's arrays take the new count as they take any host edit.
  Particles& p = particles();
  for (const auto& s : sources_) {
    const std::size_t before = p.size();
    const SourceChange c = s->apply(p, {time_, dt, executor_.collectives()});
    // Split over ranks, every rank runs every source alike: an emitter adds its whole layer
    // everywhere, so the id counter stays the same on every rank, and each rank keeps the new
    // particles its domain owns. Sinks take what each rank owns.
    if (domain_ && p.size() > before) {
      std::vector<std::uint8_t> elsewhere(p.size(), 0);
      for (std::size_t i = before; i < p.size(); ++i) elsewhere[i] = !domain_->owns(p.position[i]);
      p.remove(elsewhere);
    }
    sources_done_.added += c.added;  // an emitter's own count: the whole layer, on every rank
    sources_done_.removed += c.removed;
    sources_done_.mass_added += c.mass_added;
    sources_done_.mass_removed += c.mass_removed;
  }
  if (domain_) {
    sources_done_.removed = executor_.total(sources_done_.removed);
    sources_done_.mass_removed = domain_->sum_of_doubles(sources_done_.mass_removed);
  }
}

int World::request_neighbours(TypeMask query, TypeMask target, Real radius) {
  const Real support = settings_.support_radius();
  if (!(radius > 0) || radius > support) radius = support;  // the grid's cells cap the reach
  for (std::size_t i = 0; i < lists_.size(); ++i)
    if (lists_[i].query == query && lists_[i].target == target && lists_[i].radius == radius)
      return int(i);
  lists_.push_back({query, target, radius, {}});
  if (prepared_) {
    grid_.build(particles_, executor_);
    grid_.find_neighbours(particles_, query, target, radius, executor_, lists_.back().list);
  }
  return int(lists_.size() - 1);
}

void World::prepare() {
  particles_.seal_fields(false);  // a second prepare() may declare more
  order_solvers();
  if (settings_.periodic.any())
    for (const auto& s : solvers_)
      if (const std::string why = s->cannot_hold_images(); !why.empty())
        throw InputError("/periodic", "solver \"" + std::string(s->name()) + "\": " + why);
  // A periodic world holds its images as ghosts from here on, as a split world holds its
  // neighbours' particles: a wall by a periodic face sees the walls across it.
  if (settings_.periodic.any() && !domain_) {
    domain_ = std::make_unique<PeriodicDomain>(settings_.periodic, settings_.support_radius());
    domain_->distribute(particles_, coupling_);
    executor_.attach(domain_.get());
    periodic_images_only_ = true;
  }
  if (periodic_images_only_) domain_->exchange(step_count_);
  // Boundary particles keep their shape (walls stand still, a body moves as a whole), so their
  // volumes are computed once, here, each over its own body or over the walls.
  grid_.build(particles_, executor_);
  NeighbourList boundary;
  grid_.find_neighbours(particles_, kBoundaryMask, kBoundaryMask, settings_.support_radius(),
                        executor_, boundary);
  compute_boundary_volumes(particles_, kBoundaryMask, boundary, kernel(), executor_);
  const std::vector<std::uint8_t> free_slip = free_slip_materials(materials_);
  if (std::find(free_slip.begin(), free_slip.end(), 1) != free_slip.end())
    compute_slip_normals(particles_, free_slip, boundary, kernel(), executor_);
  if (periodic_images_only_) domain_->drop_ghosts();
  for (auto& b : bodies_) b->prepare(*this);

  stage_runners_.clear();
  for (auto& s : solvers_) {
    s->prepare(*this);
    stage_runners_.emplace_back(s->stages());
  }
  // Every field is declared now: a later request for an unknown name is a misspelling.
  particles_.seal_fields();
  // Before any split over ranks: what a checkpoint of this scene must hold (restore_state).
  identity_ = particle_identity(particles_);
  prepared_ = true;
  if (periodic_images_only_) domain_->exchange(step_count_);
  update_neighbours();
  for (auto& s : solvers_) s->initialize_fields(*this);
  if (periodic_images_only_) domain_->drop_ghosts();
}

double World::next_time_step() const {
  const auto& t = settings_.time;
  if (t.fixed_dt > 0) return t.fixed_dt;
  double dt = t.dt_max;
  for (const auto& s : solvers_) dt = std::min(dt, double(s->max_time_step(*this)));
  for (const auto& b : bodies_) dt = std::min(dt, b->max_time_step(*this));
  return std::clamp(dt, t.dt_min, t.dt_max);
}

double World::next_time_step_until(double end) const {
  const double remaining = end - time_;
  const double dt = next_time_step();
  if (remaining <= dt) return remaining;
  // The tolerance absorbs the rounding of the accumulated time: with a fixed dt that divides the
  // frame interval, remaining / dt lands a hair above a whole number, and without it every frame
  // would take one extra, shorter step (fixed_dt 0.002 s gave 0.0019 s).
  return remaining / std::ceil(remaining / dt - 1e-9);
}

void World::step_towards(double stop) {
  const double dt = next_time_step_until(stop);
  const bool reaches_stop = dt >= stop - time_;
  step(dt);
  if (reaches_stop) time_ = stop;
}

void World::update_neighbours() {
  grid_.build(particles_, executor_);
  // Requests that share a query set share one scan of the candidates.
  std::vector<bool> done(lists_.size(), false);
  for (std::size_t a = 0; a < lists_.size(); ++a) {
    if (done[a]) continue;
    std::vector<TypeMask> targets;
    std::vector<NeighbourList*> outs;
    for (std::size_t b = a; b < lists_.size(); ++b) {
      if (done[b] || lists_[b].query != lists_[a].query || lists_[b].radius != lists_[a].radius)
        continue;
      done[b] = true;
      targets.push_back(lists_[b].target);
      outs.push_back(&lists_[b].list);
    }
    grid_.find_neighbours(particles_, lists_[a].query, targets, lists_[a].radius, executor_, outs);
  }
}

void World::step(double dt) {
  if (!prepared_) throw std::logic_error("World::prepare() must run before World::step()");
  Stopwatch sources_watch;
  apply_sources(dt);
  sources_ms_ = sources_watch.elapsed_ms();
  if (device_) {
    step_on_device(dt);
    return;
  }
  Stopwatch total;
  particles_.snapshot_into(last_good_);

  for (auto& b : bodies_) b->place_particles(*this, dt);

  Stopwatch neighbours;
  // Reordering by the grid's (cell, id) order keeps neighbours close in memory. Lists depend on
  // positions and ids only, so the results are the same bits with or without it.
  if (domain_ && !periodic_images_only_) {
    // Across ranks: migration and ghosts instead (the exchange appends arrivals and ghosts in
    // rank order; the lists do not depend on it either).
    domain_->exchange(step_count_);
  } else {
    if (settings_.reorder_every > 0 && step_count_ % std::uint64_t(settings_.reorder_every) == 0) {
      grid_.build(particles_, executor_);
      particles_.permute(grid_.sorted_order());
    }
    // One process, periodic: the images go after the owned particles, as ghosts.
    if (domain_) domain_->exchange(step_count_);
  }
  update_neighbours();
  report_ = StepReport{};
  report_.dt = dt;
  report_.sources = sources_done_;
  if (!sources_.empty()) report_.stage_ms.emplace_back("sources", sources_ms_);
  report_.neighbour_ms = neighbours.elapsed_ms();

  coupling_.reset(particles_.size());
  for (std::size_t k = 0; k < solvers_.size(); ++k) {
    Solver& s = *solvers_[k];
    StageRunner& stages = stage_runners_[k];
    stages.clear();
    try {
      s.step(*this, Real(dt), stages);
    } catch (const ConvergenceError& e) {
      // Every rank is here: a solve's control flow follows global sums only.
      throw InstabilityError(step_count_, time_, e.what());
    }
    for (std::size_t j = 0; j < stages.names().size(); ++j)
      report_.stage_ms.emplace_back(stages.names()[j], stages.ms()[j]);
    const SolverStats st = s.stats();
    report_.solver.iterations = std::max(report_.solver.iterations, st.iterations);
    report_.solver.avg_density_error =
        std::max(report_.solver.avg_density_error, st.avg_density_error);
    report_.solver.max_density_error =
        std::max(report_.solver.max_density_error, st.max_density_error);
    report_.solver.viscosity_iterations =
        std::max(report_.solver.viscosity_iterations, st.viscosity_iterations);
  }
  Stopwatch body_watch;
  for (auto& b : bodies_) b->advance(*this, dt);
  if (!bodies_.empty()) report_.stage_ms.emplace_back("bodies", body_watch.elapsed_ms());
  if (domain_) domain_->drop_ghosts();
  time_ += dt;
  ++step_count_;
  report_.total_ms = total.elapsed_ms();
  check_stability();
}

void World::set_domain(std::unique_ptr<ParticleDomain> domain) {
  if (!prepared_) throw std::logic_error("World::prepare() must run before World::set_domain()");
  if (device_ && domain)
    throw InputError("--device",
                     "a device pipeline runs on one rank: run it without mpirun -n, or run the "
                     "ranks on the CPU");
  if (domain_ && !periodic_images_only_) throw std::logic_error("World::set_domain() may run once");
  if (domain && domain->ranks() > 1)
    for (const auto& s : solvers_)
      if (const std::string why = s->cannot_split(); !why.empty())
        throw InputError("mpirun -n " + std::to_string(domain->ranks()),
                         "solver \"" + std::string(s->name()) + "\": " + why);
  // Split over ranks, the ranks' domain holds the periodic images too; unsplit, a periodic
  // world keeps its own.
  if (!domain) return;
  periodic_images_only_ = false;
  domain_ = std::move(domain);
  domain_->distribute(particles_, coupling_);
  executor_.attach(domain_.get());
  for (auto& s : solvers_) s->split_over(*domain_);
  particles_.snapshot_into(last_good_);
}

void World::set_device(std::unique_ptr<DevicePipeline> pipeline) {
  if (!prepared_) throw std::logic_error("World::prepare() must run before World::set_device()");
  sync_host();
  device_ = std::move(pipeline);
  device_stale_ = device_ != nullptr;
  host_stale_ = false;
}

void World::sync_host() const {
  if (!device_ || !host_stale_) return;
  device_->download(particles_);
  // The solvers' own state (DEM's springs) comes with the particles: a checkpoint, or an upload
  // after a host edit, then finds the host's solvers current.
  device_->download_solver_states();
  host_stale_ = false;
}

double World::kinetic_energy() const {
  if (device_ && !device_stale_) return device_->kinetic_energy();
  const double mine =
      block_sum(executor_, particles_.owned_size(),
                KineticEnergyValue{particles_.mass.data(), particles_.velocity.data()});
  return domain_ ? domain_->sum_of_doubles(mine) : mine;
}

std::size_t World::count(ParticleType type) const {
  if (device_ && !device_stale_) return device_->count(type);
  std::size_t mine = 0;
  for (std::size_t i = 0; i < particles_.owned_size(); ++i) mine += particles_.type[i] == type;
  return executor_.total(mine);
}

void World::step_on_device(double dt) {
  Stopwatch total;
  // A host edit (particles()) since the last step goes up first. Body systems do their particle
  // work through the device (device()); one that edits particles() instead is still right, only
  // slower: it downloads, and its edit goes up again here.
  auto upload_if_stale = [&] {
    if (!device_stale_) return;
    device_->upload(particles_);
    device_stale_ = false;
  };
  upload_if_stale();
  host_stale_ = true;
  device_->save_last_good();
  for (auto& b : bodies_) b->place_particles(*this, dt);
  upload_if_stale();
  report_ = StepReport{};
  report_.dt = dt;
  report_.sources = sources_done_;
  if (!sources_.empty()) report_.stage_ms.emplace_back("sources", sources_ms_);
  try {
    device_->step(step_count_, dt, report_);
  } catch (const ConvergenceError& e) {
    sync_host();
    device_->download_last_good(last_good_);
    throw InstabilityError(step_count_, time_, e.what());
  }
  host_stale_ = true;  // also when a body system's host edit synced it earlier in this step
  Stopwatch body_watch;
  for (auto& b : bodies_) b->advance(*this, dt);
  if (!bodies_.empty()) report_.stage_ms.emplace_back("bodies", body_watch.elapsed_ms());
  upload_if_stale();
  time_ += dt;
  ++step_count_;
  report_.total_ms = total.elapsed_ms();
  check_stability_on_device();
}

void World::check_stability_on_device() {
  const std::size_t bad = device_->first_broken_particle(settings_.max_speed);
  if (bad == particles_.size()) return;
  sync_host();
  device_->download_last_good(last_good_);
  check_stability();
}

std::vector<std::string> World::stage_names() const {
  std::vector<std::string> names;
  if (!sources_.empty()) names.emplace_back("sources");  // emitters and sinks, before the step
  for (const StageRunner& r : stage_runners_)
    names.insert(names.end(), r.names().begin(), r.names().end());
  if (!bodies_.empty()) names.emplace_back("bodies");
  return names;
}

Real World::max_speed_squared(ParticleType type, const std::uint8_t* material_flags,
                              std::size_t material_count) const {
  if (device_ && !device_stale_)
    return device_->max_speed_squared(
        type, std::vector<std::uint8_t>(material_flags, material_flags + material_count));
  return executor_.max_of(
      all_particles(particles_.size()),
      SpeedSquaredOf{particles_.velocity.data(), particles_.type.data(), particles_.material.data(),
                     type, material_flags, material_count});
}

Real World::max_liquid_speed_squared() const {
  if (device_ && !device_stale_) return device_->max_liquid_speed_squared();
  return executor_.max_of(all_particles(particles_.size()),
                          LiquidSpeedSquared{particles_.velocity.data(), particles_.type.data()});
}

void World::check_stability() const {
  // The first bad particle in id order, so the report is the same for any thread count.
  const std::size_t n = particles_.size();
  const std::size_t bad =
      executor_.first_by_id(n, particles_.id.data(),
                            BrokenParticle{particles_.position.data(), particles_.velocity.data(),
                                           settings_.max_speed * settings_.max_speed});
  // What went bad: 0 nothing, 1 the position, 2 the velocity, 3 the speed; and its value.
  double what = 0, value = 0, id = 0;
  if (bad != n) {
    const Vec3& x = particles_.position[bad];
    const Vec3& v = particles_.velocity[bad];
    id = particles_.id[bad];
    what = !is_finite(x) ? 1 : !is_finite(v) ? 2 : 3;
    value = what == 1   ? double(x.x + x.y + x.z)
            : what == 2 ? double(v.x + v.y + v.z)
                        : std::sqrt(double(squared_norm(v)));
  }
  if (domain_) {
    // The smallest bad id over every rank, as on one rank; its owner supplies what went bad and
    // the value's bits (a sum where the others add zero: exact, NaN included).
    const double none = std::numeric_limits<double>::max();
    const double first = domain_->min(bad != n ? id : none);
    if (first == none) return;
    const bool mine = bad != n && id == first;
    std::int64_t report[2] = {mine ? std::int64_t(what) : 0, 0};
    if (mine) std::memcpy(&report[1], &value, sizeof(value));
    domain_->sum(report, 2);
    what = double(report[0]);
    std::memcpy(&value, &report[1], sizeof(value));
    id = first;
  } else if (bad == n) {
    return;
  }
  const auto pid = ParticleId(id);
  if (what == 1) throw InstabilityError(step_count_, time_, pid, "position (not finite)", value, 0);
  if (what == 2) throw InstabilityError(step_count_, time_, pid, "velocity (not finite)", value, 0);
  throw InstabilityError(step_count_, time_, pid, "speed [m/s]", value, settings_.max_speed);
}

void World::save_state(StateWriter& out) const {
  sync_host();
  out.section("world");
  out.put(time_);
  out.put(step_count_);
  out.put(std::uint64_t(solvers_.size()));
  out.put(std::uint64_t(bodies_.size()));
  out.put(std::uint64_t(sources_.size()));
  if (domain_) {
    // Every rank's particles, gathered on rank 0 in id order: the checkpoint of a split world is
    // a one-rank checkpoint, and resumes on any number of ranks. (The other ranks' bytes are
    // not written.)
    Particles whole;
    domain_->gather(particles_, whole);
    whole.save_state(out);
  } else {
    particles_.save_state(out);
  }
  for (const auto& s : solvers_) {
    out.section(s->name());
    s->save_state(out);
  }
  for (const auto& b : bodies_) {
    out.section(b->name());
    b->save_state(out);
  }
  for (const auto& s : sources_) {
    out.section(s->name());
    s->save_state(out);
  }
}

void World::restore_state(StateReader& in) {
  if (!prepared_) throw std::logic_error("World::prepare() must run before restore_state()");
  in.section("world");
  time_ = in.get<double>();
  step_count_ = in.get<std::uint64_t>();
  in.expect(in.get<std::uint64_t>() == solvers_.size(), "the number of solvers");
  in.expect(in.get<std::uint64_t>() == bodies_.size(), "the number of body systems");
  in.expect(in.get<std::uint64_t>() == sources_.size(), "the number of emitters and sinks");
  // Read into a copy and checked before the world takes it: a checkpoint is validated, not
  // trusted (its checksum only proves it was not damaged by accident).
  Particles restored = particles_;
  restored.restore_state(in);
  std::vector<ParticleType> material_types;
  for (const Material& m : materials_.all()) material_types.push_back(m.type);
  if (auto problem = particle_array_problem(restored, material_types)) in.fail(*problem);
  in.expect(particle_identity(restored) == identity_,
            "the walls, bodies and grains (their ids, types, materials and bodies)");
  particles_.swap_values(restored);
  // A checkpoint holds the whole world: a split world takes its share again.
  if (domain_) domain_->distribute(particles_, coupling_);
  for (const auto& s : solvers_) {
    in.section(s->name());
    s->restore_state(in);
  }
  for (const auto& b : bodies_) {
    in.section(b->name());
    b->restore_state(in);
  }
  for (const auto& s : sources_) {
    in.section(s->name());
    s->restore_state(in);
  }
  particles_.snapshot_into(last_good_);
  device_stale_ = device_ != nullptr;
  host_stale_ = false;
}

}  // namespace upf
