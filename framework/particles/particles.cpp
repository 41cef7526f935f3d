#include "framework/particles/particles.h"

#include "framework/core/state_stream.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <type_traits>

namespace upf {

namespace {
// Applies new[i] = old[order[i]] through a scratch buffer that is reused between calls.
template <class T>
void apply_order(std::vector<T>& values, const std::vector<std::uint32_t>& order,
                 std::vector<std::uint8_t>& scratch) {
  const std::size_t bytes = values.size() * sizeof(T);
  if (bytes == 0) return;  // an empty world: memcpy must not see the null data() of empty vectors
  if (scratch.size() < bytes) scratch.resize(bytes);
  std::memcpy(scratch.data(), values.data(), bytes);
  const T* old_values = reinterpret_cast<const T*>(scratch.data());
  for (std::size_t i = 0; i < order.size(); ++i) values[i] = old_values[order[i]];
}
}  // namespace

std::size_t Particles::count(ParticleType t) const {
  return static_cast<std::size_t>(std::count(type.begin(), type.end(), t));
}

std::size_t Particles::add(const Vec3& x, const Vec3& v, Real m, ParticleType t, MaterialId mat,
                           BodyId b) {
  position.push_back(x);
  velocity.push_back(v);
  mass.push_back(m);
  type.push_back(t);
  material.push_back(mat);
  id.push_back(next_id_++);
  body.push_back(b);
  boundary_volume.push_back(0);
  for (auto& [name, f] : scalars_) f.values.push_back(Real(0));
  for (auto& [name, f] : vectors_) f.values.push_back(Vec3{});
  return size() - 1;
}

void Particles::reserve(std::size_t n) {
  for_each_builtin([n](auto& values) { values.reserve(n); }, *this);
}

template <class T>
std::vector<T>& Particles::field_in(std::map<std::string, Field<T>>& fields,
                                    const std::string& name, T init, bool exported) {
  auto it = fields.find(name);
  if (it == fields.end()) {
    if (sealed_)
      throw std::logic_error("particle field '" + name +
                             "' was not declared: solvers declare their fields in prepare()");
    it = fields.try_emplace(name).first;
    it->second.values.assign(size(), init);
  }
  it->second.exported = it->second.exported || exported;
  return it->second.values;
}

std::vector<Real>& Particles::scalar_field(const std::string& name, Real init, bool exported) {
  return field_in(scalars_, name, init, exported);
}

std::vector<Vec3>& Particles::vector_field(const std::string& name, Vec3 init, bool exported) {
  return field_in(vectors_, name, init, exported);
}

FieldHandle<Real> Particles::declare_scalar(const std::string& name, Real init, bool exported) {
  field_in(scalars_, name, init, exported);
  return {this, &scalars_.find(name)->second};
}

FieldHandle<Vec3> Particles::declare_vector(const std::string& name, Vec3 init, bool exported) {
  field_in(vectors_, name, init, exported);
  return {this, &vectors_.find(name)->second};
}

FieldHandle<Real> Particles::declare_scratch_scalar(const std::string& name) {
  FieldHandle<Real> h = declare_scalar(name);
  scalars_.find(name)->second.scratch = true;
  return h;
}

FieldHandle<Vec3> Particles::declare_scratch_vector(const std::string& name) {
  FieldHandle<Vec3> h = declare_vector(name);
  vectors_.find(name)->second.scratch = true;
  return h;
}

FieldHandle<Vec3> Particles::declare_position_vector(const std::string& name) {
  FieldHandle<Vec3> h = declare_vector(name);
  vectors_.find(name)->second.position = true;
  return h;
}

void Particles::sort_by_id() {
  std::vector<std::uint32_t> order(size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return id[a] < id[b]; });
  permute(order);
}

namespace {
template <class T>
std::string declared_names(const std::map<std::string, Field<T>>& fields) {
  std::string names;
  for (const auto& [name, f] : fields) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}
}  // namespace

FieldHandle<Real> Particles::scalar(const std::string& name, const std::string& who) {
  auto it = scalars_.find(name);
  if (it == scalars_.end())
    throw std::logic_error("'" + who + "' reads the scalar particle field '" + name +
                           "', which nobody declared (declared: " + declared_names(scalars_) + ")");
  return {this, &it->second};
}

