// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/segmenter.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "stages/block_grid.h"
#include "stages/depth_smoothing.h"
#include "stages/leftover_seeds.h"
#include "stages/noise_estimator.h"
#include "stages/plane_flood.h"
#include "stages/plane_merger.h"
#include "stages/prepared_frame.h"
#include "stages/region_builder.h"
#include "stages/relabelling.h"
#include "stages/seed_selector.h"
#include "stages/segment_borders.h"
#include "util/distance_buffer.h"

namespace floodplane {

namespace {

// Seed candidates are every kSeedStride-th pixel of every kSeedStride-th row at full
// resolution, not every pixel as in the paper: a plane worth reporting is many strides
// wide, and this cuts the cost of testing the pixels no flood claims (clutter, curved
// surfaces, borders) sixteen-fold (as DDPFF's sparse seed grid). Sub-sampled grids use a
// proportionally smaller stride.
constexpr int kSeedStride = 4;

// Beyond the paper: a second, finer seeding pass over the pixels the first one left
// unclaimed, with a seed cube of sigma_seed / kFineSeedDivisor. sigma_seed = 6 cm keeps
// seeds off edges and out of noise, but it also means no plane narrower than about 6 cm can
// ever be seeded: table legs, shelf fronts, stair risers seen from above. After the first
// pass every large plane is already claimed, so the small seeds only see what is left;
// the noise-widened seed size (SeedSelector::seedSizeAt) still keeps them out of noise.
constexpr double kFineSeedDivisor = 2.0;
// On noise-free frames nothing fakes a small plane, and the second pass seeds with a third of
// the cube: a 3 cm edge 1.5 m from a Kinect-like camera is five pixels high.
constexpr double kNoiseFreeFineSeedDivisor = 3.0;

using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Accumulates the time of a phase when measuring is on; otherwise does nothing.
class PhaseTimer {
 public:
  PhaseTimer(bool enabled, double& total) : enabled_(enabled), total_(total) {
    if (enabled_) start_ = Clock::now();
  }
  ~PhaseTimer() {
    if (enabled_) total_ += millisecondsSince(start_);
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  bool enabled_;
  double& total_;
  Clock::time_point start_;
};

// What the floods leave, relabelled: a segment per pixel of the segmented grid (0 none), each
// segment's sums and plane, and the pairs of segments that touch. Views of the workspace's
// buffers.
struct SegmentImage {
  std::vector<std::int32_t>& labels;
  std::vector<Segment>& segments;
  std::vector<SegmentEdge>& edges;
};

// What a head start (Segmenter::Options::head_start) takes from the last frame: its noise.
struct PreviousFrame {
  bool valid = false;  // the last call completed with the current parameters
  int width = 0;
  int height = 0;
  NoiseModel noise;            // measured on the raw frame
  NoiseModel segment_noise;    // measured on the smoothed frame
  int frames_since_noise = 0;  // frames since the noise was last measured

  bool continuedBy(const PointGrid& grid) const { return valid && width == grid.width && height == grid.height; }
};

}  // namespace

struct Segmenter::Workspace {
  BlockGrid blocks;  // s > 1
  std::vector<float> pitch_scratch;
  NoiseEstimator noise_estimator;
  HoleFilling holes;
  DepthSmoothing smoothing;
  DistanceBuffer buffer;
  SeedSelector selector;
  SeedSelector fine_selector;  // the second pass's smaller seed cube
  LeftoverSeeds leftover;      // the third pass's: regions no seed reached
  PlaneFlood flood;
  std::vector<Segment> segments;
  std::vector<SegmentEdge> edges;
  Relabelling relabelling;
  SegmentBorders borders;
  PlaneMerger merger;
  std::vector<PlaneSums> cluster_sums;
  RegionBuilder regions;
  PreviousFrame previous;

