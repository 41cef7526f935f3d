// What the DEM's contact list carries from one world step to the next (dem_contact_list.h): the
// candidates' stable keys and tangential springs, where each grain's run of them lies by grain
// id, and whether the forces of the current positions were computed yet. Plain vectors, so a
// device pipeline can take the state over from the host solver and give it back (checkpoints).
// C++17.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/vec3.h"

namespace upf {

struct DemSpringState {
  bool primed = false;
  std::vector<std::uint32_t> key;
  std::vector<Vec3> xi;
  std::vector<std::uint32_t> begin_by_id, count_by_id;  // into key and xi
};

// One carried spring: the pair's holder and key (dem_contact_stages.h) and its spring xi. Split
// worlds send these between ranks as raw bytes.
struct DemSpringRecord {
  std::uint32_t holder;  // stable id
  std::uint32_t key;
  Vec3 xi;
};

}  // namespace upf
