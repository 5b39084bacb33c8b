#include "floodplane/segmenter.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "connected_components.h"
#include "distance_buffer.h"
#include "plane_flood.h"
#include "plane_merging.h"
#include "point_lanes.h"
#include "region_output.h"
#include "seed_selection.h"

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

}  // namespace

struct Segmenter::Workspace {
  std::vector<float> subsampled;  // x y z 0 of every s-th pixel when s > 1
  std::vector<float> pitch_scratch;
  DistanceBuffer buffer;
  SeedSelector selector;
  SeedSelector fine_selector;  // the second pass's smaller seed cube
  PlaneFlood flood;
  std::vector<Segment> segments;
  std::vector<SegmentEdge> edges;
  ComponentSplitter splitter;
  PlaneMerger merger;
  std::vector<PlaneSums> cluster_sums;
  RegionBuilder regions;

  // Pass 0: the grid to segment, every s-th pixel of every s-th row.
  PointGrid sample(const PointGrid& full, int s) {
    if (s == 1) return full;
    PointGrid grid;
    grid.width = (full.width + s - 1) / s;
    grid.height = (full.height + s - 1) / s;
    grid.stride = 4;  // as PCL's points: the flood reads four floats a point
    subsampled.resize(grid.size() * 4);
    float* out = subsampled.data();
    for (int y = 0; y < full.height; y += s) {
      for (int x = 0; x < full.width; x += s) {
        const float* p = full.point(static_cast<std::size_t>(y) * full.width + x);
        *out++ = p[0];
        *out++ = p[1];
        *out++ = p[2];
        *out++ = 0.f;
      }
    }
    grid.data = subsampled.data();
    return grid;
  }

  // Sec. III-B, after the floods: split what Eq. 4 takeovers disconnected. Only the pixels
  // that leave a segment are visited after the split: the piece that keeps the label keeps
  // its running sums minus what left, and its neighbour edges (an edge it inherits from a
  // piece that split off joins it to a segment it touched through that piece, across the
  // band the takeover cut, which the merge test still judges on the planes).
  void relabel(const PointGrid& grid, int subsampling) {
    // Crumbs below 16 full-resolution pixels' worth of samples are released (see
    // ComponentSplitter); at least one sample, so nothing is released at s >= 4.
    const std::size_t smallest_piece = static_cast<std::size_t>(std::max(1, 16 / (subsampling * subsampling)));
    const std::int32_t before = static_cast<std::int32_t>(segments.size());
    std::int32_t next_label = before;
    std::vector<std::int32_t>& labels = buffer.labels();
    for (std::int32_t s = 1; s < before; ++s) {
      if (!segments[s].lost_pixels || segments[s].sums.count <= 0.0) continue;
      const PixelBox box = segments[s].box;
      const std::int32_t first_new = next_label;
      const std::vector<std::int32_t> created =
          splitter.split(labels.data(), grid.width, box, s, next_label, smallest_piece);
      if (created.empty() && splitter.releasedPixels() == 0) continue;
      const FloodCriterion criterion = segments[s].criterion;
      segments.resize(static_cast<std::size_t>(next_label));
      for (std::int32_t label = first_new; label < next_label; ++label) {
        segments[label] = Segment();
        segments[label].criterion = criterion;
      }
      for (const ComponentSplitter::Run& run : splitter.runs()) {
        if (run.set == s) continue;
        Segment* piece = run.set > 0 ? &segments[run.set] : nullptr;
        PlaneSums moved;
        addRunToSums(moved, grid, static_cast<std::size_t>(run.y) * grid.width + static_cast<std::size_t>(run.x_begin),
                     static_cast<std::size_t>(run.x_end - run.x_begin + 1));
        segments[s].sums.subtract(moved);
        if (piece) {
          piece->sums.merge(moved);
          piece->box.include(run.x_begin, run.y);
          piece->box.include(run.x_end, run.y);
          addPieceEdges(grid, run);
        }
      }
    }
  }

  // The neighbour edges of a run of a new piece: its pixels' 4-neighbours with another label
  // that are 3-D neighbours too (Eq. 3).
  void addPieceEdges(const PointGrid& grid, const ComponentSplitter::Run& run) {
    const std::vector<std::int32_t>& labels = buffer.labels();
    const FloodCriterion& c = segments[run.set].criterion;
    std::int32_t last_other = 0;
    const auto consider = [&](std::size_t i, std::size_t j) {
      const std::int32_t other = labels[j];
      // Along a run the neighbour is mostly the same segment pixel after pixel: one edge.
      if (other == 0 || other == run.set || other == last_other) return;
      const Vec3 p = Vec3::load(grid.point(i));
      if (squaredEuclideanDistance(p, Vec3::load(grid.point(j))) < c.euclideanToleranceSq(p.squaredNorm())) {
        edges.emplace_back(run.set, other);
        last_other = other;
      }
    };
    const std::size_t row = static_cast<std::size_t>(run.y) * grid.width;
    // Inside the run the left and right neighbours are the run itself: only its ends count.
    if (run.x_begin > 0) consider(row + run.x_begin, row + run.x_begin - 1);
    if (run.x_end + 1 < grid.width) consider(row + run.x_end, row + run.x_end + 1);
    for (const int dy : {-1, 1}) {
      if (run.y + dy < 0 || run.y + dy >= grid.height) continue;
      const std::ptrdiff_t offset = dy * static_cast<std::ptrdiff_t>(grid.width);
      for (int x = run.x_begin; x <= run.x_end; ++x) {
        const std::size_t i = row + static_cast<std::size_t>(x);
        consider(i, static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offset));
      }
    }
  }
};

