#include "device/device_pipelines.h"

#include "device/backend_pipelines.h"
#include "framework/core/errors.h"
#include "framework/world/world.h"
#include "solvers/pcisph/pcisph_solver.h"

namespace upf {

namespace {

constexpr const char* kCovered =
    "the device pipeline runs PCISPH liquids with frozen walls so far (no bodies, grains or other "
    "solvers); run this scene with --device cpu";

// The world's PCISPH solver when the pipeline covers the scene, else an InputError saying why.
const PcisphSolver& covered_solver(const World& world, const std::string& where) {
  const auto& solvers = world.solvers();
  if (solvers.size() != 1 || solvers.front()->name() != "pcisph") {
    std::string names;
    for (const auto& s : solvers) names += (names.empty() ? "" : ", ") + std::string(s->name());
    throw InputError(where, "the scene's solvers are " + names + ": " + kCovered);
  }
  if (!world.body_systems().empty())
    throw InputError(where, std::string("the scene has rigid bodies: ") + kCovered);
  const Particles& p = world.particles();
  for (ParticleType t : {ParticleType::Rigid, ParticleType::Granular})
    if (p.count(t) > 0)
      throw InputError(where,
                       "the scene has " + std::string(to_string(t)) + " particles: " + kCovered);
  return static_cast<const PcisphSolver&>(*solvers.front());
}

device::PcisphSetup pcisph_setup(const World& world, const PcisphSolver& solver) {
  const PcisphSolver::DeviceSetup s = solver.device_setup();
  device::PcisphSetup setup;
  setup.eta = s.params.eta;
  setup.stop_percentile = s.params.stop_percentile;
  setup.min_iterations = s.params.min_iterations;
  setup.max_iterations = s.params.max_iterations;
  setup.delta_scale = s.delta_scale;
  setup.rest_density = s.fluid->table.rest_density;
  setup.viscosity = s.fluid->table.viscosity;
  setup.boundary_viscosity = s.fluid->table.boundary_viscosity;
  setup.owns.resize(world.materials().size());
  for (std::size_t m = 0; m < setup.owns.size(); ++m)
    setup.owns[m] = s.fluid->owned.owns(MaterialId(m)) ? 1 : 0;
  setup.gravity = world.settings().gravity;
  setup.support_radius = world.settings().support_radius();
  setup.reorder_every = world.settings().reorder_every;
  setup.threads = world.executor().threads();
  setup.stages = solver.stages();
  setup.density = "density";
  setup.pressure = "pressure";
  setup.predicted_density = PcisphSolver::kPredictedDensity;
  setup.predicted_position = PcisphSolver::kPredictedPosition;
  return setup;
}

}  // namespace

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

std::unique_ptr<DevicePipeline> make_device_pipeline(std::string_view name, const World& world,
                                                     const std::string& where) {
  if (name == "cpu") return nullptr;
  if (name == "omp") {
#ifdef UPF_HAVE_DEVICE_OMP
    return device::make_omp_pcisph(pcisph_setup(world, covered_solver(world, where)));
#else
    throw InputError(where,
                     "'omp': this build has no device pipeline on OpenMP (it needs Thrust, "
                     "from the CUDA Toolkit's CCCL, at build time)");
#endif
  }
  if (name == "cuda") {
#ifdef UPF_HAVE_DEVICE_CUDA
    const PcisphSolver& solver = covered_solver(world, where);
    const std::string why = device::cuda_unavailable_reason();
    if (!why.empty()) throw InputError(where, "'cuda': no usable GPU (" + why + ")");
    return device::make_cuda_pcisph(pcisph_setup(world, solver));
#else
    throw InputError(where, "'cuda': this build has no CUDA pipeline (built without nvcc)");
#endif
  }
  std::string allowed;
  for (const std::string& n : device_names()) allowed += (allowed.empty() ? "" : ", ") + n;
  throw InputError(where, "'" + std::string(name) + "' is not a device (allowed: " + allowed + ")");
}

}  // namespace upf
