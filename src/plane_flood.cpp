#include "floodplane/plane_flood.h"

#include <algorithm>
#include <cmath>

namespace floodplane {

namespace {

// Eq. 4's hysteresis, as a fraction of the plane tolerance (see DistanceBuffer::fitsBetter).
constexpr float kTakeoverMargin = 0.25f;

// The membership test of one flood, as spanFloodFill's visitor.
class FloodVisitor {
 public:
  FloodVisitor(const PointGrid& grid, std::int32_t label, DistanceBuffer& buffer, std::vector<Segment>& segments,
               std::vector<std::pair<std::size_t, std::size_t>>& frontier, std::vector<std::int32_t>& neighbour_mark,
               std::vector<SegmentEdge>& edges, std::size_t first_refit, double seed_uncertainty,
               double angular_threshold)
      : grid_(grid),
        label_(label),
        buffer_(buffer),
        segments_(segments),
        frontier_(frontier),
        neighbour_mark_(neighbour_mark),
        edges_(edges),
        self_(segments[label]),
        criterion_(segments[label].criterion),
        next_refit_(static_cast<double>(first_refit)),
        uncertainty_(seed_uncertainty),
        same_plane_cosine_(std::cos(static_cast<float>(angular_threshold))) {}

  // Eq. 1 with Eq. 4: `to` joins from its neighbour `from` when its point is a 3-D neighbour
  // of from's, lies within the plane tolerance and fits this plane better than its owner's.
  FLOODPLANE_ALWAYS_INLINE bool join(std::size_t from, std::size_t to) {
    ++attempts_;
    const std::int32_t owner = buffer_.label(to);
    if (owner == label_) return false;
    const Vec3 p = Vec3::load(grid_.point(from));
    const Vec3 q = Vec3::load(grid_.point(to));
    const float range_sq = noiseRangeSq(p, q);
    const FloodCriterion& c = criterion_;
    // Eq. 3; written so that a hole (NaN) fails it.
    if (!(squaredEuclideanDistance(p, q) < c.euclideanToleranceSq(range_sq))) return false;
    const float distance = planeDistance(c.normal, c.offset, q);  // Eq. 2
    const float tolerance = c.planeTolerance(range_sq);
    if (!(distance < tolerance)) {
      if (owner != 0) noteNeighbour(owner);
      frontier_.emplace_back(from, to);
      return false;
    }
    if (owner != 0) {
      if (!buffer_.fitsBetter(to, distance, takeoverMargin(owner, tolerance))) {  // Eq. 4
        noteNeighbour(owner);
        return false;
      }
      Segment& loser = segments_[owner];
      loser.sums.remove(q);
      loser.lost_pixels = true;
      ++taken_over_;
    }
    buffer_.claim(to, label_, distance);
    self_.sums.add(q);
    if (self_.sums.count >= next_refit_) {
      refit();
      next_refit_ *= 2.0;
    }
    return true;
  }

  // Called by the fill for every finished span: the segment's bounding box.
  void span(int y, int x_begin, int x_end) {
    PixelBox& box = self_.box;
    box.include(x_begin, y);
    box.include(x_end, y);
  }

  // The least-squares plane of the pixels collected so far replaces the current estimate
  // when its normal is more certain. That takes an area: the first spans of a flood are
  // single image rows, whose points lie on a line (or, with depth noise, on the fan of that
  // row's viewing rays), and a plane through them has an arbitrary tilt about the line.
  bool refit() {
    const PlaneFit fit = self_.sums.fit();
    const double uncertainty = normalUncertainty(fit, self_.sums.count);
    if (!(uncertainty < uncertainty_) || !facesSensor(fit.normal, fit.centroid)) return false;
    uncertainty_ = uncertainty;
    criterion_.normal = {static_cast<float>(fit.normal.x()), static_cast<float>(fit.normal.y()),
                         static_cast<float>(fit.normal.z())};
    criterion_.offset = static_cast<float>(fit.offset);
    self_.criterion = criterion_;
    return true;
  }

  std::size_t takenOver() const { return taken_over_; }

