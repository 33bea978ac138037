#include "core/io/mesh_inside.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace amls {

double winding_number(const TriangleMesh& mesh, const Vec<3>& x) {
  double solid_angle = 0.0;
  for (const auto& t : mesh.triangles) {
    // Van Oosterom and Strackee's formula for the solid angle of a triangle.
    const Vec<3> a = mesh.vertices[t[0]] - x, b = mesh.vertices[t[1]] - x, c = mesh.vertices[t[2]] - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return solid_angle / (4.0 * std::numbers::pi);
}

}  // namespace amls
