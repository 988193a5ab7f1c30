#include "env/collision_checker.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include "env/fcl_shapes.h"

namespace colav {

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
        PlanarTransform(circle.center)));
  }
  for (const MovingObstacle& vessel : vessels) {
    shapes_->vessels.push_back(std::make_unique<fcl::CollisionObjectd>(
        FclPrism(vessel.hull()), PlanarTransform(vessel.hull().bound_center)));
  }
}

bool CollisionChecker::Collides(const Eigen::Vector2d& position,
                                const std::vector<MovingObstacle>& vessels) {
  const fcl::CollisionObjectd disc(shapes_->vessel, PlanarTransform(position));
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
