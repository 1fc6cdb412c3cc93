// Particle-to-segment contact kinematics (eq. 20): where an SPH particle sits relative to the plate's
// deformed outer surface. The surface is the plate mesh's ordered polyline (right face up, top leftwards,
// left face down); the outward normal of a segment F -> S is its unit tangent turned clockwise.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace halfeti::coupling {

// The current outer surface: node positions along the polyline; segment k joins points[k] -> points[k + 1].
struct SurfacePolyline {
  std::vector<Eigen::Vector2d> points;
  std::vector<int> nodes;  // the structure node of each point (same length as points)
  int segment_count() const { return points.empty() ? 0 : static_cast<int>(points.size()) - 1; }
};

// The direction t turned clockwise: for a segment's direction F -> S, its outward normal (not normalised).
inline Eigen::Vector2d turned_clockwise(const Eigen::Vector2d& t) {
  return {t.y(), -t.x()};
}

// A particle projected onto one segment.
struct SegmentProjection {
  double eta = 0.0;     // eq. 20 with the tangent: t . (x - x_F) / l_e, not clamped (may leave [0, 1])
  double gap = 0.0;     // n . (x - x_F): < 0 past the surface
  double length = 0.0;  // l_e
  Eigen::Vector2d tangent = Eigen::Vector2d::Zero();  // (x_S - x_F) / l_e
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();   // tangent turned clockwise: outward
  double distance = 0.0;  // Euclidean distance to the closest point of the segment (eta clamped to [0, 1])
};

SegmentProjection project_on_segment(const Eigen::Vector2d& x, const Eigen::Vector2d& first,
                                     const Eigen::Vector2d& second);

// The contact partner of a particle: the closest segment of the polyline (ties, e.g. outside a convex corner
// where both neighbours are closest at their shared vertex, go to the segment with the larger gap, the face
// the particle is most clearly in front of). signed_distance is the gap of that segment: < 0 means inside.
struct ContactPoint {
  int segment = -1;
  SegmentProjection projection;
};

ContactPoint closest_segment(const SurfacePolyline& surface, const Eigen::Vector2d& x);

// Axis-aligned box of the polyline, for a cheap first test of the search.
struct BoundingBox {
  Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();
  bool contains(const Eigen::Vector2d& x, double margin) const {
    return x.x() >= lo.x() - margin && x.x() <= hi.x() + margin && x.y() >= lo.y() - margin &&
           x.y() <= hi.y() + margin;
  }
};
BoundingBox bounding_box(const SurfacePolyline& surface);

// closest_segment() for particles near the surface, fast: segments are grouped in runs of consecutive ones
// with their boxes, and runs whose box is farther than `reach` are skipped. When the particle is within
// `reach` of the surface the result is exactly closest_segment()'s (same segment, same tie-breaking);
// otherwise segment = -1.
class SurfaceSearch {
 public:
  SurfaceSearch(const SurfacePolyline& surface, double reach);
  ContactPoint closest_within_reach(const Eigen::Vector2d& x) const;
  const BoundingBox& box() const { return box_; }

 private:
  static constexpr int kRun = 8;
  const SurfacePolyline& surface_;
  double reach_;
  BoundingBox box_;
  std::vector<BoundingBox> runs_;
};

}  // namespace halfeti::coupling
