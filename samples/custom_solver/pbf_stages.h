// The per-particle stages of the PBF solver (pbf_solver.h), built on pbf_kernels.h: plain structs
// of views with a UPF_HD operator()(i) that writes only particle i. C++17: nvcc compiles them
// (pbf_cuda_check.cu).
#pragma once

#include "pbf_kernels.h"
#include "solvers/fluid/fluid_view.h"
#include "solvers/fluid/owned_particles.h"

namespace upf::pbf {

// v = v + a_other dt, the displacement v dt and x* = x + v dt (algorithm 1, lines 2-3).
struct PbfPredictStage {
  FluidView f;
  const Vec3* a_other;
  Real dt;
  Vec3* displacement;
  Vec3* xs;
  UPF_HD void operator()(std::uint32_t i) const {
    const Vec3 v = f.v[i] + a_other[i] * dt;
    displacement[i] = v * dt;
    xs[i] = f.x[i] + displacement[i];
  }
};

// PBF has no pressure term of its own at the step's start: the corrections add their reactions.
struct NoPressureFactor {
  static constexpr bool kPerDensitySquared = true;  // (a wall pressure would average it)
  UPF_HD Real operator()(std::uint32_t) const { return 0; }
};

struct ZeroScalarStage {
  Real* values;
  UPF_HD void operator()(std::uint32_t i) const { values[i] = 0; }
};

// lambda_i (eq. 11) and the pressure it stands for, p -= rho0 lambda / dt^2 summed over iterations.
struct PbfLambdaStage {
  FluidView f;
  const Vec3* xs;
  PbfConstants constants;
  PbfPairTerms terms;
  Real inv_dt2;
  Real* lambda;
  Real* pressure;
  UPF_HD void operator()(std::uint32_t i) const {
    lambda[i] = pbf_lambda(f, xs, constants, terms, i);
    pressure[i] -= f.rest_density[f.material[i]] * lambda[i] * inv_dt2;
  }
};

// The reaction of one iteration's boundary corrections on body particle b:
//   F_b = -sum_i m_i lambda_i V_b grad W(x*_i - x*_b) / dt^2.
struct PbfCorrectionReactionStage {
  FluidView f;
  NeighbourView fluid_of_body;
  OwnedMaterials owns;
  const Vec3* xs;
  const Real* lambda;
  Real inv_dt2;
  Vec3* force;
  UPF_HD void operator()(std::uint32_t b) const {
    const std::uint32_t begin = fluid_of_body.offsets[b];
    const std::uint32_t end = fluid_of_body.offsets[b + 1];
    if (begin == end) return;
    Vec3 sum{};
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t i = fluid_of_body.indices[k];
      if (!owns(f.material[i])) continue;
      sum -= f.kernel.gradient(xs[i] - xs[b]) * (f.mass[i] * lambda[i]);
    }
    force[b] += sum * (f.boundary_volume[b] * inv_dt2);
  }
};

// dx_i (eq. 12, 14).
struct PbfCorrectionStage {
  FluidView f;
  const Real* lambda;
  PbfPairTerms terms;
  Vec3* dx;
  UPF_HD void operator()(std::uint32_t i) const {
    dx[i] = pbf_position_correction(f, lambda, terms, i);
  }
};

// x* += dx, and the step's displacement with it.
struct PbfApplyCorrectionStage {
  const Vec3* dx;
  Vec3* xs;
  Vec3* displacement;
  UPF_HD void operator()(std::uint32_t i) const {
    xs[i] += dx[i];
    displacement[i] += dx[i];
  }
};

// v = displacement / dt, x = x* (algorithm 1, lines 21-23).
struct PbfTakePredictionStage {
  const Vec3* xs;
  const Vec3* displacement;
  Real dt;
  Vec3* x;
  Vec3* v;
  UPF_HD void operator()(std::uint32_t i) const {
    v[i] = displacement[i] / dt;
    x[i] = xs[i];
  }
};

// XSPH viscosity and the vorticity (eq. 15, 17), into scratch fields.
struct PbfVelocityTermsStage {
  FluidView f;
  Real xsph;
  Vec3* v_new;
  Vec3* omega;
  UPF_HD void operator()(std::uint32_t i) const {
    const PbfVelocityTerms t = pbf_velocity_terms(f, xsph, i);
    v_new[i] = t.xsph;
    omega[i] = t.omega;
  }
};

// Vorticity confinement (eq. 16).
struct PbfVorticityStage {
  FluidView f;
  const Vec3* omega;
  Real epsilon;
  Real dt;
  Vec3* v_new;
  UPF_HD void operator()(std::uint32_t i) const {
    v_new[i] += pbf_vorticity_acceleration(f, omega, epsilon, i) * dt;
  }
};

struct CopyVectorStage {
  const Vec3* from;
  Vec3* to;
  UPF_HD void operator()(std::uint32_t i) const { to[i] = from[i]; }
};

}  // namespace upf::pbf
