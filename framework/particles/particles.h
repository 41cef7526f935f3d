// Particles: the world's particles as a structure of arrays.
//
// Built-in arrays hold what every solver needs; a solver adds the fields it needs by name
// ("pcisph.pressure"), so a plug-in needs no change here and writers can export any field.
// Every particle has a stable id that survives reordering; exports carry it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "framework/core/particle_type.h"
#include "framework/core/vec3.h"
#include "framework/particles/field_handle.h"

namespace upf {

class StateWriter;
class StateReader;

using ParticleId = std::uint32_t;
using MaterialId = std::uint16_t;
using BodyId = std::int32_t;
inline constexpr BodyId kNoBody = -1;

// A named per-particle field. `exported` fields go into frames and into the last-good snapshot.
template <class T>
struct Field {
  std::vector<T> values;
  bool exported = false;
  // Rewritten every step before anything reads it (a solver's per-step arrays that neighbours
  // read): ghosts carry it, checkpoints do not, and a device pipeline may keep its own copy.
  bool scratch = false;
  // Holds positions (a predicted position): a periodic image holds it shifted by its period,
  // as it holds `position` (periodic_box.h).
  bool position = false;
};

class Particles {
 public:
  // Built-in arrays, all of size size(). for_each_builtin lists them once for every operation
  // that treats them alike.
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
  std::vector<Real> mass;
  std::vector<ParticleType> type;
  std::vector<MaterialId> material;
  std::vector<ParticleId> id;
  std::vector<BodyId> body;
  // Akinci et al. 2012 boundary volume V_b = 1 / sum_k W_bk (zero for non-boundary particles).
  std::vector<Real> boundary_volume;

  std::size_t size() const { return position.size(); }
  std::size_t count(ParticleType t) const;

  // Ghosts (MPI, framework/world/particle_domain.h): copies of other ranks' particles within
  // reach of this rank's domain, held at the end of the arrays, [owned_size(), size()), for the
  // length of a step. Solvers move only the owned ones; the domain refreshes the ghosts.
  std::size_t owned_size() const { return size() - ghosts_; }
  std::size_t ghost_count() const { return ghosts_; }
  void set_ghost_count(std::size_t ghosts) { ghosts_ = ghosts; }
  // Cuts every array to its first n particles.
  void truncate(std::size_t n);

  // Every array of the particles listed in `indices`, appended to `out` as raw bytes (the
  // built-in arrays, then the named fields by name): how particles travel between ranks.
  void pack(const std::uint32_t* indices, std::size_t count, std::vector<std::uint8_t>& out) const;
  // The bytes of one packed particle.
  std::size_t packed_size() const;
  // The bytes of one element of each array, in the packed order: a packet of n particles holds
  // the arrays one after another, n elements each.
  std::vector<std::size_t> packed_element_sizes() const;
  // Appends `count` particles packed by a Particles with the same fields.
  void append_packed(const std::uint8_t* bytes, std::size_t count);
  // Overwrites particles first, first + 1, ... with `count` packed ones.
  void overwrite_packed(std::size_t first, const std::uint8_t* bytes, std::size_t count);

  // Appends a particle and gives it the next stable id. Returns its index.
  std::size_t add(const Vec3& x, const Vec3& v, Real m, ParticleType t, MaterialId mat,
                  BodyId b = kNoBody);
  void reserve(std::size_t n);