Segmenter::Segmenter(const Params& params) : workspace_(std::make_unique<Workspace>()) { setParams(params); }
Segmenter::~Segmenter() = default;
Segmenter::Segmenter(Segmenter&&) noexcept = default;
Segmenter& Segmenter::operator=(Segmenter&&) noexcept = default;

void Segmenter::setParams(const Params& params) {
  params.validate();
  params_ = params;
}

const Segmentation& Segmenter::segment(const PointGrid& full, const Options& options) {
  Workspace& ws = *workspace_;
  result_.phases = PhaseTimes();
  result_.stats = SegmentationStats();
  const bool timed = options.measure_phases;
  const int s = params_.subsampling;

  PointGrid grid;
  float full_pitch = 0.f;
  float pitch = 0.f;
  {
    PhaseTimer timer(timed, result_.phases.seed_selection);
    grid = ws.sample(full, s);
    pitch = SeedSelector::estimateAngularPitch(grid, ws.pitch_scratch, static_cast<float>(s) / 525.0f);
    full_pitch = pitch / static_cast<float>(s);
    ws.selector.configure(params_, pitch, grid.width, grid.height);
    Params fine = params_;
    fine.seed_size /= kFineSeedDivisor;
    ws.fine_selector.configure(fine, pitch, grid.width, grid.height);
    ws.buffer.reset(grid.size());
    ws.segments.assign(1, Segment());  // label 0: no segment
    ws.edges.clear();
    ws.flood.beginFrame();
  }

  // Seed selection (Sec. III-C) interleaved with flooding (Sec. III-A, III-B), in scan order.
  {
    const Clock::time_point scan_start = timed ? Clock::now() : Clock::time_point();
    double flooding = 0.0;
    const int stride = std::max(1, kSeedStride / s);
    const int offset = stride / 2;
    Seed seed;
    for (const SeedSelector* selector : {&ws.selector, &ws.fine_selector}) {
      for (int y = offset; y < grid.height; y += stride) {
        for (int x = offset; x < grid.width; x += stride) {
          if (ws.buffer.label(static_cast<std::size_t>(y) * grid.width + x) != 0) continue;
          ++result_.stats.seed_candidates;
          if (selector->test(grid, x, y, seed) != SeedVerdict::kAccepted) continue;
          ++result_.stats.seeds;
          const std::int32_t label = static_cast<std::int32_t>(ws.segments.size());
          ws.segments.emplace_back();
          PhaseTimer timer(timed, flooding);
          result_.stats.pixels_taken_over += ws.flood.grow(grid, seed, label, params_, ws.buffer, ws.segments, ws.edges);
        }
      }
    }
    if (timed) {
      result_.phases.flood_fill += flooding;
      result_.phases.seed_selection += millisecondsSince(scan_start) - flooding;
    }
  }

  {
    PhaseTimer timer(timed, result_.phases.relabelling);
    ws.relabel(grid, s);
    result_.stats.segments = ws.segments.size() - 1;
  }

  {
    PhaseTimer timer(timed, result_.phases.merging);
    ws.merger.reset(ws.segments.size());
    for (const SegmentEdge& edge : ws.edges) ws.merger.addEdge(edge.first, edge.second);
    ws.cluster_sums.resize(ws.segments.size());
    for (std::size_t i = 0; i < ws.segments.size(); ++i) ws.cluster_sums[i] = ws.segments[i].sums;
    ws.merger.merge(ws.cluster_sums, MergeCriterion(params_));
    result_.stats.merges = ws.merger.mergeCount();
  }

  {
    PhaseTimer timer(timed, result_.phases.region_output);
    MergedSegments merged;
    merged.labels = ws.buffer.labels().data();
    merged.root = ws.merger.rootData();
    merged.sums = ws.cluster_sums.data();
    merged.segment_count = ws.segments.size();
    ws.regions.build(full, grid, s, merged, params_, full_pitch, options.refine, result_);
  }
  return result_;
}

}  // namespace floodplane
