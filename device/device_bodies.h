// The body systems' per-particle work on the device pipeline (body_particle_stages.h): placing
// the particles of moving bodies, each body's sum of fluid reactions and their torques, and the
// penetration guard. The body system itself (Bullet, on the host) sends poses and gets back six
// numbers per body and the guard's few hits, so the particles never leave the device.
//
// Per-body sums are exact fixed-point (BodyWrench): a reduce_by_key over the body particles
// sorted by body gives the CPU's bits whatever order the device adds them in. The guard's hits
// come back in particle-id order, as the CPU sorts them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <thrust/copy.h>
#include <thrust/iterator/transform_iterator.h>
#include <thrust/reduce.h>
#include <thrust/sort.h>

#include "device/device_particles.h"
#include "device/device_primitives.h"
#include "framework/boundary/slip_normal_fields.h"
#include "framework/world/body_particle_stages.h"

namespace upf::device {

namespace bodies_detail {

// The particles of any body: rigid ones, and a static or kinematic body's frozen ones.
struct IsBodyParticle {
  const BodyId* body;
  UPF_HD bool operator()(std::uint32_t i) const { return body[i] != kNoBody; }
};

struct BodyOf {
  const BodyId* body;
  UPF_HD BodyId operator()(std::uint32_t i) const { return body[i]; }
};

struct HitOf {
  const std::uint8_t* hit;
  UPF_HD bool operator()(std::uint32_t i) const { return hit[i] != 0; }
};

struct HitRecord {
  const SurfaceHit* hits;
  UPF_HD SurfaceHit operator()(std::uint32_t i) const { return hits[i]; }
};

struct HitParticleLess {
  UPF_HD bool operator()(const SurfaceHit& a, const SurfaceHit& b) const {
    return a.particle < b.particle;
  }
};

}  // namespace bodies_detail

template <class Backend>
class DeviceBodies {
  template <class T>
  using vector = typename Backend::template vector<T>;

 public:
  void place(DeviceParticles<Backend>& p, const std::vector<BodyPose>& poses,
             const std::string& local_field) {
    copy_to_device(poses_, poses);
    // With free-slip boundaries, their normals turn with the bodies (slip_normal.h).
    vector<Vec3>* local_slip = p.find_vector(kBodySlipNormalField);
    vector<Vec3>* slip = p.find_vector(kSlipNormalField);
    const bool turn = local_slip != nullptr && slip != nullptr;
    run<Backend>(
        all_particles(p.size()),
        PlaceBodyParticlesStage{raw<BodyPose>(poses_), raw<BodyId>(p.body),
                                raw<Vec3>(p.vector_array(local_field)), raw<Vec3>(p.position),
                                raw<Vec3>(p.velocity), turn ? raw<Vec3>(*local_slip) : nullptr,
                                turn ? raw<Vec3>(*slip) : nullptr});
  }

  // One wrench per body id of `origins`; bodies without particles get zero.
  void wrenches(const DeviceParticles<Backend>& p, const vector<Vec3>& force,
                const std::vector<Vec3d>& origins, std::vector<BodyWrench>& out) {
    using namespace bodies_detail;
    out.assign(origins.size(), BodyWrench{});
    const std::size_t n = p.size();
    if (force.size() != n || n == 0) return;
    copy_to_device(origins_, origins);
    // The body particles, sorted by body (stable: index order within a body, though any order
    // gives the same exact sums).
    rigid_.resize(n);
    const auto last =
        thrust::copy_if(Backend::policy(), thrust::counting_iterator<std::uint32_t>(0),
                        thrust::counting_iterator<std::uint32_t>(std::uint32_t(n)), rigid_.begin(),
                        IsBodyParticle{raw<BodyId>(p.body)});
    const std::size_t count = std::size_t(last - rigid_.begin());
    if (count == 0) return;
    rigid_.resize(count);
    keys_.resize(count);
    thrust::transform(Backend::policy(), rigid_.begin(), rigid_.end(), keys_.begin(),
                      BodyOf{raw<BodyId>(p.body)});
    thrust::stable_sort_by_key(Backend::policy(), keys_.begin(), keys_.end(), rigid_.begin());
    unique_keys_.resize(origins.size());
    sums_.resize(origins.size());
    const auto values = thrust::make_transform_iterator(
        rigid_.begin(), RigidReactionWrench{raw<Vec3>(p.position), raw<Vec3>(force),
                                            raw<BodyId>(p.body), raw<Vec3d>(origins_)});
    const auto ends = thrust::reduce_by_key(Backend::policy(), keys_.begin(), keys_.end(), values,
                                            unique_keys_.begin(), sums_.begin(),
                                            thrust::equal_to<BodyId>(), BodyWrenchPlus{});
    const std::size_t bodies = std::size_t(ends.first - unique_keys_.begin());
    const std::vector<BodyId> ids(unique_keys_.begin(), unique_keys_.begin() + bodies);
    const std::vector<BodyWrench> sums(sums_.begin(), sums_.begin() + bodies);
    for (std::size_t k = 0; k < bodies; ++k) out[std::size_t(ids[k])] = sums[k];
  }

