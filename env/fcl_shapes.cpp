#include "env/fcl_shapes.h"

#include <vector>

namespace colav {

std::shared_ptr<fcl::Convexd> FclPrism(const ConvexPolygon& polygon) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  const int n = polygon.size;
  for (const double z : {-kPrismHeight / 2.0, kPrismHeight / 2.0}) {
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d v = polygon.vertices[k] - polygon.bound_center;
      vertices->emplace_back(v.x(), v.y(), z);
    }
  }
  // Faces: [count, indices...]: bottom, top (reversed), then one quad per edge.
  auto faces = std::make_shared<std::vector<int>>();
  faces->push_back(n);
  for (int k = 0; k < n; ++k) faces->push_back(k);
  faces->push_back(n);
  for (int k = n - 1; k >= 0; --k) faces->push_back(n + k);
  for (int k = 0; k < n; ++k) {
    const int next = (k + 1) % n;
    faces->insert(faces->end(), {4, k, next, n + next, n + k});
  }
  return std::make_shared<fcl::Convexd>(vertices, n + 2, faces);
}

fcl::Transform3d PlanarTransform(const Eigen::Vector2d& position) {
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.translation() = Eigen::Vector3d(position.x(), position.y(), 0.0);
  return transform;
}

}  // namespace colav