  // Eq. 4's hysteresis applies only between two estimates of one plane (normals within the
  // merge angle), where it stops noise from trading pixels by coin flip. Between different
  // planes the better fit wins outright, as in the paper: with a margin there, the band
  // along a crease where both planes fit within the margin stays with whichever flood came
  // first, and that one-pixel band can cut a third plane in two (a floor flooded across by a
  // ramp's plane along their junction line).
  float takeoverMargin(std::int32_t owner, float tolerance) const {
    const Vec3& mine = criterion_.normal;
    const Vec3& theirs = segments_[owner].criterion.normal;
    return std::abs(mine.dot(theirs)) >= same_plane_cosine_ ? kTakeoverMargin * tolerance : 0.0f;
  }
  std::size_t attempts() const { return attempts_; }

 private:
  void noteNeighbour(std::int32_t owner) {
    if (neighbour_mark_[owner] == label_) return;
    neighbour_mark_[owner] = label_;
    edges_.emplace_back(label_, owner);
  }

  const PointGrid& grid_;
  const std::int32_t label_;
  DistanceBuffer& buffer_;
  std::vector<Segment>& segments_;
  std::vector<std::pair<std::size_t, std::size_t>>& frontier_;
  std::vector<std::int32_t>& neighbour_mark_;
  std::vector<SegmentEdge>& edges_;
  Segment& self_;             // segments_[label_]; the vector does not grow during a flood
  FloodCriterion criterion_;  // self_.criterion, read on every join; refit() keeps both in step
  double next_refit_;
  double uncertainty_;  // of the current normal [rad]
  const float same_plane_cosine_;
  std::size_t taken_over_ = 0;
  std::size_t attempts_ = 0;
};

}  // namespace

std::size_t PlaneFlood::grow(const PointGrid& grid, const Seed& seed, std::int32_t label, const Params& params,
                             DistanceBuffer& buffer, std::vector<Segment>& segments,
                             std::vector<SegmentEdge>& edges) {
  if (neighbour_mark_.size() < segments.size()) neighbour_mark_.resize(segments.size(), 0);

  Segment& segment = segments[label];
  FloodCriterion& criterion = segment.criterion;
  criterion.normal = seed.normal;
  criterion.offset = -seed.normal.dot(seed.point);
  criterion.plane_threshold = static_cast<float>(params.distance_threshold);
  criterion.plane_noise_factor = static_cast<float>(3.0 * params.depth_noise_coefficient);
  criterion.setEuclidean(seed.spacing, seed.point.squaredNorm(), static_cast<float>(params.depth_noise_coefficient));

  buffer.claim(seed.index, label, 0.0f);
  segment.sums.add(seed.point);
  const int width = grid.width;
  const int seed_x = static_cast<int>(seed.index % static_cast<std::size_t>(width));
  const int seed_y = static_cast<int>(seed.index / static_cast<std::size_t>(width));
  segment.box.include(seed_x, seed_y);

  frontier_.clear();
  const std::size_t first_refit = std::max<std::size_t>(16, static_cast<std::size_t>(seed.rho) * seed.rho);
  FloodVisitor visitor(grid, label, buffer, segments, frontier_, neighbour_mark_, edges, first_refit,
                       std::max(static_cast<double>(seed.normal_uncertainty), 1e-4), params.angular_threshold);
  spanFloodFill(width, grid.height, seed_x, seed_y, visitor, shadows_);

  // Give the pixels rejected under an earlier plane estimate a second chance.
  for (int round = 0; round < kFrontierRounds && !frontier_.empty(); ++round) {
    if (!visitor.refit()) break;  // the plane did not change
    retest_.swap(frontier_);
    frontier_.clear();
    bool grew = false;
    for (const auto& [from, to] : retest_) {
      if (!visitor.join(from, to)) continue;
      grew = true;
      spanFloodFill(width, grid.height, static_cast<int>(to % static_cast<std::size_t>(width)),
                    static_cast<int>(to / static_cast<std::size_t>(width)), visitor, shadows_);
    }
    if (!grew) break;
  }
  join_attempts_ = visitor.attempts();
  return visitor.takenOver();
}

}  // namespace floodplane
