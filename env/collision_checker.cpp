#include "env/collision_checker.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

namespace colav {
namespace {

// Prism height: any value well above the vessel sphere's diameter works.
constexpr double kPrismHeight = 10.0;

fcl::Transform3d PlanarTranslation(const Eigen::Vector2d& position) {
  fcl::Transform3d transform = fcl::Transform3d::Identity();
  transform.translation() = Eigen::Vector3d(position.x(), position.y(), 0.0);
  return transform;
}

// A pentagonal prism of a hull, vertices relative to the obstacle position.
std::shared_ptr<fcl::Convexd> PrismOf(const ConvexPolygon& hull) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  const int n = hull.size;
  for (const double z : {-kPrismHeight / 2.0, kPrismHeight / 2.0}) {
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d v = hull.vertices[k] - hull.bound_center;
      vertices->emplace_back(v.x(), v.y(), z);
    }
  }
  // Faces: [count, indices...]; bottom, top, then one quad per edge.
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

}  // namespace

struct CollisionChecker::Shapes {
  std::shared_ptr<fcl::Sphered> vessel;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> circles;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> vessels;
};

CollisionChecker::CollisionChecker(double vessel_radius)
    : vessel_radius_(vessel_radius), shapes_(std::make_unique<Shapes>()) {
  shapes_->vessel = std::make_shared<fcl::Sphered>(vessel_radius);
}

CollisionChecker::~CollisionChecker() = default;
CollisionChecker::CollisionChecker(CollisionChecker&&) noexcept = default;
CollisionChecker& CollisionChecker::operator=(CollisionChecker&&) noexcept = default;

void CollisionChecker::Load(const std::vector<CircleSpec>& circles,
                            const std::vector<MovingObstacle>& vessels) {
  circles_ = circles;
  shapes_->circles.clear();
  shapes_->vessels.clear();
  for (const CircleSpec& circle : circles) {
    shapes_->circles.push_back(std::make_unique<fcl::CollisionObjectd>(
        std::make_shared<fcl::Cylinderd>(circle.radius, kPrismHeight),
        PlanarTranslation(circle.center)));
  }
  for (const MovingObstacle& vessel : vessels) {
    shapes_->vessels.push_back(std::make_unique<fcl::CollisionObjectd>(
        PrismOf(vessel.hull()), PlanarTranslation(vessel.hull().bound_center)));
  }
}

bool CollisionChecker::Collides(const Eigen::Vector2d& position,
                                const std::vector<MovingObstacle>& vessels) {
  const fcl::CollisionObjectd disc(shapes_->vessel, PlanarTranslation(position));
  const fcl::CollisionRequestd request;
  const auto overlaps = [&](const fcl::CollisionObjectd& obstacle) {
    fcl::CollisionResultd result;
    return fcl::collide(&disc, &obstacle, request, result) > 0;
  };
  for (std::size_t k = 0; k < circles_.size(); ++k) {
    const double reach = circles_[k].radius + vessel_radius_;
    if ((circles_[k].center - position).squaredNorm() < reach * reach &&
        overlaps(*shapes_->circles[k])) {
      return true;
    }
  }
  for (std::size_t k = 0; k < vessels.size(); ++k) {
    const ConvexPolygon& hull = vessels[k].hull();
    const double reach = hull.bound_radius + vessel_radius_;
    if ((hull.bound_center - position).squaredNorm() >= reach * reach) continue;
    fcl::CollisionObjectd& obstacle = *shapes_->vessels[k];
    obstacle.setTranslation(Eigen::Vector3d(hull.bound_center.x(), hull.bound_center.y(), 0.0));
    obstacle.computeAABB();
    if (overlaps(obstacle)) return true;
  }
  return false;
}

}  // namespace colav
