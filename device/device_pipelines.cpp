#include "device/device_pipelines.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "device/backend_pipelines.h"
#include "framework/core/errors.h"
#include "framework/core/stopwatch.h"
#include "framework/world/world.h"
#include "solvers/dfsph/dfsph_solver.h"
#include "solvers/iisph/iisph_solver.h"
#include "solvers/pcisph/pcisph_solver.h"
#include "solvers/sph/sph_solver.h"
#include "solvers/wcsph/wcsph_solver.h"

namespace upf {

namespace {

constexpr const char* kCovered =
    "the device pipeline runs PCISPH, IISPH, DFSPH, WCSPH or SPH liquids with frozen walls and "
    "rigid bodies so far (no grains yet); run this scene with --device cpu";

// The world's fluid solver when the pipeline covers the scene, else an InputError saying why.
[[maybe_unused]] const Solver& covered_solver(const World& world, const std::string& where) {
  const auto& solvers = world.solvers();
  if (solvers.size() != 1 ||
      (solvers.front()->name() != "pcisph" && solvers.front()->name() != "wcsph" &&
       solvers.front()->name() != "sph" && solvers.front()->name() != "iisph" &&
       solvers.front()->name() != "dfsph")) {
    std::string names;
    for (const auto& s : solvers) names += (names.empty() ? "" : ", ") + std::string(s->name());
    throw InputError(where, "the scene's solvers are " + names + ": " + kCovered);
  }
  const Particles& p = world.particles();
  for (ParticleType t : {ParticleType::Granular})
    if (p.count(t) > 0)
      throw InputError(where,
                       "the scene has " + std::string(to_string(t)) + " particles: " + kCovered);
  return *solvers.front();
}

[[maybe_unused]] device::FluidSetup fluid_setup(const World& world, const Solver& solver,
                                                const FluidSolverState& fluid) {
  device::FluidSetup setup;
  setup.rest_density = fluid.table.rest_density;
  setup.viscosity = fluid.table.viscosity;
  setup.boundary_viscosity = fluid.table.boundary_viscosity;
  setup.owns.resize(world.materials().size());
  for (std::size_t m = 0; m < setup.owns.size(); ++m)
    setup.owns[m] = fluid.owned.owns(MaterialId(m)) ? 1 : 0;
  setup.gravity = world.settings().gravity;
  setup.support_radius = world.settings().support_radius();
  setup.reorder_every = world.settings().reorder_every;
  setup.reactions = fluid.reaction_list >= 0;
  setup.threads = world.executor().threads();
  setup.stages = solver.stages();
  return setup;
}

// The pipeline of the world's solver on the backend `Make` names.
template <class Make>
std::unique_ptr<DevicePipeline> make_for(const World& world, const Solver& solver, Make&& make) {
  if (const auto* pcisph = dynamic_cast<const PcisphSolver*>(&solver)) {
    device::PcisphSetup method;
    method.loop = pcisph->loop_settings();
    method.stop_percentile = pcisph->stop_percentile();
    method.predicted_density = PcisphSolver::kPredictedDensity;
    method.predicted_position = PcisphSolver::kPredictedPosition;
    return make(fluid_setup(world, solver, pcisph->fluid_state()), std::move(method));
  }
  if (const auto* iisph = dynamic_cast<const IisphSolver*>(&solver)) {
    device::IisphSetup method;
    method.solve = iisph->settings();
    method.stop_percentile = iisph->stop_percentile();
    return make(fluid_setup(world, solver, iisph->fluid_state()), std::move(method));
  }
  if (const auto* dfsph = dynamic_cast<const DfsphSolver*>(&solver)) {
    device::DfsphSetup method;
    method.solve = dfsph->settings();
    method.stop_percentile = dfsph->stop_percentile();
    method.density_stiffness = DfsphSolver::kDensityStiffness;
    method.divergence_stiffness = DfsphSolver::kDivergenceStiffness;
    return make(fluid_setup(world, solver, dfsph->fluid_state()), std::move(method));
  }
  if (const auto* sph = dynamic_cast<const SphSolver*>(&solver)) {
    device::SphSetup method;
    method.kernels = sph->kernel_choice(world.settings().support_radius());
    method.stiffness = sph->stiffness();
    method.mu = sph->paper_viscosity();
    return make(fluid_setup(world, solver, sph->fluid_state()), std::move(method));
  }
  const auto& wcsph = dynamic_cast<const WcsphSolver&>(solver);
  device::WcsphSetup method;
  method.tait_factor = wcsph.tait_factors();
  method.artificial_viscosity =
      wcsph.artificial_viscosity_factor(world.settings().support_radius());
  return make(fluid_setup(world, solver, wcsph.fluid_state()), std::move(method));
}

}  // namespace

std::size_t estimated_device_bytes(std::size_t particles, std::size_t liquid) {
  // Per particle: the arrays and PCISPH's fields twice (state and last good state, 67 B each),
  // the grid (57 B), the per-step buffers (44 B) and list offsets (8 B). Per liquid particle:
  // about 40 fluid and 10 boundary neighbours at h = 2 s, 4 B each; kernel gradients are
  // recomputed, not stored (FluidGradients). device_bytes() on the dam break at 28,896 liquid
  // particles (62,448 in all) measured 334 B per particle where this says 335.
  return particles * (2 * 67 + 57 + 44 + 8) + liquid * (50 * 4);
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
  if (name != "cpu") covered_solver(world, where);
}

std::unique_ptr<DevicePipeline> make_device_pipeline(std::string_view name, const World& world,
                                                     const std::string& where) {
  if (name == "cpu") return nullptr;
  if (name == "omp") {
#ifdef UPF_HAVE_DEVICE_OMP
    return make_for(world, covered_solver(world, where), [](auto fluid, auto method) {
      return device::make_omp_pipeline(std::move(fluid), std::move(method));
    });
#else
    throw InputError(where,
                     "'omp': this build has no device pipeline on OpenMP (it needs Thrust, "
                     "from the CUDA Toolkit's CCCL, at build time)");
#endif
  }
  if (name == "cuda") {
#ifdef UPF_HAVE_DEVICE_CUDA
    const Solver& solver = covered_solver(world, where);
    const std::string why = device::cuda_unavailable_reason();
    if (!why.empty()) throw InputError(where, "'cuda': no usable GPU (" + why + ")");
    // Out of memory is said before the first step, with what it would take.
    const Particles& p = world.particles();
    const std::size_t need = estimated_device_bytes(p.size(), p.count(ParticleType::Liquid));
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
    return make_for(world, solver, [](auto fluid, auto method) {
      return device::make_cuda_pipeline(std::move(fluid), std::move(method));
    });
#else
    throw InputError(where, "'cuda': this build has no CUDA pipeline (built without nvcc)");
#endif
  }
  std::string allowed;
  for (const std::string& n : device_names()) allowed += (allowed.empty() ? "" : ", ") + n;
  throw InputError(where, "'" + std::string(name) + "' is not a device (allowed: " + allowed + ")");
}

}  // namespace upf
