// A sink: a region where liquid leaves the scene, a box or a half-space (beyond a plane, on the
// side its normal points to), like SPlisHSPlasH's and DualSPHysics' outlets. Before each step it
// removes every liquid particle whose centre is inside; walls, bodies and grains are never
// removed (particle_source.h: survivors keep their order). A box sink may have an outflow buffer
// upstream of it (outflow_buffer.h), which makes it an outlet that holds the flow's speed.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "framework/scene/scene.h"
#include "framework/world/particle_source.h"
#include "solvers/sources/outflow_buffer.h"

namespace upf {

struct SinkDesc {
  std::string name;
  std::optional<Box> box;                             // a box sink, or
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    // a half-space through `point`
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  // pointing into the removed side (unit)
  std::optional<OutflowBufferDesc> outflow;           // a box's outflow buffer
  std::string reuse;  // the emitter it gives its particles back to (at_limit "reuse"), or none
};

class Emitter;

class Sink : public ParticleSource {
 public:
  explicit Sink(SinkDesc desc) : desc_(std::move(desc)) {
    if (desc_.outflow) outflow_.emplace(*desc_.outflow);
  }
  std::string_view name() const override { return desc_.name; }
  bool may_change(double, double) const override { return true; }
  SourceChange apply(Particles& particles, const SourceStep& step) override;
  bool contains(const Eigen::Vector3d& x) const;
  // Gives what it takes back to `emitter` (desc.reuse), counted over every rank.
  void reuse_into(Emitter* emitter) { reuse_into_ = emitter; }

 private:
  SinkDesc desc_;
  std::optional<OutflowBuffer> outflow_;
  Emitter* reuse_into_ = nullptr;
  std::vector<std::uint8_t> doomed_;  // apply()'s flags, kept between steps
};

}  // namespace upf