  // Named fields: created on first request (filled with `init`), found afterwards. Once the
  // world is prepared (seal_fields) a name nobody declared is an error that names the field.
  std::vector<Real>& scalar_field(const std::string& name, Real init = 0, bool exported = false);
  std::vector<Vec3>& vector_field(const std::string& name, Vec3 init = {}, bool exported = false);
  // The same, as typed handles: what a solver declares in prepare() and uses in step().
  FieldHandle<Real> declare_scalar(const std::string& name, Real init = 0, bool exported = false);
  FieldHandle<Vec3> declare_vector(const std::string& name, Vec3 init = {}, bool exported = false);
  // A per-step field (Field::scratch), zero-initialised and never exported.
  FieldHandle<Real> declare_scratch_scalar(const std::string& name);
  FieldHandle<Vec3> declare_scratch_vector(const std::string& name);
  // A vector field of positions (Field::position): PCISPH's and PBF's predicted positions.
  FieldHandle<Vec3> declare_position_vector(const std::string& name);
  // visit(array) for `position` and every field of positions: what a periodic image shifts.
  template <class Visit>
  void for_each_position_array(Visit&& visit) {
    visit(position);
    for (auto& [name, f] : vectors_)
      if (f.position) visit(f.values);
  }
  // Reorders every array by stable id (frames and checkpoints of a domain list them so).
  void sort_by_id();
  // A field someone else declared, for `who` (a solver or system name, for the error).
  FieldHandle<Real> scalar(const std::string& name, const std::string& who);
  FieldHandle<Vec3> vector(const std::string& name, const std::string& who);
  // The values behind a handle of this Particles.
  template <class T>
  std::vector<T>& operator[](FieldHandle<T> h) {
    check_owner(h.owner_, h.valid());
    return h.field_->values;
  }
  template <class T>
  const std::vector<T>& operator[](FieldHandle<T> h) const {
    check_owner(h.owner_, h.valid());
    return h.field_->values;
  }
  // From here on, asking for a field nobody declared throws (World::prepare calls it).
  void seal_fields(bool sealed = true) { sealed_ = sealed; }
  const std::vector<Real>* find_scalar(const std::string& name) const;
  const std::vector<Vec3>* find_vector(const std::string& name) const;
  std::vector<Vec3>* find_vector(const std::string& name);
  const std::map<std::string, Field<Real>>& scalar_fields() const { return scalars_; }
  const std::map<std::string, Field<Vec3>>& vector_fields() const { return vectors_; }

  // Reorders every array: new[i] = old[order[i]]. `order` must be a permutation of size().
  void permute(const std::vector<std::uint32_t>& order);
  // Removes the particles i with doomed[i] != 0 (doomed.size() == size()), keeping the order
  // and the ids of the others. Returns how many went.
  std::size_t remove(const std::vector<std::uint8_t>& doomed);

  // Copies positions, velocities and exported fields into `into` (reusing its storage), so the
  // last good state can be written after an instability.
  void snapshot_into(Particles& into) const;

  // Largest stable id handed out so far plus one.
  ParticleId id_bound() const { return next_id_; }

  // Exchanges every array and field's values with `other`, a copy of this Particles (the same
  // fields): a state read and checked aside becomes this one while the field handles, which point
  // into this object, stay valid.
  void swap_values(Particles& other);

  // Checkpoints: every array, every field but the scratch ones, and the id counter. restore_state
  // expects the fields this world's solvers made (same names): anything else is another run.
  void save_state(StateWriter& out) const;
  void restore_state(StateReader& in);

  // visit(a.position, b.position, ...), then velocity, ... for every built-in array, in the order
  // of checkpoints. One list, so a new built-in array cannot be forgotten by one operation; any
  // structure with members of these names takes part (the device mirror, device_particles.h).
  template <class Visit, class... P>
  static void for_each_builtin(Visit&& visit, P&... p) {
    visit(p.position...);
    visit(p.velocity...);
    visit(p.mass...);
    visit(p.type...);
    visit(p.material...);
    visit(p.id...);
    visit(p.body...);
    visit(p.boundary_volume...);
  }

 private:
  void check_owner(const Particles* owner, bool valid) const;
  template <class T>
  std::vector<T>& field_in(std::map<std::string, Field<T>>& fields, const std::string& name, T init,
                           bool exported);
  // new[i] = old[order[i]] for i < order.size() in every array, sizes unchanged.
  void take(const std::vector<std::uint32_t>& order);

  std::map<std::string, Field<Real>> scalars_;
  std::map<std::string, Field<Vec3>> vectors_;
  ParticleId next_id_ = 0;
  std::size_t ghosts_ = 0;
  bool sealed_ = false;
  std::vector<std::uint8_t> permute_scratch_;
};

}  // namespace upf
