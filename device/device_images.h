// Periodic images in a device pipeline (periodic_box.h): PeriodicDomain's work (periodic_domain.h)
// as device stages. At a step's start the moving particles are wrapped into the box and every
// particle within reach of a periodic face lends an image (a copy shifted by the period) that
// goes after the owned particles; after every shared stage the images are copied again from
// their sources (refresh_ghosts), and at the step's end they are dropped. The images come in the
// CPU's order (by source index, then PeriodicBox::image_shifts' order: a count, a scan and a
// fill), so lists, stages and results are the CPU's bits.
#pragma once

#include <cstddef>
#include <cstdint>

#include <thrust/gather.h>
#include <thrust/scan.h>

#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "framework/core/particle_type.h"
#include "framework/world/periodic_box.h"

namespace upf::device {

namespace images_detail {

struct WrapMovingStage {
  PeriodicBox box;
  Vec3* x;
  const ParticleType* type;
  UPF_HD void operator()(std::size_t i) const {
    if (type[i] != ParticleType::Frozen) box.wrap(x[i]);
  }
};

struct CountImagesStage {
  PeriodicBox box;
  Real reach;
  const Vec3* x;
  std::uint32_t* count;  // count[i + 1]
  UPF_HD void operator()(std::size_t i) const {
    Vec3 shifts[PeriodicBox::kMaxImages];
    count[i + 1] = std::uint32_t(box.image_shifts(x[i], reach, shifts));
  }
};

struct FillImagesStage {
  PeriodicBox box;
  Real reach;
  const Vec3* x;
  const std::uint32_t* offsets;
  std::uint32_t* sources;
  Vec3* shifts;
  UPF_HD void operator()(std::size_t i) const {
    Vec3 s[PeriodicBox::kMaxImages];
    const int count = box.image_shifts(x[i], reach, s);
    for (int k = 0; k < count; ++k) {
      sources[offsets[i] + std::uint32_t(k)] = std::uint32_t(i);
      shifts[offsets[i] + std::uint32_t(k)] = s[k];
    }
  }
};

// Image k (particle first + k) moved by shifts[k] (shift_ghost_positions).
struct ShiftImagesStage {
  const Vec3* shifts;
  Vec3* x;  // from the first image on
  UPF_HD void operator()(std::size_t k) const { x[k] = PeriodicBox::shifted(x[k], shifts[k]); }
};

}  // namespace images_detail

template <class Backend>
class DeviceImages final : public DeviceGhosts {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  DeviceImages(const PeriodicBox& box, Real support_radius)
      : box_(box), reach_(periodic_image_reach(support_radius)) {}

  // Wraps the moving particles and appends the images (PeriodicDomain::exchange). `coupling`:
  // the arrays refreshed with them once sized to every particle (the pipeline's coupling arrays).
  void append(DeviceParticles<Backend>& p, vector<Vec3>* coupling0, vector<Vec3>* coupling1) {
    using namespace images_detail;
    particles_ = &p;
    coupling_[0] = coupling0;
    coupling_[1] = coupling1;
    owned_ = p.size();
    for_each_index<Backend>(
        owned_, WrapMovingStage{box_, raw<Vec3>(p.position), raw<ParticleType>(p.type)});
    offsets_.resize(owned_ + 1);
    offsets_[0] = 0;
    for_each_index<Backend>(owned_, CountImagesStage{box_, reach_, raw<Vec3>(p.position),
                                                     raw<std::uint32_t>(offsets_)});
    thrust::inclusive_scan(Backend::policy(), offsets_.begin(), offsets_.end(), offsets_.begin());
    const std::size_t images = std::size_t(offsets_[owned_]);
    sources_.resize(images);
    shifts_.resize(images);
    for_each_index<Backend>(
        owned_, FillImagesStage{box_, reach_, raw<Vec3>(p.position), raw<std::uint32_t>(offsets_),
                                raw<std::uint32_t>(sources_), raw<Vec3>(shifts_)});
    p.copy_to_tail(owned_, sources_, true);
    shift_images();
  }

  // The images copied again from their sources, positions shifted (PeriodicDomain::
  // refresh_ghosts), and the coupling arrays' entries with them.
  void refresh_ghosts() const override {
    if (!particles_ || sources_.empty()) return;
    particles_->copy_to_tail(owned_, sources_, false);
    shift_images();
    for (vector<Vec3>* values : coupling_)
      if (values && values->size() == particles_->size())
        thrust::gather(Backend::policy(), sources_.begin(), sources_.end(), values->begin(),
                       values->begin() + std::ptrdiff_t(owned_));
  }

  // Back to the owned particles (PeriodicDomain::drop_ghosts).
  void drop() {
    if (particles_) particles_->truncate(owned_);
    particles_ = nullptr;
    sources_.clear();
    shifts_.clear();
  }

  std::size_t bytes() const { return bytes_of(offsets_) + bytes_of(sources_) + bytes_of(shifts_); }

 private:
  void shift_images() const {
    const std::size_t images = sources_.size();
    particles_->for_each_position_array([&](vector<Vec3>& x) {
      for_each_index<Backend>(
          images, images_detail::ShiftImagesStage{raw<Vec3>(shifts_), raw<Vec3>(x) + owned_});
    });
  }

  PeriodicBox box_;
  Real reach_;
  DeviceParticles<Backend>* particles_ = nullptr;
  vector<Vec3>* coupling_[2] = {nullptr, nullptr};
  std::size_t owned_ = 0;
  vector<std::uint32_t> offsets_, sources_;
  vector<Vec3> shifts_;
};

}  // namespace upf::device
