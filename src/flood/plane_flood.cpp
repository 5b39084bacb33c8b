// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "flood/plane_flood.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/lane_sums.h"
#include "util/simd.h"

namespace floodplane {

namespace {

// Eq. 4's hysteresis, as a fraction of the plane tolerance (see DistanceBuffer::fitsBetter).
constexpr float kTakeoverMargin = 0.25f;

// Pixels a flood tests at once along a row (one SSE register of floats): a group of four.
constexpr int kGroup = 4;

// When a flood refits its plane: first at `first` pixels, then at each doubling, and only
// where the refit's normal is more certain than the current one's (`uncertainty` [rad]).
struct RefitSchedule {
  std::size_t first;
  double uncertainty;
};

// A flood's scratch that outlives it: the pixels rejected under the current plane, and per
// segment the last flood that noted it as a neighbour.
struct FloodScratch {
  std::vector<std::pair<std::size_t, std::size_t>>& frontier;
  std::vector<std::int32_t>& neighbour_mark;
};

// The membership test of one flood, as spanFloodFill's visitor.
class FloodVisitor {
 public:
  FloodVisitor(const PointGrid& grid, std::int32_t label, const FloodCriterion& criterion, FloodTarget target,
               FloodScratch scratch, RefitSchedule refits, double angular_threshold)
      : grid_(grid),
        in_groups_(fourPixelsAtATime(grid)),
        label_(label),
        buffer_(target.buffer),
        labels_(target.buffer.labels().data()),
        distances_(target.buffer.distances().data()),
        segments_(target.segments),
        frontier_(scratch.frontier),
        neighbour_mark_(scratch.neighbour_mark),
        edges_(target.edges),
        self_(target.segments[label]),
        criterion_(criterion),
        next_refit_(static_cast<double>(refits.first)),
        uncertainty_(refits.uncertainty),
        same_plane_cosine_(std::cos(static_cast<float>(angular_threshold))) {}