  // The frame as the stages segment it, and every buffer reset for it. With `reuse_noise`, the
  // previous frame's noise models stand in for the measurements: the noise belongs to the
  // sensor, not the scene.
  PreparedFrame prepare(const PointGrid& full, const Params& params, bool reuse_noise, NoiseModel& noise) {
    PreparedFrame frame;
    const int s = params.subsampling;
    frame.measured = full;
    frame.subsampling = s;
    frame.full_pitch = SeedSelector::estimateAngularPitch(full, pitch_scratch);
    frame.pitch = frame.full_pitch * static_cast<float>(s);
    noise = reuse_noise ? previous.noise : s == 1 || !params.estimatesNoise() ? noiseModel(full, params) : NoiseModel();
    frame.pixel_tolerances = Tolerances(params, noise, frame.full_pitch, full.size());
    NoiseModel segment_noise = noise;
    if (s == 1) {
      const PointGrid& filled = holes.fill(full, frame.pixel_tolerances);
      // The smoothed frame, and its own noise (the smoothing's gain depends on how correlated
      // the sensor's noise is: a third of it on the Kinect model, a quarter less on a real
      // Kinect). A noise model the user gives describes the raw data: no smoothing then; nor
      // on exact depths rounded to a lattice (roundingOnly).
      frame.grid = filled;
      if (params.estimatesNoise() && !negligibleAgainstPixels(noise, frame.full_pitch) && !roundingOnly(noise)) {
        frame.grid = smoothing.smooth(filled, noise);
        segment_noise = reuse_noise ? previous.segment_noise : noise_estimator.estimate(frame.grid);
      }
    } else {
      // Coarse to fine: the frame read once into s x s blocks, whose means are segmented (their
      // averaging is the smoothing), with the noise of those means. The pixels' own noise
      // follows from it: a mean of s^2 pixels of independent noise has 1/s of theirs (more
      // where the noise is correlated, which widens the pixels' band).
      blocks.read(full, s);
      frame.blocks = &blocks;
      if (params.estimatesNoise()) {
        const int spacing = std::max(1, NoiseEstimator::kPatchSpacing / s);
        segment_noise = reuse_noise ? previous.segment_noise : noise_estimator.estimate(blocks.means(), spacing);
        noise = segment_noise;
        noise.sigma_constant *= s;
        noise.sigma_quadratic *= s;
        frame.pixel_tolerances = Tolerances(params, noise, frame.full_pitch, full.size());
      }
      blocks.separateSurfaces(full, noise, frame.full_pitch);
      frame.grid = holes.fill(blocks.means(), Tolerances(params, segment_noise, frame.pitch, full.size()));
    }
    frame.holes = &holes;
    frame.tolerances = Tolerances(params, segment_noise, frame.pitch, full.size());
    selector.configure(params, frame.tolerances, 1.0, frame.pitch, frame.grid.width, frame.grid.height);
    fine_selector.configure(
        params, frame.tolerances,
        1.0 / (negligibleAgainstPixels(segment_noise, frame.full_pitch) ? kNoiseFreeFineSeedDivisor : kFineSeedDivisor),
        frame.pitch, frame.grid.width, frame.grid.height);
    buffer.reset(frame.grid.size());
    segments.assign(1, Segment());  // label 0: no segment
    edges.clear();
    flood.beginFrame();
    return frame;
  }

  // Seed selection (Sec. III-C) interleaved with flooding (Sec. III-A, III-B), in scan order:
  // every candidate still unclaimed when the scan reaches it is tested, and a seed floods at
  // once.
  SegmentImage seedAndFlood(const PreparedFrame& frame, const Params& params, bool timed, Segmentation& result) {
    const Clock::time_point scan_start = timed ? Clock::now() : Clock::time_point();
    double flooding = 0.0;
    const PointGrid& grid = frame.grid;
    const int stride = std::max(1, kSeedStride / params.subsampling);
    const int offset = stride / 2;
    // A new segment flooded from an accepted seed.
    const auto floodFrom = [&](const Seed& accepted) {
      ++result.stats.seeds;
      const std::int32_t label = static_cast<std::int32_t>(segments.size());
      segments.emplace_back();
      PhaseTimer timer(timed, flooding);
      result.stats.pixels_taken_over +=
          flood.grow(grid, accepted, label, params, frame.tolerances, buffer, segments, edges);
    };
    Seed seed;
    for (const SeedSelector* seeds : {&selector, &fine_selector}) {
      for (int y = offset; y < grid.height; y += stride) {
        for (int x = offset; x < grid.width; x += stride) {
          const std::size_t pixel =
              static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) + static_cast<std::size_t>(x);
          if (buffer.label(pixel) != 0) continue;
          ++result.stats.seed_candidates;
          if (seeds->test(grid, x, y, seed) == SeedVerdict::kAccepted) floodFrom(seed);
        }
      }
    }
    // Regions of unclaimed points large enough to be a plane: faces narrower than any seed
    // cross (LeftoverSeeds).
    const std::size_t min_pixels =
        frame.tolerances.minInliers() / static_cast<std::size_t>(params.subsampling * params.subsampling);
    for (const Seed& leftover_seed : leftover.find(grid, buffer, frame.tolerances, min_pixels)) {
      if (buffer.label(leftover_seed.index) == 0) floodFrom(leftover_seed);  // else an earlier one's flood took it
    }
    if (timed) {
      result.phases.flood_fill += flooding;
      result.phases.seed_selection += millisecondsSince(scan_start) - flooding;
    }
    return {buffer.labels(), segments, edges};
  }

