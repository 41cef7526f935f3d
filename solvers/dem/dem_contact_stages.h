// Building DEM's candidate contacts (dem_contact_list.h) as plain particle stages, so that the
// CPU executor and a device pipeline build the same list with the same bits: a count per grain,
// a scan into offsets (exact: integers), a fill in the same order, the springs carried over by
// the pair's stable key, and the reverse index counted and filled the same way. No atomics; each
// stage writes only its own particle's slots. C++17 and UPF_HD.
#pragma once

#include <cstdint>

#include "framework/core/vec3.h"
#include "framework/neighbours/neighbour_list.h"
#include "framework/particles/particles.h"
#include "framework/world/container_box.h"
#include "solvers/dem/dem_views.h"
#include "solvers/fluid/owned_particles.h"

namespace upf {

// Wall faces have keys too: container c, face f (0..5) gets a key above every particle id.
UPF_HD constexpr std::uint32_t dem_wall_key(std::size_t container, int face) {
  return 0xFFFFFFFFu - std::uint32_t(container * 6 + std::size_t(face));
}

// What the candidates of a grain are made from.
struct DemCandidateSources {
  const Vec3* x;
  const ParticleType* type;
  const MaterialId* material;
  const ParticleId* id;
  const BodyId* body;
  const Real* radius;         // grain radius by particle
  OwnedMaterials owns;        // the solver's grains
  NeighbourView grains;       // owned grains -> grains and boundary particles
  NeighbourView reactions;    // rigid boundary particles -> grains; null offsets: none
  const ContainerBox* boxes;  // the containers' inner boxes
  std::uint32_t box_count;
  Real skin;  // m, how far beyond contact the candidates reach
  // Particles from here on are ghosts (another rank's, particle_domain.h); one rank: the size.
  std::uint32_t owned_end;

  // Whether grain i holds the pair with neighbour j: the grain with the lower id holds a pair of
  // the solver's grains, a grain holds every pair with another solver's grain or with a body's
  // boundary particle (walls are exact planes, not particles).
  UPF_HD bool holds(std::uint32_t i, std::uint32_t j) const {
    if (type[j] == ParticleType::Granular) return id[j] > id[i] || !owns(material[j]);
    return body[j] != kNoBody;
  }

  // emit(partner, key) for each candidate of grain i: container faces first (container and face
  // order), then the neighbours it holds, in neighbour-list order. A ghost grain holds only its
  // pairs with this rank's own particles: the rank computes them too, in the same operand order
  // and with the same spring as the ghost's owner, so its particles gather the same reactions.
  template <class Emit>
  UPF_HD void for_each_candidate(std::uint32_t i, Emit& emit) const {
    const bool ghost = i >= owned_end;
    const Vec3 xi = x[i];
    const Real reach = radius[i] + skin;
    const std::uint32_t boxes_near = ghost ? 0u : box_count;  // a ghost's walls are its owner's
    for (std::uint32_t b = 0; b < boxes_near; ++b) {
      const ContainerBox& box = boxes[b];
      bool near = true;
      for (int a = 0; a < 3; ++a)
        near = near && xi[a] > box.min[a] - reach && xi[a] < box.max[a] + reach;
      if (!near) continue;
      for (int face = 0; face < 6; ++face) {
        const int a = face / 2;
        const Real gap = face % 2 == 0 ? xi[a] - box.min[a] : box.max[a] - xi[a];
        if (gap < reach)
          emit(kDemWallPartner | (b * 6 + std::uint32_t(face)), dem_wall_key(b, face));
      }
    }
    for (std::uint32_t k = grains.offsets[i]; k < grains.offsets[i + 1]; ++k) {
      const std::uint32_t j = grains.indices[k];
      if (holds(i, j) && !(ghost && j >= owned_end)) emit(j, std::uint32_t(id[j]));
    }
  }
};

namespace dem_detail {
struct CountEmit {
  std::uint32_t count = 0;
  UPF_HD void operator()(std::uint32_t, std::uint32_t) { ++count; }
};
struct FillEmit {
  std::uint32_t* partner;
  std::uint32_t* key;
  std::uint32_t k;
  UPF_HD void operator()(std::uint32_t p, std::uint32_t q) {
    partner[k] = p;
    key[k] = q;
    ++k;
  }
};
}  // namespace dem_detail

// counts[i + 1] = grain i's candidates (counts[0] and non-grains stay as they are: zero).
struct DemCountCandidatesStage {
  DemCandidateSources s;
  std::uint32_t* counts;
  UPF_HD void operator()(std::uint32_t i) const {
    dem_detail::CountEmit emit;
    s.for_each_candidate(i, emit);
    counts[i + 1] = emit.count;
  }
};

// Grain i's candidates into [offsets[i], offsets[i + 1]), springs zeroed, none touching.
struct DemFillCandidatesStage {
  DemCandidateSources s;
  const std::uint32_t* offsets;
  std::uint32_t* partner;
  std::uint32_t* key;
  Vec3* xi;
  std::uint8_t* touching;
  UPF_HD void operator()(std::uint32_t i) const {
    dem_detail::FillEmit emit{partner, key, offsets[i]};
    s.for_each_candidate(i, emit);
    for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k) {
      xi[k] = Vec3{};
      touching[k] = 0;
    }
  }
};