  // Eq. 1 with Eq. 4: `to` joins from its neighbour `from` when its point is a 3-D neighbour
  // of from's, lies within the plane tolerance and fits this plane better than its owner's.
  FLOODPLANE_ALWAYS_INLINE bool join(std::size_t from, std::size_t to) {
    const std::int32_t owner = buffer_.label(to);
    if (owner == label_) return false;
    const Vec3 p = Vec3::load(grid_.point(from));
    const Vec3 q = Vec3::load(grid_.point(to));
    const float range_sq = noiseRangeSq(p, q);
    const FloodCriterion& c = criterion_;
    // Eq. 3; written so that a hole (NaN) fails it.
    if (!(squaredEuclideanDistance(p, q) < c.euclideanToleranceSq(range_sq))) return false;
    float distance = 0.f;                       // along q's ray
    if (!c.fitsPlane(q, range_sq, distance)) {  // Eq. 2
      if (owner != 0) noteNeighbour(owner);
      frontier_.emplace_back(from, to);
      return false;
    }
    if (owner != 0) {
      if (!buffer_.fitsBetter(to, distance, takeoverMargin(owner, c.planeTolerance(range_sq)))) {  // Eq. 4
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

  // The fill's run along a row (see spanFloodFill): inside a plane, where most pixels are,
  // groups of kGroup pixels at once while all pixels of a group join the same way (see
  // joinGroup); pixel by pixel through join() elsewhere. Where a group's test fails at one
  // of its pixels, the pixels before it join as join() would take them, one by one, and
  // join() decides the failing pixel and the rest of the group: a span's end costs the group
  // and one join(). Labels, distances and refits come out as with join() alone; only the
  // order in which points are added to sums differs (a whole group is summed at once).
  FLOODPLANE_ALWAYS_INLINE int joinRun(std::size_t from, int step, int max) {
    int joined = 0;
    [[maybe_unused]] int pixel_by_pixel_until = 0;
    std::size_t pixel = from;
    while (joined < max) {
#if FLOODPLANE_SIMD
      // A group must not carry the count past the next refit, which join() makes at the
      // exact pixel.
      if (in_groups_ && joined >= pixel_by_pixel_until && max - joined >= kGroup &&
          self_.sums.count + kGroup < next_refit_) {
        const int taken = joinGroup(pixel, step);
        pixel = step > 0 ? pixel + static_cast<std::size_t>(taken) : pixel - static_cast<std::size_t>(taken);
        joined += taken;
        if (taken == kGroup) continue;
        pixel_by_pixel_until = joined + kGroup - taken;
      }
#endif
      const std::size_t next = step > 0 ? pixel + 1 : pixel - 1;
      if (!join(pixel, next)) break;
      pixel = next;
      ++joined;
    }
    return joined;
  }

  // Called by the fill for a shadow it will scan later: its points, labels and distances are
  // requested from memory now (a hint; 5-10 % of the flood's time on a real frame).
  void prefetch(std::size_t first, std::size_t last) const {
    prefetchRange(grid_.point(first), grid_.point(last) + 3);
    prefetchRange(labels_ + first, labels_ + last + 1);
    prefetchRange(distances_ + first, distances_ + last + 1);
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
    return samePlane(owner) ? kTakeoverMargin * tolerance : 0.0f;
  }
  bool samePlane(std::int32_t owner) const {
    return std::abs(criterion_.normal.dot(segments_[owner].criterion.normal)) >= same_plane_cosine_;
  }

 private:
#if FLOODPLANE_SIMD
  // join() for the kGroup pixels after `pixel` in direction `step`, each from its
  // predecessor, where every pixel is in the same state: all unclaimed, or all owned by one
  // other segment (a takeover under Eq. 4). Returns how many of them, in the order of the
  // walk, pass Eqs. 2, 3 (and 4) before the first that does not, and has claimed those as
  // join() would have; 0 where the pixels are not in the same state. Every float operation is
  // the one join() does, in the same order, so a lane passes exactly when join() would pass
  // its pixel.
  int joinGroup(std::size_t pixel, int step) {
    // Lane j tests pixel first + j from its neighbour first + j - step: the five points from
    // `low` on, as x, y, z across lanes (the fourth float of a point is readable: stride >= 4).
    const std::size_t first = step > 0 ? pixel + 1 : pixel - kGroup;
    const std::size_t low = step > 0 ? pixel : pixel - kGroup;
    // One owner for all four, not this flood: none (0), or a segment to take them from.
    const std::int32_t owner = labels_[first];
    if (owner == label_ || !allLabelsEqual(labels_ + first, owner)) return 0;

    const PointLanes lower = PointLanes::transpose(grid_.point(low), grid_.point(low + 1), grid_.point(low + 2),
                                                   grid_.point(low + 3));  // points low .. low + 3
    const PointLanes upper = PointLanes::transpose(grid_.point(low + 1), grid_.point(low + 2), grid_.point(low + 3),
                                                   grid_.point(low + 4));  // points low + 1 .. low + 4
    const PointLanes& q = step > 0 ? upper : lower;
    const PointLanes& p = step > 0 ? lower : upper;
    const Float4 range_sq = Float4::min(p.squaredNorm(), q.squaredNorm());  // noiseRangeSq
    const FloodCriterion& c = criterion_;
    // Eq. 3: |p - q|^2 < (K r^2) r^2. A NaN fails it, so no lane below has a NaN range.
    Mask4 pass = p.squaredDistance(q) < c.euclideanToleranceSq(range_sq);
    // Eq. 2, along the rays.
    Float4 distance;
    pass = pass & c.fitsPlane(q, range_sq, distance);
    if (owner != 0) {
      // Eq. 4 (DistanceBuffer::fitsBetter): distance + margin < D, the margin as takeoverMargin.
      const Float4 margin = Float4::broadcast(samePlane(owner) ? kTakeoverMargin : 0.0f) * c.planeTolerance(range_sq);
      pass = pass & (distance + margin < Float4::load(distances_ + first));
    }
    float distances[kGroup];
    distance.store(distances);
    if (pass.all()) {
      claimGroup(first, owner, q, distances);
      return kGroup;
    }
    // The pixels before the first that fails, in the order of the walk, as join() takes them.
    const int passing = step > 0 ? pass.leadingLanes() : pass.trailingLanes();
    for (int k = 0; k < passing; ++k) {
      const std::size_t lane = step > 0 ? static_cast<std::size_t>(k) : static_cast<std::size_t>(kGroup - 1 - k);
      const std::size_t to = first + lane;
      const Vec3 point = Vec3::load(grid_.point(to));
      if (owner != 0) {
        Segment& loser = segments_[owner];
        loser.sums.remove(point);
        loser.lost_pixels = true;
        ++taken_over_;
      }
      buffer_.claim(to, label_, distances[lane]);
      self_.sums.add(point);
    }
    return passing;
  }

  // Claims the kGroup pixels from `first` on, points `q`, at `distances`, from `owner` (0: none).
  void claimGroup(std::size_t first, std::int32_t owner, const PointLanes& q, const float* distances) {
    buffer_.claimRun(first, kGroup, label_, distances);
    LaneSums lanes;
    lanes.add(q);
    if (owner == 0) {
      lanes.addTo(self_.sums);
      return;
    }
    PlaneSums group;  // of the four points, once for both segments
    lanes.addTo(group);
    Segment& loser = segments_[owner];
    loser.sums.subtract(group);
    loser.lost_pixels = true;
    taken_over_ += kGroup;
    self_.sums.merge(group);
  }

#endif

  void noteNeighbour(std::int32_t owner) {
    if (neighbour_mark_[owner] == label_) return;
    neighbour_mark_[owner] = label_;
    edges_.emplace_back(label_, owner);
  }

  const PointGrid& grid_;
  const bool in_groups_;  // fourPixelsAtATime(grid_): rows are taken a group of four at a time
  const std::int32_t label_;
  DistanceBuffer& buffer_;
  const std::int32_t* labels_;  // buffer_'s, for the group test
  const float* distances_;      // buffer_'s
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
};

}  // namespace

std::size_t PlaneFlood::grow(const PointGrid& grid, const Seed& seed, std::int32_t label, const Params& params,
                             const Tolerances& tolerances, FloodTarget target) {
  DistanceBuffer& buffer = target.buffer;
  std::vector<Segment>& segments = target.segments;
  if (neighbour_mark_.size() < segments.size()) neighbour_mark_.resize(segments.size(), 0);

  Segment& segment = segments[label];
  // Eq. 8's spacing at the seed, as metres per r^2 (see FloodCriterion).
  const double spacing_per_range_sq =
      static_cast<double>(seed.spacing) / std::max(static_cast<double>(seed.point.squaredNorm()), 1e-12);
  segment.criterion = FloodCriterion::make(seed.normal, -seed.normal.dot(seed.point), seed.point.norm(),
                                           spacing_per_range_sq, tolerances);

  // A seed on a pixel another flood claimed (not from the seed scan, which takes only
  // unclaimed pixels) takes it from that segment.
  if (const std::int32_t owner = buffer.claim(seed.index, label, 0.0f); owner != 0) {
    segments[owner].sums.remove(seed.point);
    segments[owner].lost_pixels = true;
  }
  segment.sums.add(seed.point);
  const int width = grid.width;
  const int seed_x = static_cast<int>(seed.index % static_cast<std::size_t>(width));
  const int seed_y = static_cast<int>(seed.index / static_cast<std::size_t>(width));

  frontier_.clear();
  const std::size_t first_refit = std::max<std::size_t>(16, static_cast<std::size_t>(seed.rho) * seed.rho);
  FloodVisitor visitor(grid, label, segment.criterion, target, {frontier_, neighbour_mark_},
                       {first_refit, std::max(static_cast<double>(seed.normal_uncertainty), 1e-4)},
                       params.angular_threshold);
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
  return visitor.takenOver();
}

std::size_t PlaneFlood::extend(const PointGrid& grid, const std::vector<std::size_t>& starts, std::int32_t label,
                               const FloodCriterion& criterion, const Params& params, FloodTarget target) {
  if (neighbour_mark_.size() < target.segments.size()) neighbour_mark_.resize(target.segments.size(), 0);
  frontier_.clear();
  // No refit: the first would come at twice the pixels the segment has.
  FloodVisitor visitor(grid, label, criterion, target, {frontier_, neighbour_mark_},
                       {std::numeric_limits<std::size_t>::max(), 0.0}, params.angular_threshold);
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const std::int32_t* labels = target.buffer.labels().data();
  for (const std::size_t start : starts) {
    // A start whose neighbours are all the segment's already (the fill from an earlier start
    // took them) has nothing to look at.
    const int x = static_cast<int>(start % width), y = static_cast<int>(start / width);
    const bool open = (x > 0 && labels[start - 1] != label) || (x + 1 < grid.width && labels[start + 1] != label) ||
                      (y > 0 && labels[start - width] != label) ||
                      (y + 1 < grid.height && labels[start + width] != label);
    if (open) spanFloodFill(grid.width, grid.height, x, y, visitor, shadows_);
  }
  return visitor.takenOver();
}

}  // namespace floodplane