FieldHandle<Vec3> Particles::vector(const std::string& name, const std::string& who) {
  auto it = vectors_.find(name);
  if (it == vectors_.end())
    throw std::logic_error("'" + who + "' reads the vector particle field '" + name +
                           "', which nobody declared (declared: " + declared_names(vectors_) + ")");
  return {this, &it->second};
}

void Particles::check_owner(const Particles* owner, bool valid) const {
  if (!valid) throw std::logic_error("a particle field handle that was never declared");
  if (owner != this) throw std::logic_error("a particle field handle of other particles");
}

const std::vector<Real>* Particles::find_scalar(const std::string& name) const {
  auto it = scalars_.find(name);
  return it == scalars_.end() ? nullptr : &it->second.values;
}

const std::vector<Vec3>* Particles::find_vector(const std::string& name) const {
  auto it = vectors_.find(name);
  return it == vectors_.end() ? nullptr : &it->second.values;
}

std::vector<Vec3>* Particles::find_vector(const std::string& name) {
  auto it = vectors_.find(name);
  return it == vectors_.end() ? nullptr : &it->second.values;
}

void Particles::permute(const std::vector<std::uint32_t>& order) {
  take(order);
}

void Particles::take(const std::vector<std::uint32_t>& order) {
  for_each_builtin([&](auto& values) { apply_order(values, order, permute_scratch_); }, *this);
  for (auto& [name, f] : scalars_) apply_order(f.values, order, permute_scratch_);
  for (auto& [name, f] : vectors_) apply_order(f.values, order, permute_scratch_);
}

std::size_t Particles::remove(const std::vector<std::uint8_t>& doomed) {
  std::vector<std::uint32_t> kept;
  kept.reserve(size());
  for (std::size_t i = 0; i < size(); ++i)
    if (!doomed[i]) kept.push_back(std::uint32_t(i));
  const std::size_t removed = size() - kept.size();
  if (removed == 0) return 0;
  // take() fills the first kept.size() slots; the rest are cut off.
  take(kept);
  const std::size_t n = kept.size();
  for_each_builtin([n](auto& values) { values.resize(n); }, *this);
  for (auto& [name, f] : scalars_) f.values.resize(n);
  for (auto& [name, f] : vectors_) f.values.resize(n);
  return removed;
}

void Particles::truncate(std::size_t n) {
  if (n >= size()) return;
  const std::size_t owned = owned_size();
  ghosts_ = n > owned ? n - owned : 0;  // the ghosts among the first n
  for_each_builtin([n](auto& values) { values.resize(n); }, *this);
  for (auto& [name, f] : scalars_) f.values.resize(n);
  for (auto& [name, f] : vectors_) f.values.resize(n);
}

namespace {
// Calls visit(values) for every array in packing order: built-in arrays, then named fields.
template <class P, class Visit>
void for_each_array(P& p, std::map<std::string, Field<Real>>& scalars,
                    std::map<std::string, Field<Vec3>>& vectors, Visit&& visit) {
  Particles::for_each_builtin(visit, p);
  for (auto& [name, f] : scalars) visit(f.values);
  for (auto& [name, f] : vectors) visit(f.values);
}
}  // namespace

std::size_t Particles::packed_size() const {
  std::size_t bytes = 0;
  auto& self = const_cast<Particles&>(*this);
  for_each_array(self, self.scalars_, self.vectors_, [&](auto& values) {
    bytes += sizeof(typename std::decay_t<decltype(values)>::value_type);
  });
  return bytes;
}

std::vector<std::size_t> Particles::packed_element_sizes() const {
  std::vector<std::size_t> sizes;
  auto& self = const_cast<Particles&>(*this);
  for_each_array(self, self.scalars_, self.vectors_, [&](auto& values) {
    sizes.push_back(sizeof(typename std::decay_t<decltype(values)>::value_type));
  });
  return sizes;
}

void Particles::pack(const std::uint32_t* indices, std::size_t count,
                     std::vector<std::uint8_t>& out) const {
  const std::size_t start = out.size();
  out.resize(start + count * packed_size());
  std::uint8_t* at = out.data() + start;
  auto& self = const_cast<Particles&>(*this);  // visited read-only
  for_each_array(self, self.scalars_, self.vectors_, [&](auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    for (std::size_t k = 0; k < count; ++k, at += sizeof(T))
      std::memcpy(at, &values[indices[k]], sizeof(T));
  });
}