// Grain i's springs from the last step's candidates of the same grain (found by its stable id)
// with the same key.
struct DemCarrySpringsStage {
  const ParticleId* id;
  const std::uint32_t* offsets;
  const std::uint32_t* key;
  Vec3* xi;
  const std::uint32_t* last_begin_by_id;
  const std::uint32_t* last_count_by_id;
  std::uint32_t id_count;  // entries of the last step's by-id arrays
  const std::uint32_t* last_key;
  const Vec3* last_xi;
  UPF_HD void operator()(std::uint32_t i) const {
    const ParticleId me = id[i];
    if (me >= id_count || last_count_by_id[me] == 0) return;
    const std::uint32_t first = last_begin_by_id[me], last = first + last_count_by_id[me];
    for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k)
      for (std::uint32_t o = first; o < last; ++o)
        if (last_key[o] == key[k]) {
          xi[k] = last_xi[o];
          break;
        }
  }
};

// Where grain i's candidates are, by its stable id, for the next step's carry-over.
struct DemRecordByIdStage {
  const ParticleId* id;
  const std::uint32_t* offsets;
  std::uint32_t* begin_by_id;
  std::uint32_t* count_by_id;
  UPF_HD void operator()(std::uint32_t i) const {
    begin_by_id[id[i]] = offsets[i];
    count_by_id[id[i]] = offsets[i + 1] - offsets[i];
  }
};

// The candidates whose partner is particle j (a grain of the solver with a lower-id holder, or a
// rigid boundary particle), in the order of j's own neighbour list: count, then fill.
struct DemReverseCandidates {
  DemCandidateSources s;
  const std::uint32_t* offsets;
  const std::uint32_t* partner;

  template <class Emit>
  UPF_HD void for_each(std::uint32_t j, Emit& emit) const {
    NeighbourView list{nullptr, nullptr};
    if (s.type[j] == ParticleType::Granular && s.owns(s.material[j]))
      list = s.grains;
    else if (s.type[j] == ParticleType::Rigid && s.reactions.offsets)
      list = s.reactions;
    if (!list.offsets) return;
    for (std::uint32_t r = list.offsets[j]; r < list.offsets[j + 1]; ++r) {
      const std::uint32_t i = list.indices[r];
      if (s.type[i] != ParticleType::Granular || !s.owns(s.material[i])) continue;
      for (std::uint32_t k = offsets[i]; k < offsets[i + 1]; ++k)
        if (partner[k] == j) {
          emit(k);
          break;
        }
    }
  }
};

namespace dem_detail {
struct CountOne {
  std::uint32_t count = 0;
  UPF_HD void operator()(std::uint32_t) { ++count; }
};
struct FillOne {
  std::uint32_t* out;
  std::uint32_t r;
  UPF_HD void operator()(std::uint32_t k) { out[r++] = k; }
};
}  // namespace dem_detail

struct DemCountReverseStage {
  DemReverseCandidates reverse;
  std::uint32_t* counts;  // counts[j + 1]
  UPF_HD void operator()(std::uint32_t j) const {
    dem_detail::CountOne emit;
    reverse.for_each(j, emit);
    counts[j + 1] = emit.count;
  }
};

struct DemFillReverseStage {
  DemReverseCandidates reverse;
  const std::uint32_t* reverse_offsets;
  std::uint32_t* out;
  UPF_HD void operator()(std::uint32_t j) const {
    dem_detail::FillOne emit{out, reverse_offsets[j]};
    reverse.for_each(j, emit);
  }
};

}  // namespace upf
