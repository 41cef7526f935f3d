// Plain views of the DEM's tables for its particle stages (dem_stages.h): the pair constants and
// the candidate contacts with their springs (dem_contact_list.h). C++17 and UPF_HD.
#pragma once

#include <cstddef>
#include <cstdint>

#include "framework/core/vec3.h"
#include "framework/particles/particles.h"
#include "solvers/dem/dem_contact.h"

namespace upf {

// Partner of a container-face candidate: this flag with container * 6 + face.
inline constexpr std::uint32_t kDemWallPartner = 0x80000000u;

// Pair constants by material (DemPairs).
struct DemPairTable {
  const DemPairParams* pairs = nullptr;     // n x n
  const DemPairParams* walls = nullptr;     // by material
  const DemPairParams* boundary = nullptr;  // by material, against boundary particles
  std::size_t n = 0;
  Real boundary_radius = 0;
  UPF_HD const DemPairParams& pair(MaterialId a, MaterialId b) const { return pairs[a * n + b]; }
};

// The candidates of this world step (DemContactList). Only a candidate's holder writes it.
struct DemContactView {
  const std::uint32_t* offsets = nullptr;  // by particle: its candidates [offsets[i], offsets[i+1])
  const std::uint32_t* partner = nullptr;
  Vec3* xi = nullptr;
  Vec3* force = nullptr;
  Vec3* partner_torque = nullptr;
  Vec3* partner_rolling = nullptr;
  std::uint8_t* touching = nullptr;
  const std::uint32_t* reverse_offsets = nullptr;  // by particle: candidates it is partner of
  const std::uint32_t* reverse = nullptr;

  // Candidate k touches this sub-step: its new spring, the force on the holder and the torque on
  // the partner (contact and rolling parts).
  UPF_HD void touch(std::uint32_t k, const Vec3& new_xi, const Vec3& f, const Vec3& torque,
                    const Vec3& rolling) const {
    xi[k] = new_xi;
    force[k] = f;
    partner_torque[k] = torque;
    partner_rolling[k] = rolling;
    touching[k] = 1;
  }
  // Candidate k is apart this sub-step: its spring is gone.
  UPF_HD void separate(std::uint32_t k) const {
    xi[k] = Vec3{};
    touching[k] = 0;
  }
};

}  // namespace upf