void Particles::append_packed(const std::uint8_t* bytes, std::size_t count) {
  const std::size_t first = size();
  for_each_array(*this, scalars_, vectors_, [&](auto& values) { values.resize(first + count); });
  overwrite_packed(first, bytes, count);
}

void Particles::overwrite_packed(std::size_t first, const std::uint8_t* bytes, std::size_t count) {
  if (count == 0) return;
  for_each_array(*this, scalars_, vectors_, [&](auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    std::memcpy(static_cast<void*>(&values[first]), bytes, count * sizeof(T));
    bytes += count * sizeof(T);
  });
}

void Particles::snapshot_into(Particles& into) const {
  for_each_builtin([](const auto& from, auto& to) { to = from; }, *this, into);
  for (const auto& [name, f] : scalars_)
    if (f.exported) into.scalars_[name] = f;
  for (const auto& [name, f] : vectors_)
    if (f.exported) into.vectors_[name] = f;
  into.next_id_ = next_id_;
}

namespace {

template <class T>
std::size_t kept_count(const std::map<std::string, Field<T>>& fields) {
  std::size_t n = 0;
  for (const auto& [name, f] : fields) n += !f.scratch;
  return n;
}

template <class T>
void save_fields(StateWriter& out, const std::map<std::string, Field<T>>& fields) {
  out.put(std::uint64_t(kept_count(fields)));
  for (const auto& [name, f] : fields) {
    if (f.scratch) continue;
    out.put_string(name);
    out.put(std::uint8_t(f.exported));
    out.put_vector(f.values);
  }
}

template <class T>
void restore_fields(StateReader& in, std::map<std::string, Field<T>>& fields, std::size_t n) {
  const auto count = in.get<std::uint64_t>();
  const std::size_t here = kept_count(fields);
  in.expect(count == here, "the number of particle fields (" + std::to_string(count) + " saved, " +
                               std::to_string(here) + " here)");
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::string name = in.get_string();
    auto it = fields.find(name);
    in.expect(it != fields.end() && !it->second.scratch, "particle field '" + name + "'");
    it->second.exported = in.get<std::uint8_t>() != 0;
    in.get_vector(it->second.values);
    in.expect(it->second.values.size() == n, "the length of particle field '" + name + "'");
  }
  // Scratch fields are not saved: zero, at the restored length.
  for (auto& [name, f] : fields)
    if (f.scratch) f.values.assign(n, T{});
}

}  // namespace

void Particles::swap_values(Particles& other) {
  for_each_builtin([](auto& mine, auto& theirs) { mine.swap(theirs); }, *this, other);
  auto swap_fields = [](auto& mine, auto& theirs) {
    for (auto& [name, field] : mine) {
      auto it = theirs.find(name);
      if (it == theirs.end()) throw std::logic_error("Particles::swap_values: no field " + name);
      field.values.swap(it->second.values);
      std::swap(field.exported, it->second.exported);
    }
  };
  swap_fields(scalars_, other.scalars_);
  swap_fields(vectors_, other.vectors_);
  std::swap(next_id_, other.next_id_);
  std::swap(ghosts_, other.ghosts_);
}

void Particles::save_state(StateWriter& out) const {
  out.section("particles");
  out.put(next_id_);
  for_each_builtin([&out](const auto& values) { out.put_vector(values); }, *this);
  save_fields(out, scalars_);
  save_fields(out, vectors_);
}

void Particles::restore_state(StateReader& in) {
  in.section("particles");
  // Emitters hand out ids after the scene's: the count only grows from the scene's own.
  const auto next_id = in.get<ParticleId>();
  in.expect(next_id >= next_id_, "the particle id count (" + std::to_string(next_id) +
                                     " saved, at least " + std::to_string(next_id_) + " here)");
  next_id_ = next_id;
  for_each_builtin([&in](auto& values) { in.get_vector(values); }, *this);
  const std::size_t n = position.size();
  bool sizes = true;
  for_each_builtin([&](const auto& values) { sizes = sizes && values.size() == n; }, *this);
  in.expect(sizes, "the particle arrays' lengths");
  restore_fields(in, scalars_, n);
  restore_fields(in, vectors_, n);
}

}  // namespace upf
