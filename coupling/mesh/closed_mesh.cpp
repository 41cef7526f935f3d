#include "coupling/mesh/closed_mesh.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "coupling/mesh/mesh_error.h"

namespace upf {

namespace {
struct DirectedEdge {
  std::uint32_t low, high;  // the undirected edge
  bool forward;             // runs low -> high
  auto operator<=>(const DirectedEdge&) const = default;
};
}  // namespace

ClosedMeshReport check_closed(const TriangleMesh& mesh) {
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t from = t[std::size_t(k)], to = t[std::size_t((k + 1) % 3)];
      edges.push_back({std::min(from, to), std::max(from, to), from < to});
    }
  std::sort(edges.begin(), edges.end());  // the uses of one edge become neighbours

  ClosedMeshReport report;
  for (std::size_t begin = 0; begin < edges.size();) {
    std::size_t end = begin + 1;
    while (end < edges.size() && edges[end].low == edges[begin].low &&
           edges[end].high == edges[begin].high)
      ++end;
    const std::size_t uses = end - begin;
    if (uses == 1) {
      ++report.boundary_edges;
    } else if (uses > 2) {
      ++report.non_manifold_edges;
    } else if (edges[begin].forward == edges[begin + 1].forward) {
      ++report.misoriented_edges;
    }
    begin = end;
  }
  return report;
}

void require_closed(const TriangleMesh& mesh, const std::string& where) {
  const ClosedMeshReport report = check_closed(mesh);
  if (report.closed()) return;
  std::string what = "is not a closed, consistently oriented surface, which a dynamic body needs:";
  auto count = [&what](std::size_t n, const char* kind) {
    if (n) what += " " + std::to_string(n) + " " + kind + ";";
  };
  count(report.boundary_edges, "edges used by one triangle only (holes)");
  count(report.non_manifold_edges, "edges shared by more than two triangles");
  count(report.misoriented_edges, "edges whose two triangles have opposite windings");
  what.pop_back();
  throw mesh_error(mesh.source, where, what);
}

}  // namespace upf
