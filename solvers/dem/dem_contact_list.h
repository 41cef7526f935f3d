// The candidate contacts of one world step and their tangential springs, in the layout of
// LAMMPS's granular pair styles (the "shear history" kept alongside the neighbour list): each
// grain's candidates (partners within contact reach plus the lists' skin, and the container faces
// as near) lie in one contiguous run, and each candidate carries its own spring xi, so a
// sub-step reads and writes history by position, with no search.
//
// A pair of grains is one candidate, held by the grain with the lower id (or by both when the
// partner belongs to another solver); the partner reads the pair's force back through the
// reverse index, as a rigid body's boundary particle does. Only the holder writes a candidate,
// so one buffer suffices and no thread sees another's half-written state.
//
// The list is rebuilt every world step from the neighbour lists. Springs carry over by the
// stable (grain id, partner key) of their pair, so reordering the particles loses nothing.
// Sum orders follow the neighbour lists, which depend on positions and ids only: results do not
// depend on memory order or thread count.
//
// Split over MPI ranks, a pair across a domain face is computed on both ranks: a ghost grain
// holds its pairs with the rank's own particles (dem_contact_stages.h), so every rank computes
// what its own particles gather, in the one-rank operand order. The springs follow the particles
// that migrate (follow_migration): whichever ranks compute a pair next step find its spring. The
// building passes are the plain stages of dem_contact_stages.h, so a device pipeline can build the
// same list.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/state_stream.h"
#include "framework/core/vec3.h"
#include "framework/executors/cpu/cpu_executor.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"
#include "framework/world/container_box.h"
#include "framework/world/particle_domain.h"
#include "solvers/dem/dem_contact_stages.h"
#include "solvers/dem/dem_spring_state.h"
#include "solvers/dem/dem_views.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

class DemContactList {
 public:
  struct Sources {
    const NeighbourList* grains = nullptr;     // owned grains -> grains and boundary particles
    const NeighbourList* reactions = nullptr;  // rigid boundary particles -> grains, or null
    const std::vector<ContainerBox>* boxes = nullptr;
    const Real* radius = nullptr;  // grain radius by particle
    Real skin = 0;                 // m, how far beyond contact the candidates reach
  };

  // Forgets every spring (a new world).
  void clear();
  // The candidates of this world step, held by `holders` (the solver's grains, then its ghost
  // grains on a split world); springs carry over from the last.
  void rebuild(const Particles& particles, const OwnedParticles& owned, ParticleRange holders,
               const Sources& sources, const CpuExecutor& exec);
  // A split world just moved particles (ParticleDomain::departed): the springs of every pair
  // that one of them is in go after it, so that the ranks computing the pair next find them.
  // Every rank calls it, before rebuild.
  void follow_migration(const ParticleDomain& domain);

  // Candidates of particle i: [begin(i), end(i)).
  std::uint32_t begin(std::size_t i) const { return offsets_[i]; }
  std::uint32_t end(std::size_t i) const { return offsets_[i + 1]; }
  std::uint32_t partner(std::uint32_t k) const { return partner_[k]; }
  std::uint32_t key(std::uint32_t k) const { return key_[k]; }
  const Vec3& xi(std::uint32_t k) const { return xi_[k]; }

  // Records candidate k as touching this sub-step: its new spring, the force on the holder and
  // the torque on the partner (contact and rolling parts).
  void touch(std::uint32_t k, const Vec3& xi, const Vec3& force, const Vec3& partner_torque,
             const Vec3& partner_rolling) {
    xi_[k] = xi;
    force_[k] = force;
    partner_torque_[k] = partner_torque;
    partner_rolling_[k] = partner_rolling;
    touching_[k] = 1;
  }
  // Candidate k is apart this sub-step: its spring is gone.
  void separate(std::uint32_t k) {
    xi_[k] = Vec3{};
    touching_[k] = 0;
  }

  // Candidates whose partner is particle j (a grain with the higher id, or a rigid boundary
  // particle), in the order of j's own neighbour list: [reverse_begin(j), reverse_end(j)) index
  // reverse_pair().
  std::uint32_t reverse_begin(std::size_t j) const { return reverse_offsets_[j]; }
  std::uint32_t reverse_end(std::size_t j) const { return reverse_offsets_[j + 1]; }
  std::uint32_t reverse_pair(std::uint32_t r) const { return reverse_[r]; }
  bool touching(std::uint32_t k) const { return touching_[k] != 0; }
  const Vec3& force(std::uint32_t k) const { return force_[k]; }
  const Vec3& partner_torque(std::uint32_t k) const { return partner_torque_[k]; }
  const Vec3& partner_rolling(std::uint32_t k) const { return partner_rolling_[k]; }

  std::size_t size() const { return partner_.size(); }
  // The view the DEM's stages hold.
  DemContactView view() {
    return {offsets_.data(),  partner_.data(),         xi_.data(),
            force_.data(),    partner_torque_.data(),  partner_rolling_.data(),
            touching_.data(), reverse_offsets_.data(), reverse_.data()};
  }

  // Checkpoints: the springs and whose they are (the candidates are listed again next step).
  void save_state(StateWriter& out) const;
  // The same for a split world, on every rank: the springs of all ranks, merged. A checkpoint
  // holds the whole world and resumes on any rank count.
  void save_gathered(StateWriter& out, const ParticleDomain& domain) const;
  void restore_state(StateReader& in);
  // The same state as plain vectors (`primed` is the solver's): for a device pipeline.
  void springs_into(DemSpringState& state) const;
  void set_springs(const DemSpringState& state);

 private:
  void carry_springs(const Particles& particles, ParticleRange holders, const CpuExecutor& exec);
  // The springs carried to the next step, as (holder id, key, spring) records, and back.
  std::vector<DemSpringRecord> records() const;
  void set_records(std::vector<DemSpringRecord> records);
  void build_reverse(const DemCandidateSources& sources, std::size_t n, const CpuExecutor& exec);

  std::vector<std::uint32_t> offsets_;  // by particle, size() + 1
  std::vector<std::uint32_t> partner_, key_;
  std::vector<Vec3> xi_, force_, partner_torque_, partner_rolling_;
  std::vector<std::uint8_t> touching_;
  std::vector<std::uint32_t> reverse_offsets_, reverse_;
  // The last step's springs, found by the holder's id: its candidates' keys and springs.
  std::vector<std::uint32_t> last_begin_by_id_, last_count_by_id_;
  std::vector<std::uint32_t> last_key_;
  std::vector<Vec3> last_xi_;
};

}  // namespace upf