  // The guard over every liquid particle; `hits` in particle-id order.
  void guard(DeviceParticles<Backend>& p, NeighbourView liquid_to_boundary,
             const std::vector<BodyPose>& poses, const std::vector<const MeshParityData*>& meshes,
             double layer_depth, double clearance, const std::string& local_field,
             const std::string& normal_field, std::vector<SurfaceHit>& hits) {
    using namespace bodies_detail;
    hits.clear();
    const std::size_t n = p.size();
    if (n == 0) return;
    if (mesh_views_.size() != meshes.size()) upload_meshes(meshes);
    copy_to_device(poses_, poses);
    hit_records_.resize(n);
    hit_.resize(n);
    run<Backend>(
        all_particles(n),
        SurfaceGuardStage{raw<Vec3>(p.position), raw<Vec3>(p.velocity), raw<Real>(p.mass),
                          raw<ParticleType>(p.type), raw<BodyId>(p.body), raw<ParticleId>(p.id),
                          raw<Vec3>(p.vector_array(local_field)),
                          raw<Vec3>(p.vector_array(normal_field)), liquid_to_boundary,
                          raw<BodyPose>(poses_), raw<MeshParityView>(mesh_views_), layer_depth,
                          clearance, raw<SurfaceHit>(hit_records_), raw<std::uint8_t>(hit_)});
    hit_index_.resize(n);
    const auto last =
        thrust::copy_if(Backend::policy(), thrust::counting_iterator<std::uint32_t>(0),
                        thrust::counting_iterator<std::uint32_t>(std::uint32_t(n)),
                        hit_index_.begin(), HitOf{raw<std::uint8_t>(hit_)});
    const std::size_t count = std::size_t(last - hit_index_.begin());
    if (count == 0) return;
    found_.resize(count);
    thrust::transform(Backend::policy(), hit_index_.begin(), hit_index_.begin() + count,
                      found_.begin(), HitRecord{raw<SurfaceHit>(hit_records_)});
    thrust::sort(Backend::policy(), found_.begin(), found_.end(), HitParticleLess{});
    hits.assign(found_.begin(), found_.end());
  }

  std::size_t bytes() const {
    return bytes_of(poses_) + bytes_of(origins_) + bytes_of(rigid_) + bytes_of(keys_) +
           bytes_of(unique_keys_) + bytes_of(sums_) + bytes_of(hit_records_) + bytes_of(hit_) +
           bytes_of(hit_index_) + bytes_of(found_) + bytes_of(mesh_views_) +
           bytes_of(mesh_vertices_) + bytes_of(mesh_indices_);
  }

 private:
  // The bodies' meshes (body frame: they never change) into one set of buffers, once; a view
  // per body into them.
  void upload_meshes(const std::vector<const MeshParityData*>& meshes) {
    std::vector<Vec3d> vertices;
    std::vector<std::uint32_t> indices;  // triangles, bin offsets and bin triangles, per mesh
    struct Start {
      std::size_t vertices, triangles, bin_offsets, bin_triangles;
    };
    std::vector<Start> starts;
    for (const MeshParityData* m : meshes) {
      Start s{vertices.size(), 0, 0, 0};
      if (m) {
        vertices.insert(vertices.end(), m->vertices.begin(), m->vertices.end());
        s.triangles = indices.size();
        indices.insert(indices.end(), m->triangles.begin(), m->triangles.end());
        s.bin_offsets = indices.size();
        indices.insert(indices.end(), m->bin_offsets.begin(), m->bin_offsets.end());
        s.bin_triangles = indices.size();
        indices.insert(indices.end(), m->bin_triangles.begin(), m->bin_triangles.end());
      }
      starts.push_back(s);
    }
    copy_to_device(mesh_vertices_, vertices);
    copy_to_device(mesh_indices_, indices);
    std::vector<MeshParityView> views(meshes.size());
    for (std::size_t b = 0; b < meshes.size(); ++b) {
      const MeshParityData* m = meshes[b];
      if (!m) continue;  // no vertices: not guarded
      MeshParityView& v = views[b];
      v.vertices = raw<Vec3d>(mesh_vertices_) + starts[b].vertices;
      v.triangles = raw<std::uint32_t>(mesh_indices_) + starts[b].triangles;
      v.bin_offsets = raw<std::uint32_t>(mesh_indices_) + starts[b].bin_offsets;
      v.bin_triangles = raw<std::uint32_t>(mesh_indices_) + starts[b].bin_triangles;
      v.box_min = m->box_min;
      v.box_max = m->box_max;
      v.bin_size = m->bin_size;
      v.bins_y = m->bins_y;
      v.bins_z = m->bins_z;
    }
    copy_to_device(mesh_views_, views);
  }

  vector<BodyPose> poses_;
  vector<Vec3d> origins_;
  vector<std::uint32_t> rigid_;
  vector<BodyId> keys_, unique_keys_;
  vector<BodyWrench> sums_;
  vector<SurfaceHit> hit_records_;
  vector<std::uint8_t> hit_;
  vector<std::uint32_t> hit_index_;
  vector<SurfaceHit> found_;
  vector<MeshParityView> mesh_views_;
  vector<Vec3d> mesh_vertices_;
  vector<std::uint32_t> mesh_indices_;
};

}  // namespace upf::device
