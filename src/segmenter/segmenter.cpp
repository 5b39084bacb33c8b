// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/segmenter.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "coarse/coarse_planes.h"
#include "flood/flood_pass.h"
#include "frame/block_grid.h"
#include "frame/depth_smoothing.h"
#include "frame/noise_estimator.h"
#include "frame/prepared_frame.h"
#include "regions/region_builder.h"

namespace floodplane {

namespace {

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

// What a head start (Segmenter::Options::head_start) takes from the last frame: its noise.
struct PreviousFrame {
  bool valid = false;  // the last call completed with the current parameters
  int width = 0;
  int height = 0;
  NoiseModel noise;            // measured on the raw frame
  NoiseModel segment_noise;    // measured on the smoothed frame
  NoiseModel block_noise;      // measured on the block means (s > 1)
  int frames_since_noise = 0;  // frames since the noise was last measured

  bool continuedBy(const PointGrid& grid) const { return valid && width == grid.width && height == grid.height; }
};

}  // namespace

struct Segmenter::Workspace {
  BlockGrid blocks;  // s > 1
  std::vector<float> pitch_scratch;
  NoiseEstimator noise_estimator;
  HoleFilling holes;
  HoleFilling block_holes;  // s > 1: of the block means
  DepthSmoothing smoothing;
  FloodGrid fine_grid;
  FloodPass coarse;  // s > 1: over the block means
  CoarsePlanes coarse_planes;
  FloodPass fine;  // over the pixels
  RegionBuilder regions;
  PreviousFrame previous;

  // The frame as the stages segment it: at full resolution with small holes filled and the
  // noise smoothed, and at s > 1 also read once into s x s blocks, whose means the coarse pass
  // segments. With `reuse_noise`, the previous frame's noise models stand in for the
  // measurements: the noise belongs to the sensor, not the scene.
  PreparedFrame prepare(const PointGrid& full, const Params& params, bool reuse_noise, NoiseModel& noise) {
    PreparedFrame frame;
    const int s = params.subsampling;
    frame.measured = full;
    frame.pitch = SeedSelector::estimateAngularPitch(full, pitch_scratch);
    noise = reuse_noise ? previous.noise : noiseModel(full, params);
    frame.measured_tolerances = Tolerances(params, noise, frame.pitch, full.size());
    NoiseModel segment_noise = noise;
    const PointGrid& filled = holes.fill(full, frame.measured_tolerances);
    // The smoothed frame, and its own noise (the smoothing's gain depends on how correlated
    // the sensor's noise is: a third of it on the Kinect model, a quarter less on a real
    // Kinect). A noise model the user gives describes the raw data: no smoothing then; nor
    // on exact depths rounded to a lattice (roundingOnly).
    frame.grid = filled;
    if (params.estimatesNoise() && !negligibleAgainstPixels(noise, frame.pitch) && !roundingOnly(noise)) {
      frame.grid = smoothing.smooth(filled, noise);
      segment_noise = reuse_noise ? previous.segment_noise : noise_estimator.estimate(frame.grid);
    }
    frame.holes = &holes;
    frame.tolerances = Tolerances(params, segment_noise, frame.pitch, full.size());
    fine_grid.points = frame.grid;
    fine_grid.tolerances = frame.tolerances;
    fine_grid.pitch = frame.pitch;
    fine_grid.factor = 1;
    fine_grid.noise_free = negligibleAgainstPixels(segment_noise, frame.pitch);
    frame.subsampling = s;
    if (s > 1) {
      // Coarse to fine: the frame read once into s x s blocks, whose means the coarse pass
      // segments (their averaging is its smoothing), with the noise of those means.
      blocks.read(full, s);
      frame.blocks = &blocks;
      NoiseModel block_noise = noise;
      if (params.estimatesNoise()) {
        const int spacing = std::max(1, NoiseEstimator::kPatchSpacing / s);
        block_noise = reuse_noise ? previous.block_noise : noise_estimator.estimate(blocks.means(), spacing);
      }
      blocks.separateSurfaces(full, noise, frame.pitch);
      FloodGrid& coarse_grid = frame.coarse;
      coarse_grid.pitch = frame.pitch * static_cast<float>(s);
      coarse_grid.tolerances = Tolerances(params, block_noise, coarse_grid.pitch, full.size());
      coarse_grid.points = block_holes.fill(blocks.means(), coarse_grid.tolerances);
      coarse_grid.factor = s;
      coarse_grid.noise_free = negligibleAgainstPixels(block_noise, coarse_grid.pitch);
    }
    return frame;
  }

  // s > 1: the coarse pass over the block means and the coarse planes it finds, in
  // coarse_planes.
  void findCoarsePlanes(const PreparedFrame& frame, const Params& params, bool timed, Segmentation& result) {
    {
      PhaseTimer timer(timed, result.phases.flood_fill);
      coarse.begin(frame.coarse, params);
    }
    coarse.seedAndFlood(timed, result.stats, result.phases);
    PhaseTimer timer(timed, result.phases.merging);
    coarse.relabel();
    const MergedSegments clusters = coarse.merge(MergeCriterion(params, frame.coarse.tolerances));
    coarse_planes.find(*frame.blocks, frame.coarse, coarse, clusters, params, frame.measured_tolerances);
  }

  // The fine pass over the pixels, from the coarse planes' inner blocks (s > 1): the merged
  // segments, valid until the fine pass begins again.
  MergedSegments segmentPixels(const PreparedFrame& frame, const Params& params, bool timed, Segmentation& result) {
    {
      // The fine pass starts with the coarse planes' inner blocks claimed and flooded on from
      // their edges: flood work.
      PhaseTimer timer(timed, result.phases.flood_fill);
      fine.begin(fine_grid, params);
      if (frame.blocks)
        coarse_planes.claim(*frame.blocks, frame.grid, *frame.holes, frame.tolerances, frame.pitch, fine, result.stats);
    }
    fine.seedAndFlood(timed, result.stats, result.phases);
    {
      PhaseTimer timer(timed, result.phases.relabelling);
      fine.relabel();
      result.stats.segments = fine.segments().size() - 1;
    }
    PhaseTimer timer(timed, result.phases.merging);
    MergedSegments clusters = fine.merge(MergeCriterion(params, frame.tolerances));
    result.stats.merges = fine.mergeCount();
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
  // The pipeline, coarse to fine: the prepared frame -> (s > 1) the coarse pass over the block
  // means: seeds, floods, relabelling, merging, and the coarse planes, whose inner blocks the
  // fine pass takes as they are -> the fine pass over the pixels: seeds and floods wherever
  // nothing is taken, relabelling, merging -> planes (refined, occluded pieces joined, curved
  // ones dropped) -> labels and plane sums at full resolution.
  PreparedFrame frame;
  {
    PhaseTimer timer(timed, result_.phases.preparation);
    frame = ws.prepare(full, params_, reuse_noise, result_.noise);
  }
  if (frame.blocks) ws.findCoarsePlanes(frame, params_, timed, result_);
  const MergedSegments clusters = ws.segmentPixels(frame, params_, timed, result_);
  {
    PhaseTimer timer(timed, result_.phases.region_output);
    ws.regions.assemble(frame, clusters, params_, options.refine);
    ws.regions.write(frame, result_);
  }
  previous.valid = true;
  previous.width = full.width;
  previous.height = full.height;
  previous.frames_since_noise = reuse_noise ? previous.frames_since_noise + 1 : 0;
  previous.noise = result_.noise;
  previous.segment_noise = frame.tolerances.noise();
  previous.block_noise = frame.coarse.tolerances.noise();
  return result_;
}

}  // namespace floodplane
