// A triangle soup with shared vertices: what every mesh file becomes once loaded. Host-side
// geometry, so Eigen doubles (particles use Real and Vec3).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace upf {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  // Vertex indices, counter-clockwise seen from the side the normal points to.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // The file it came from (or what made it): error messages name it.
  std::string source;
};

// (b - a) x (c - a): normal direction by the winding, length twice the triangle's area.
Eigen::Vector3d triangle_area_vector(const TriangleMesh& mesh, std::size_t triangle);
double triangle_area(const TriangleMesh& mesh, std::size_t triangle);
double surface_area(const TriangleMesh& mesh);
Eigen::AlignedBox3d bounding_box(const TriangleMesh& mesh);

// Reverses every triangle's winding (turns the normals around).
void flip_winding(TriangleMesh& mesh);

}  // namespace upf
