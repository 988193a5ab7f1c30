// Length along a polyline to its point nearest a query point (GEOS `project` semantics:
// global search, first segment on ties, projection clamped to the segment).
//
// The brute-force search costs O(vertices) (~4000 for a training path) on every step; here the
// segments are grouped in blocks with bounding boxes and only blocks whose box could hold a
// segment at least as near as the best one found are searched. The answer is the brute-force
// answer: blocks are pruned only when their lower bound is strictly worse.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace colav {

class PolylineProjector {
 public:
  explicit PolylineProjector(std::vector<Eigen::Vector2d> vertices);

  /// Length along the polyline to the nearest point to `point`.
  double Project(const Eigen::Vector2d& point) const;
  /// The same by testing every segment (reference implementation, for tests and benchmarks).
  double ProjectBruteForce(const Eigen::Vector2d& point) const;

  double length() const { return cumulative_.back(); }
  const std::vector<Eigen::Vector2d>& vertices() const { return vertices_; }

 private:
  struct Block {
    Eigen::Vector2d lower;
    Eigen::Vector2d upper;
    std::size_t first_segment;
    std::size_t end_segment;
  };
  struct Candidate {
    double distance_squared;
    double measure;
  };

  Candidate SegmentCandidate(std::size_t segment, const Eigen::Vector2d& point) const;
  /// Updates `best` with the segments of one block (strictly nearer wins: first on ties).
  void SearchBlock(const Block& block, const Eigen::Vector2d& point, Candidate& best) const;

  std::vector<Eigen::Vector2d> vertices_;
  std::vector<double> cumulative_;  ///< length from the start to each vertex
  std::vector<Block> blocks_;
};

}  // namespace colav
