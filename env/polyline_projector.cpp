#include "env/polyline_projector.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace colav {
namespace {

// Segments per block: about sqrt(4000), balancing box tests against segment tests.
constexpr std::size_t kSegmentsPerBlock = 32;
// Relative and absolute slack (m^2) for comparing box bounds with computed distances.
constexpr double kRoundingMargin = 1e-9;

double BoxDistanceSquared(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper,
                          const Eigen::Vector2d& p) {
  const double dx = std::max({lower.x() - p.x(), 0.0, p.x() - upper.x()});
  const double dy = std::max({lower.y() - p.y(), 0.0, p.y() - upper.y()});
  return dx * dx + dy * dy;
}

}  // namespace

PolylineProjector::PolylineProjector(std::vector<Eigen::Vector2d> vertices)
    : vertices_(std::move(vertices)) {
  if (vertices_.size() < 2) throw std::invalid_argument("PolylineProjector: need 2 vertices");
  cumulative_.resize(vertices_.size());
  cumulative_[0] = 0.0;
  for (std::size_t k = 1; k < vertices_.size(); ++k) {
    cumulative_[k] = cumulative_[k - 1] + (vertices_[k] - vertices_[k - 1]).norm();
  }
  const std::size_t segments = vertices_.size() - 1;
  for (std::size_t first = 0; first < segments; first += kSegmentsPerBlock) {
    Block block{vertices_[first], vertices_[first], first,
                std::min(first + kSegmentsPerBlock, segments)};
    for (std::size_t k = first; k <= block.end_segment; ++k) {
      block.lower = block.lower.cwiseMin(vertices_[k]);
      block.upper = block.upper.cwiseMax(vertices_[k]);
    }
    blocks_.push_back(block);
  }
}

PolylineProjector::Candidate PolylineProjector::SegmentCandidate(std::size_t segment,
                                                                 const Eigen::Vector2d& p) const {
  const Eigen::Vector2d& a = vertices_[segment];
  const Eigen::Vector2d& b = vertices_[segment + 1];
  const Eigen::Vector2d ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double start = cumulative_[segment];
  if (length_squared == 0.0) return {(p - a).squaredNorm(), start};
  const double factor = (p - a).dot(ab) / length_squared;
  if (factor <= 0.0) return {(p - a).squaredNorm(), start};
  if (factor >= 1.0) return {(p - b).squaredNorm(), start + std::sqrt(length_squared)};
  const double cross = (a.y() - p.y()) * ab.x() - (a.x() - p.x()) * ab.y();
  return {cross * cross / length_squared, start + factor * std::sqrt(length_squared)};
}

void PolylineProjector::SearchBlock(const Block& block, const Eigen::Vector2d& p,
                                    Candidate& best) const {
  for (std::size_t k = block.first_segment; k < block.end_segment; ++k) {
    const Candidate candidate = SegmentCandidate(k, p);
    if (candidate.distance_squared < best.distance_squared) best = candidate;
  }
}

double PolylineProjector::Project(const Eigen::Vector2d& p) const {
  // Pass 1: the block with the smallest bound gives an achievable distance. (Bounds are
  // recomputed in pass 2 rather than stored: cheaper than allocating on every step.)
  std::size_t nearest_block = 0;
  double nearest_bound = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const double bound = BoxDistanceSquared(blocks_[b].lower, blocks_[b].upper, p);
    if (bound < nearest_bound) {
      nearest_bound = bound;
      nearest_block = b;
    }
  }
  Candidate achievable{std::numeric_limits<double>::infinity(), 0.0};
  SearchBlock(blocks_[nearest_block], p, achievable);
  // Pass 2: in segment order, so the first of equally near segments wins as in GEOS. A block
  // is skipped only when its bound exceeds the achievable distance by more than the rounding
  // of the segment-distance formula (on a straight path the two are mathematically equal).
  const double limit = achievable.distance_squared * (1.0 + kRoundingMargin) + kRoundingMargin;
  Candidate best{std::numeric_limits<double>::infinity(), 0.0};
  for (const Block& block : blocks_) {
    if (BoxDistanceSquared(block.lower, block.upper, p) <= limit) {
      SearchBlock(block, p, best);
    }
  }
  return best.measure;
}

double PolylineProjector::ProjectBruteForce(const Eigen::Vector2d& p) const {
  Candidate best{std::numeric_limits<double>::infinity(), 0.0};
  for (std::size_t k = 0; k + 1 < vertices_.size(); ++k) {
    const Candidate candidate = SegmentCandidate(k, p);
    if (candidate.distance_squared < best.distance_squared) best = candidate;
  }
  return best.measure;
}

}  // namespace colav
