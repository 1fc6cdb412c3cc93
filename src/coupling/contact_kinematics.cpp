// Contact kinematics of eq. 20. As printed, eq. 20 projects with n^T; the contact parameter along F -> S
// needs the unit tangent (n . (r_inv - O - r_F) is zero by construction of the overlap O along n), see
// docs/coupling.md.
#include "halfeti/coupling/contact_kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "halfeti/core/error.hpp"

namespace halfeti::coupling {

SegmentProjection project_on_segment(const Eigen::Vector2d& x, const Eigen::Vector2d& first,
                                     const Eigen::Vector2d& second) {
  SegmentProjection p;
  const Eigen::Vector2d d = second - first;
  p.length = d.norm();
  HALFETI_CHECK(p.length > 0.0, "degenerate surface segment (zero length)");
  p.tangent = d / p.length;
  p.normal = turned_clockwise(p.tangent);  // outward for a CCW surface
  const Eigen::Vector2d r = x - first;
  p.eta = p.tangent.dot(r) / p.length;  // eq. 20 (tangent reading)
  p.gap = p.normal.dot(r);
  const double clamped = std::clamp(p.eta, 0.0, 1.0);
  p.distance = (x - ((1.0 - clamped) * first + clamped * second)).norm();
  return p;
}

namespace {
// The scan's rule, shared by both searches: the nearer segment wins; at equal distance the one the point stands
// further in front of (the larger gap).
void keep_closer(ContactPoint& best, int k, const SegmentProjection& p) {
  const bool closer = best.segment < 0 || p.distance < best.projection.distance;
  const bool tie_in_front =
      best.segment >= 0 && p.distance == best.projection.distance && p.gap > best.projection.gap;
  if (closer || tie_in_front) {
    best.segment = k;
    best.projection = p;
  }
}
}  // namespace

ContactPoint closest_segment(const SurfacePolyline& surface, const Eigen::Vector2d& x) {
  ContactPoint best;
  for (int k = 0; k < surface.segment_count(); ++k) {
    keep_closer(best, k, project_on_segment(x, surface.points[k], surface.points[k + 1]));
  }
  return best;
}

BoundingBox bounding_box(const SurfacePolyline& surface) {
  BoundingBox b;
  if (surface.points.empty()) return b;
  b.lo = b.hi = surface.points.front();
  for (const auto& p : surface.points) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

SurfaceSearch::SurfaceSearch(const SurfacePolyline& surface, double reach)
    : surface_(surface), reach_(reach), box_(bounding_box(surface)) {
  for (int first = 0; first < surface.segment_count(); first += kRun) {
    const int last = std::min(first + kRun, surface.segment_count());  // points first .. last
    BoundingBox b;
    b.lo = b.hi = surface.points[first];
    for (int k = first; k <= last; ++k) {
      b.lo = b.lo.cwiseMin(surface.points[k]);
      b.hi = b.hi.cwiseMax(surface.points[k]);
    }
    runs_.push_back(b);
  }
}

ContactPoint SurfaceSearch::closest_within_reach(const Eigen::Vector2d& x) const {
  ContactPoint best;
  if (!box_.contains(x, reach_)) return best;
  // Same scan and tie-breaking as closest_segment(), over the runs that can hold a point within reach.
  for (std::size_t r = 0; r < runs_.size(); ++r) {
    if (!runs_[r].contains(x, reach_)) continue;
    const int first = static_cast<int>(r) * kRun;
    const int last = std::min(first + kRun, surface_.segment_count());
    for (int k = first; k < last; ++k) {
      keep_closer(best, k, project_on_segment(x, surface_.points[k], surface_.points[k + 1]));
    }
  }
  if (best.segment >= 0 && best.projection.distance > reach_) best = ContactPoint{};
  return best;
}

}  // namespace halfeti::coupling
