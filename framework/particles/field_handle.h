// A typed handle to a named particle field (Particles::declare_scalar / declare_vector). A solver
// declares its fields in prepare() and keeps the handles; in step() it reaches the arrays through
// them, with no string lookup and no chance of a misspelt name creating a new zero field.
#pragma once

namespace upf {

template <class T>
struct Field;
class Particles;

template <class T>
class FieldHandle {
 public:
  FieldHandle() = default;
  bool valid() const { return field_ != nullptr; }

 private:
  friend class Particles;
  FieldHandle(const Particles* owner, Field<T>* field) : owner_(owner), field_(field) {}
  const Particles* owner_ = nullptr;
  Field<T>* field_ = nullptr;
};

}  // namespace upf
