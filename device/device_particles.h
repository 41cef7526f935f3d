// The device mirror of Particles: the same structure of arrays, named fields included, in a
// backend's memory (device_backend_*.h). Uploaded once; frames, probes and checkpoints download.
// Reordering gathers every array, as Particles::permute does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <thrust/copy.h>
#include <thrust/gather.h>

#include "device/device_primitives.h"
#include "framework/particles/particles.h"

namespace upf::device {

template <class Backend>
class DeviceParticles {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  vector<Vec3> position, velocity;
  vector<Real> mass, boundary_volume;
  vector<ParticleType> type;
  vector<MaterialId> material;
  vector<ParticleId> id;
  vector<BodyId> body;

  std::size_t size() const { return position.size(); }

  // Every array and every named field of `p`.
  void upload(const Particles& p) {
    Particles::for_each_builtin([](auto& to, const auto& from) { copy_to_device(to, from); }, *this,
                                p);
    for (const auto& [name, f] : p.scalar_fields()) copy_to_device(scalars_[name], f.values);
    for (const auto& [name, f] : p.vector_fields()) copy_to_device(vectors_[name], f.values);
    exported_.clear();
    for (const auto& [name, f] : p.scalar_fields()) exported_[name] = f.exported;
    for (const auto& [name, f] : p.vector_fields()) exported_[name] = f.exported;
    positions_.clear();
    for (const auto& [name, f] : p.vector_fields())
      if (f.position) positions_.push_back(name);
  }

  // Every array and named field into `p`, which has the same fields (the one uploaded from).
  void download(Particles& p) const { download(p, false); }
  // Only the built-in arrays and the exported fields: what Particles::snapshot_into copies.
  void download_snapshot(Particles& p) const { download(p, true); }

  // The same arrays and exported fields in `into`: the last good state of a step.
  void snapshot_into(DeviceParticles& into) const {
    Particles::for_each_builtin([](auto& to, const auto& from) { to = from; }, into, *this);
    for (const auto& [name, f] : scalars_)
      if (exported_.at(name)) into.scalars_[name] = f;
    for (const auto& [name, f] : vectors_)
      if (exported_.at(name)) into.vectors_[name] = f;
    into.exported_ = exported_;
    into.positions_ = positions_;
  }

  // A named field's array; the object stays put (reordering swaps its contents).
  vector<Real>& scalar_array(const std::string& name) { return scalars_.at(name); }
  vector<Vec3>& vector_array(const std::string& name) { return vectors_.at(name); }
  // The named field's array, or null when the particles have no such field.
  vector<Vec3>* find_vector(const std::string& name) {
    const auto it = vectors_.find(name);
    return it == vectors_.end() ? nullptr : &it->second;
  }
  const vector<Vec3>* find_vector(const std::string& name) const {
    const auto it = vectors_.find(name);
    return it == vectors_.end() ? nullptr : &it->second;
  }

  // Device memory held by every array and field.
  std::size_t bytes() const {
    std::size_t total = 0;
    auto add = [&](const auto& a) { total += bytes_of(a); };
    Particles::for_each_builtin(add, *this);
    for (const auto& [name, f] : scalars_) add(f);
    for (const auto& [name, f] : vectors_) add(f);
    return total;
  }

  // Copies of particles sources[k] at first + k in every array and field, as a ghost refresh
  // copies them (Particles::overwrite_packed); with `grow`, the arrays grow to hold them first
  // (Particles::append_packed). Sources lie below `first`.
  void copy_to_tail(std::size_t first, const vector<std::uint32_t>& sources, bool grow) {
    auto copy = [&](auto& a) {
      if (grow) a.resize(first + sources.size());
      thrust::gather(Backend::policy(), sources.begin(), sources.end(), a.begin(),
                     a.begin() + std::ptrdiff_t(first));
    };
    Particles::for_each_builtin([&](auto& a) { copy(a); }, *this);
    for (auto& [name, f] : scalars_) copy(f);
    for (auto& [name, f] : vectors_) copy(f);
  }

  // Keeps the first n particles of every array and field (Particles::truncate).
  void truncate(std::size_t n) {
    Particles::for_each_builtin([&](auto& a) { a.resize(n); }, *this);
    for (auto& [name, f] : scalars_) f.resize(n);
    for (auto& [name, f] : vectors_) f.resize(n);
  }

  // visit(array) for `position` and every field of positions (Particles::for_each_position_array).
  template <class Visit>
  void for_each_position_array(Visit&& visit) {
    visit(position);
    for (const std::string& name : positions_) visit(vectors_.at(name));
  }

  // new[i] = old[order[i]] for every array.
  void permute(const vector<std::uint32_t>& order) {
    auto gather = [&](auto& a) {
      std::decay_t<decltype(a)> scratch(a.size());
      thrust::gather(Backend::policy(), order.begin(), order.end(), a.begin(), scratch.begin());
      a.swap(scratch);
    };
    Particles::for_each_builtin([&](auto& a) { gather(a); }, *this);
    for (auto& [name, f] : scalars_) gather(f);
    for (auto& [name, f] : vectors_) gather(f);
  }

 private:
  void download(Particles& p, bool snapshot_only) const {
    Particles::for_each_builtin([](auto& to, const auto& from) { copy_to_host(to, from); }, p,
                                *this);
    for (const auto& [name, f] : scalars_)
      if (!snapshot_only || exported_.at(name)) copy_to_host(p.scalar_field(name), f);
    for (const auto& [name, f] : vectors_)
      if (!snapshot_only || exported_.at(name)) copy_to_host(p.vector_field(name), f);
  }

  std::map<std::string, vector<Real>> scalars_;
  std::map<std::string, vector<Vec3>> vectors_;
  std::map<std::string, bool> exported_;
  std::vector<std::string> positions_;  // the vector fields of positions (Field::position)
};

}  // namespace upf::device