  // Sec. III-B, after the floods: segments that takeovers cut apart become one per piece.
  void relabel(const PreparedFrame& frame, int subsampling, SegmentImage& image) {
    relabelling.run(frame.grid, subsampling, image.labels, image.segments, image.edges);
  }

  // Sec. III-D over the segment graph, and across the borders where a bent surface was cut:
  // the clusters of segments, each with its whole sums.
  MergedSegments merge(const PreparedFrame& frame, const MergeCriterion& criterion, const SegmentImage& image) {
    borders.collect(frame.grid, image.labels, image.segments);
    merger.reset(image.segments.size());
    for (const SegmentEdge& edge : image.edges) merger.addEdge(edge.first, edge.second);
    cluster_sums.resize(image.segments.size());
    for (std::size_t i = 0; i < image.segments.size(); ++i) cluster_sums[i] = image.segments[i].sums;
    merger.merge(cluster_sums, criterion, borders.mutableBorders());
    MergedSegments clusters;
    clusters.labels = image.labels.data();
    clusters.root = merger.rootData();
    clusters.sums = cluster_sums.data();
    clusters.segment_count = image.segments.size();
    return clusters;
  }

  // The noise model: measured on the full-resolution grid unless the parameters fix it.
  NoiseModel noiseModel(const PointGrid& full, const Params& params) {
    if (params.estimatesNoise()) return noise_estimator.estimate(full);
    NoiseModel model;
    model.sigma_constant = params.depth_noise_constant.value_or(0.0);
    model.sigma_quadratic = params.depth_noise_coefficient.value_or(0.0);
    return model;
  }
};

Segmenter::Segmenter(const Params& params) : workspace_(std::make_unique<Workspace>()) { setParams(params); }
Segmenter::~Segmenter() = default;
Segmenter::Segmenter(Segmenter&&) noexcept = default;
Segmenter& Segmenter::operator=(Segmenter&&) noexcept = default;

void Segmenter::setParams(const Params& params) {
  params.validate();
  params_ = params;
  workspace_->previous.valid = false;  // a head start needs the same parameters
}

const Segmentation& Segmenter::segment(const PointGrid& full, const Options& options) {
  Workspace& ws = *workspace_;
  result_.phases = PhaseTimes();
  result_.stats = SegmentationStats();
  const bool timed = options.measure_phases;
  PreviousFrame& previous = ws.previous;
  // A noise model from too few patches (NoiseEstimator::kMinimumPatches) is measured again.
  const bool reuse_noise = options.head_start && previous.continuedBy(full) && params_.estimatesNoise() &&
                           previous.frames_since_noise + 1 < kNoiseRefreshFrames &&
                           previous.noise.patches >= NoiseEstimator::kMinimumPatches;
  previous.valid = false;  // until this frame is done
  result_.stats.head_start = reuse_noise;
  // The pipeline, coarse to fine: the prepared frame (at s > 1 the frame read once into
  // blocks) -> the segment image (seeds and floods, relabelled) -> clusters (merged) -> planes
  // on the segmented grid (refined, occluded pieces joined, curved ones dropped) -> labels at
  // full resolution (at s > 1 written once).
  PreparedFrame frame;
  {
    PhaseTimer timer(timed, result_.phases.preparation);
    frame = ws.prepare(full, params_, reuse_noise, result_.noise);
  }
  SegmentImage image = ws.seedAndFlood(frame, params_, timed, result_);
  {
    PhaseTimer timer(timed, result_.phases.relabelling);
    ws.relabel(frame, params_.subsampling, image);
    result_.stats.segments = image.segments.size() - 1;
  }
  MergedSegments clusters;
  {
    PhaseTimer timer(timed, result_.phases.merging);
    clusters = ws.merge(frame, MergeCriterion(params_, frame.tolerances), image);
    result_.stats.merges = ws.merger.mergeCount();
  }
  {
    PhaseTimer timer(timed, result_.phases.region_output);
    ws.regions.assemble(frame, clusters, params_, options.refine, result_);
    ws.regions.write(frame, params_, result_);
  }
  previous.valid = true;
  previous.width = full.width;
  previous.height = full.height;
  previous.frames_since_noise = reuse_noise ? previous.frames_since_noise + 1 : 0;
  previous.noise = result_.noise;
  previous.segment_noise = frame.tolerances.noise();
  return result_;
}

}  // namespace floodplane
