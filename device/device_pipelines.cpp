#include "device/device_pipelines.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "device/backend_pipelines.h"
#include "framework/core/errors.h"
#include "framework/core/stopwatch.h"
#include "framework/world/world.h"
#include "solvers/dem/dem_solver.h"
#include "solvers/dfsph/dfsph_solver.h"
#include "solvers/iisph/iisph_solver.h"
#include "solvers/pcisph/pcisph_solver.h"
#include "solvers/sph/sph_solver.h"
#include "solvers/wcsph/wcsph_solver.h"

namespace upf {

namespace {

constexpr const char* kCovered =
    "the device pipeline runs the PCISPH, IISPH, DFSPH, WCSPH, SPH and DEM solvers with frozen "
    "walls and bodies; run this scene with --device cpu";

bool is_covered(const Solver& s) {
  return dynamic_cast<const PcisphSolver*>(&s) || dynamic_cast<const IisphSolver*>(&s) ||
         dynamic_cast<const DfsphSolver*>(&s) || dynamic_cast<const SphSolver*>(&s) ||
         dynamic_cast<const WcsphSolver*>(&s) || dynamic_cast<const DemSolver*>(&s);
}

// Throws an InputError naming the first solver the pipeline does not run.
void check_covered(const World& world, const std::string& where) {
  for (const auto& s : world.solvers())
    if (!is_covered(*s))
      throw InputError(where, "the scene's solver '" + std::string(s->name()) +
                                  "' has no device "
                                  "part: " +
                                  kCovered);
  // Periodic images on the device are the fluids' (device_images.h); scenes refuse grains and
  // bodies in a periodic domain anyway (periodic_keys.cpp).
  if (!world.settings().periodic.any()) return;
  for (const auto& s : world.solvers())
    if (dynamic_cast<const DemSolver*>(s.get()))
      throw InputError(where,
                       "a periodic world on the device pipeline holds liquids and walls "
                       "only; its solver '" +
                           std::string(s->name()) + "' moves grains");
  if (!world.body_systems().empty())
    throw InputError(where,
                     "a periodic world on the device pipeline holds liquids and walls "
                     "only, no bodies");
}

[[maybe_unused]] device::FluidSetup fluid_setup(const World& world, const Solver& solver,
                                                const FluidSolverState& fluid) {
  device::FluidSetup setup;
  setup.rest_density = fluid.table.rest_density;
  setup.viscosity = fluid.table.viscosity;
  setup.boundary_viscosity = fluid.table.boundary_viscosity;
  setup.viscosity_factor = Real(fluid.table.viscosity_operator.laplacian_factor);
  setup.surface_model = fluid.table.surface_model;
  setup.cohesion = fluid.table.cohesion;
  setup.adhesion = fluid.table.adhesion;
  setup.has_adhesion = fluid.table.has_adhesion;
  setup.implicit_viscosity = fluid.implicit_viscosity();
  setup.viscosity_solve = {fluid.table.viscosity_tolerance, fluid.table.viscosity_max_iterations};
  setup.owns.resize(world.materials().size());
  for (std::size_t m = 0; m < setup.owns.size(); ++m)
    setup.owns[m] = fluid.owned.owns(MaterialId(m)) ? 1 : 0;
  setup.reaction_query = fluid.reaction_query;
  setup.wall_friction = fluid.wall_list >= 0;
  setup.wall_pressure = fluid.wall_pressure;
  setup.density_contrast = fluid.table.density_contrast;
  setup.stages = solver.stages();
  return setup;
}

// The setup of one covered solver.
[[maybe_unused]] device::SolverSetup solver_setup(const World& world, Solver& solver) {
  if (auto* dem = dynamic_cast<DemSolver*>(&solver)) {
    device::DemSolverSetup setup;
    setup.step = dem->step_setup(world);
    setup.stages = dem->stages();
    setup.load_springs = [dem] { return dem->spring_state(); };
    setup.store_springs = [dem](const DemSpringState& s) { dem->set_spring_state(s); };
    return setup;
  }
  if (const auto* pcisph = dynamic_cast<const PcisphSolver*>(&solver)) {
    device::PcisphSetup method;
    method.loop = pcisph->loop_settings();
    method.stop_percentile = pcisph->stop_percentile();
    method.predicted_density = PcisphSolver::kPredictedDensity;
    method.predicted_position = PcisphSolver::kPredictedPosition;
    method.scaled_pressure = PcisphSolver::kScaledPressure;
    return device::FluidSolverSetup{fluid_setup(world, solver, pcisph->fluid_state()), method};
  }
  if (const auto* iisph = dynamic_cast<const IisphSolver*>(&solver)) {
    device::IisphSetup method;
    method.solve = iisph->settings();
    method.stop_percentile = iisph->stop_percentile();
    return device::FluidSolverSetup{fluid_setup(world, solver, iisph->fluid_state()), method};
  }
  if (const auto* dfsph = dynamic_cast<const DfsphSolver*>(&solver)) {
    device::DfsphSetup method;
    method.solve = dfsph->settings();
    method.stop_percentile = dfsph->stop_percentile();
    method.density_stiffness = DfsphSolver::kDensityStiffness;
    method.divergence_stiffness = DfsphSolver::kDivergenceStiffness;
    return device::FluidSolverSetup{fluid_setup(world, solver, dfsph->fluid_state()), method};
  }
  if (const auto* sph = dynamic_cast<const SphSolver*>(&solver)) {
    device::SphSetup method;
    method.kernels = sph->kernel_choice(world.settings().support_radius());
    method.stiffness = sph->stiffness();
    method.mu = sph->paper_viscosity();
    return device::FluidSolverSetup{fluid_setup(world, solver, sph->fluid_state()), method};
  }
  const auto& wcsph = dynamic_cast<const WcsphSolver&>(solver);
  device::WcsphSetup method;
  method.tait_factor = wcsph.tait_factors();
  method.artificial_viscosity =
      wcsph.artificial_viscosity_factor(world.settings().support_radius());
  return device::FluidSolverSetup{fluid_setup(world, solver, wcsph.fluid_state()), method};
}

// The setup of a world whose solvers are all covered (check_covered), in its stepping order.
[[maybe_unused]] device::PipelineSetup pipeline_setup(const World& world) {
  device::PipelineSetup setup;
  setup.world.gravity = world.settings().gravity;
  setup.world.support_radius = world.settings().support_radius();
  setup.world.reorder_every = world.settings().reorder_every;
  setup.world.threads = world.executor().threads();
  setup.world.boundary_force = world.coupling().active(CouplingArray::BoundaryForce);
  setup.world.liquid_force = world.coupling().active(CouplingArray::LiquidForce);
  setup.world.periodic = world.settings().periodic;
  for (const auto& s : world.solvers()) setup.solvers.push_back(solver_setup(world, *s));
  return setup;
}

}  // namespace

std::size_t estimated_device_bytes(const World& world) {
  // The particles' arrays and fields twice (the state and the last good state), as large as the
  // host's. Per particle besides: the grid (62 B), each active coupling array (12 B), the fluid
  // solvers' step buffers (40 B) and, with bodies, their per-particle buffers (70 B). Per
  // neighbour list: offsets and entries, 4 B each, as many as the world's own lists hold (built by
  // prepare() with the device's requests; kernel gradients are recomputed, not stored). Per
  // grain: the contact list and the step's buffers, about 1,500 B at a grain diameter of 0.6
  // spacings (samples/sand_into_water.json). docs/device.md compares it with device_bytes().
  const Particles& p = world.particles();
  const std::size_t n = p.size();
  std::size_t arrays = 0;
  Particles::for_each_builtin([&](const auto& a) { arrays += a.size() * sizeof(a[0]); }, p);
  for (const auto& [name, f] : p.scalar_fields()) arrays += f.values.size() * sizeof(Real);
  for (const auto& [name, f] : p.vector_fields()) arrays += f.values.size() * sizeof(Vec3);
  std::size_t per_particle = 62;
  for (CouplingArray a : {CouplingArray::BoundaryForce, CouplingArray::LiquidForce})
    per_particle += world.coupling().active(a) ? 12 : 0;
  per_particle += p.count(ParticleType::Liquid) > 0 ? 40 : 0;
  per_particle += world.body_systems().empty() ? 0 : 70;
  std::size_t lists = 0;
  for (int h = 0; h < world.neighbour_list_count(); ++h)
    lists += 4 * (n + 1 + world.neighbours(h).total());
  const std::size_t estimate =
      2 * arrays + n * per_particle + lists + p.count(ParticleType::Granular) * 1500;
  // device_bytes() / this, before the margin: 1.11 (the dam break), 1.06 (floating objects), 0.97
  // (sand into water), 0.67 (the sand pile, whose grains are larger); the margin keeps a refusal
  // on the safe side.
  return estimate / 100 * 115;
}

double copy_bandwidth_gbps(std::string_view device, std::size_t bytes) {
#ifdef UPF_HAVE_DEVICE_CUDA
  if (device == "cuda") return device::cuda_copy_bandwidth_gbps(bytes);
#endif
  if (device == "cuda") return 0;
  std::vector<char> from(bytes, 1), to(bytes, 0);
  std::vector<double> ms;
  for (int k = 0; k < 7; ++k) {
    const Stopwatch watch;
    std::memcpy(to.data(), from.data(), bytes);
    if (k >= 2) ms.push_back(watch.elapsed_ms());
  }
  std::sort(ms.begin(), ms.end());
  return 2.0 * double(bytes) / (ms[ms.size() / 2] * 1e-3) / 1e9;
}

std::vector<std::string> device_names() {
  std::vector<std::string> names{"cpu"};
#ifdef UPF_HAVE_DEVICE_OMP
  names.emplace_back("omp");
#endif
#ifdef UPF_HAVE_DEVICE_CUDA
  names.emplace_back("cuda");
#endif
  return names;
}

void check_device(std::string_view name, const World& world, const std::string& where) {
  const std::vector<std::string> names = device_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    if (name == "omp" || name == "cuda") make_device_pipeline(name, world, where);  // says why
    std::string allowed;
    for (const std::string& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
    throw InputError(where,
                     "'" + std::string(name) + "' is not a device (allowed: " + allowed + ")");
  }
  if (name != "cpu") check_covered(world, where);
}

std::unique_ptr<DevicePipeline> make_device_pipeline(std::string_view name, const World& world,
                                                     const std::string& where) {
  if (name == "cpu") return nullptr;
  if (name == "omp") {
#ifdef UPF_HAVE_DEVICE_OMP
    check_covered(world, where);
    return device::make_omp_pipeline(pipeline_setup(world));
#else
    throw InputError(where,
                     "'omp': this build has no device pipeline on OpenMP (it needs Thrust, "
                     "from the CUDA Toolkit's CCCL, at build time)");
#endif
  }
  if (name == "cuda") {
#ifdef UPF_HAVE_DEVICE_CUDA
    check_covered(world, where);
    const std::string why = device::cuda_unavailable_reason();
    if (!why.empty()) throw InputError(where, "'cuda': no usable GPU (" + why + ")");
    // Out of memory is said before the first step, with what it would take.
    const Particles& p = world.particles();
    const std::size_t need = estimated_device_bytes(world);
    std::size_t free = 0, total = 0;
    device::cuda_memory(free, total);
    if (need > free) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "'cuda': %zu particles need about %.2f GiB of device memory; the GPU has "
                    "%.2f GiB free of %.2f GiB",
                    p.size(), double(need) / 1073741824.0, double(free) / 1073741824.0,
                    double(total) / 1073741824.0);
      throw InputError(where, text);
    }
    return device::make_cuda_pipeline(pipeline_setup(world));
#else
    throw InputError(where, "'cuda': this build has no CUDA pipeline (built without nvcc)");
#endif
  }
  std::string allowed;
  for (const std::string& n : device_names()) allowed += (allowed.empty() ? "" : ", ") + n;
  throw InputError(where, "'" + std::string(name) + "' is not a device (allowed: " + allowed + ")");
}

}  // namespace upf
