#include "framework/mpi/zoltan_rcb.h"

#include <zoltan.h>

#include <stdexcept>
#include <string>

namespace upf {

namespace {

using PointsView = ZoltanRcb::Points;

int count_of(void* data, int* error) {
  *error = ZOLTAN_OK;
  return int(static_cast<const PointsView*>(data)->count);
}

void list_of(void* data, int /*gid_size*/, int /*lid_size*/, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids,
             int /*weight_dim*/, float* weights, int* error) {
  const auto* p = static_cast<const PointsView*>(data);
  for (std::size_t i = 0; i < p->count; ++i) {
    gids[i] = lids[i] = ZOLTAN_ID_TYPE(i);
    weights[i] = p->weight[i];
  }
  *error = ZOLTAN_OK;
}

int dimension_of(void*, int* error) {
  *error = ZOLTAN_OK;
  return 3;
}

void coordinates_of(void* data, int /*gid_size*/, int /*lid_size*/, int count,
                    ZOLTAN_ID_PTR /*gids*/, ZOLTAN_ID_PTR lids, int /*dims*/, double* coords,
                    int* error) {
  const auto* p = static_cast<const PointsView*>(data);
  for (int k = 0; k < count; ++k) {
    const Vec3& x = p->x[lids[k]];
    coords[3 * k] = double(x.x);
    coords[3 * k + 1] = double(x.y);
    coords[3 * k + 2] = double(x.z);
  }
  *error = ZOLTAN_OK;
}

void check(int status, const char* what) {
  if (status != ZOLTAN_OK && status != ZOLTAN_WARN)
    throw std::runtime_error(std::string("Zoltan: ") + what + " failed (status " +
                             std::to_string(status) + ")");
}

}  // namespace

ZoltanRcb::ZoltanRcb(MPI_Comm comm) {
  float version = 0;
  check(Zoltan_Initialize(0, nullptr, &version), "Zoltan_Initialize");
  MPI_Comm_size(comm, &ranks_);
  zz_ = Zoltan_Create(comm);
  if (!zz_) throw std::runtime_error("Zoltan: Zoltan_Create failed");
  Zoltan_Set_Param(zz_, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz_, "LB_METHOD", "RCB");
  Zoltan_Set_Param(zz_, "NUM_GID_ENTRIES", "1");
  Zoltan_Set_Param(zz_, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz_, "OBJ_WEIGHT_DIM", "1");   // a weight per particle
  Zoltan_Set_Param(zz_, "RETURN_LISTS", "NONE");  // owners come from the kept cuts
  Zoltan_Set_Param(zz_, "KEEP_CUTS", "1");
  Zoltan_Set_Param(zz_, "RCB_RECTILINEAR_BLOCKS", "1");  // boxes: a particle has one owner
  PointsView* view = &points_;
  Zoltan_Set_Num_Obj_Fn(zz_, count_of, view);
  Zoltan_Set_Obj_List_Fn(zz_, list_of, view);
  Zoltan_Set_Num_Geom_Fn(zz_, dimension_of, view);
  Zoltan_Set_Geom_Multi_Fn(zz_, coordinates_of, view);
  scratch_procs_.resize(std::size_t(ranks_));
  scratch_parts_.resize(std::size_t(ranks_));
}

ZoltanRcb::~ZoltanRcb() {
  Zoltan_Destroy(&zz_);
}

void ZoltanRcb::balance(const Vec3* points, const float* weights, std::size_t count) {
  points_ = {points, weights, count};
  int changes = 0, gid_size = 1, lid_size = 1, imports = 0, exports = 0;
  ZOLTAN_ID_PTR import_gids = nullptr, import_lids = nullptr, export_gids = nullptr,
                export_lids = nullptr;
  int *import_procs = nullptr, *import_parts = nullptr, *export_procs = nullptr,
      *export_parts = nullptr;
  const int status = Zoltan_LB_Partition(
      zz_, &changes, &gid_size, &lid_size, &imports, &import_gids, &import_lids, &import_procs,
      &import_parts, &exports, &export_gids, &export_lids, &export_procs, &export_parts);
  Zoltan_LB_Free_Part(&import_gids, &import_lids, &import_procs, &import_parts);
  Zoltan_LB_Free_Part(&export_gids, &export_lids, &export_procs, &export_parts);
  points_ = {};
  check(status, "Zoltan_LB_Partition (RCB)");
}

int ZoltanRcb::owner(const Vec3& x) const {
  double c[3] = {double(x.x), double(x.y), double(x.z)};
  int proc = 0, part = 0;
  check(Zoltan_LB_Point_PP_Assign(zz_, c, &proc, &part), "Zoltan_LB_Point_PP_Assign");
  return proc;
}

void ZoltanRcb::box(int r, double lo[3], double hi[3]) const {
  int dims = 0;
  check(Zoltan_RCB_Box(zz_, r, &dims, &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]),
        "Zoltan_RCB_Box");
}

void ZoltanRcb::ranks_touching(const Vec3& lo, const Vec3& hi, std::vector<int>& ranks) const {
  int procs = 0, parts = 0;
  check(Zoltan_LB_Box_PP_Assign(zz_, double(lo.x), double(lo.y), double(lo.z), double(hi.x),
                                double(hi.y), double(hi.z), scratch_procs_.data(), &procs,
                                scratch_parts_.data(), &parts),
        "Zoltan_LB_Box_PP_Assign");
  ranks.assign(scratch_procs_.begin(), scratch_procs_.begin() + procs);
}

}  // namespace upf
