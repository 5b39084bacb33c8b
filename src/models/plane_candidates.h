// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "floodplane/params.h"
#include "floodplane/plane_fit.h"
#include "models/flood_criterion.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"
#include "util/row_search.h"

namespace floodplane {

/// "No pixel yet" for PlaneCandidate::first_pixel.
constexpr std::size_t kNoPixel = std::numeric_limits<std::size_t>::max();

/// The label image read in the planes' current numbers: pixel i belongs to plane labels[i]
/// (0: none). The image keeps the numbers it was written in until someone writes to it, and
/// `number` maps them to today's: the stages that renumber the planes (sorting, merging
/// occluded pieces, dropping curved ones) then cost no pass over the image each. A view of
/// PlaneCandidates' image, valid until their next renumbering or write request.
struct CurrentLabels {
  const std::uint32_t* image = nullptr;   // the image's own numbers
  const std::uint32_t* number = nullptr;  // image number -> current plane number
  std::uint32_t operator[](std::size_t i) const { return number[image[i]]; }

  /// Calls f(k, begin, end) for every run [begin, end) of one image number in columns
  /// x_begin..x_last of the row starting at pixel `row`, k its current plane. Neighbouring runs
  /// may be of one plane (pieces merged since the image was written).
  template <class F>
  void forEachRunInRow(std::size_t row, int x_begin, int x_last, F&& f) const {
    floodplane::forEachRunInRow(image + row, x_begin, x_last,
                                [&](std::uint32_t label, int begin, int end) { f(number[label], begin, end); });
  }
  /// Calls f(k, begin, end) for every maximal run [begin, end) of one current plane k in the
  /// `width` pixels of the row starting at pixel `row`: runs of image numbers that now carry
  /// the same number join.
  template <class F>
  void forEachPlaneRunInRow(std::size_t row, int width, F&& f) const {
    const std::uint32_t* image_row = image + row;
    int u = 0;
    while (u < width) {
      const std::uint32_t k = number[image_row[u]];
      int end = findInRow(image_row, u, width - 1, image_row[u], false);
      while (end < width && number[image_row[end]] == k)
        end = findInRow(image_row, end, width - 1, image_row[end], false);
      f(k, u, end);
      u = end;
    }
  }
};

/// A plane on its way to the output: its full-resolution inliers and its membership test.
struct PlaneCandidate {
  PlaneSums sums;            ///< of its full-resolution inliers
  FloodCriterion criterion;  ///< its plane and thresholds, for labelling and refinement
  std::size_t first_pixel = kNoPixel;
};

/// The candidate planes, numbered 1..K by size (largest first; 0: no plane), and their label
/// image: the one owner of the plane numbers. Every renumbering (sortBySize, regroup, drop) is
/// recorded here, against the image, so that whoever reads the labels (labels()) or writes
/// them (writableImage(), forEachWritableRow()) gets them in the current numbers, whatever
/// came before: no stage needs to know whether another changed the numbers first. A
/// renumbering costs no pass over the image: the image is rewritten at most once per write
/// request, and then only if the numbers changed since it was written.
///
/// First pixels move with their planes (and a merged plane keeps the first of its pieces'):
/// renumbering a plane does not move its pixels.
class PlaneCandidates {
 public:
  std::vector<PlaneCandidate>& list() { return candidates_; }
  const std::vector<PlaneCandidate>& list() const { return candidates_; }
  PlaneCandidate& operator[](std::uint32_t label) { return candidates_[label - 1]; }
  /// No candidate and no image. (Candidates added to list() afterwards take the next numbers.)
  void clear();

  /// Drops candidates under `min_inliers` and, when `recheck` is given, those whose inliers
  /// no longer make an acceptable plane under its parameters; orders the rest by size.
  /// Returns whether any number changed.
  bool sortBySize(std::uint32_t min_inliers, const Params* recheck);
  /// Merges the candidates whose numbers k share a value group[k] (group[0] is ignored) and
  /// orders the result by size again. Returns whether any merged.
  bool regroup(const std::vector<std::uint32_t>& group);
  /// Drops the candidates whose number k has drop[k] set (drop[0] is ignored), keeping the
  /// order of the rest. Returns whether any was dropped.
  bool drop(const std::vector<bool>& drop);
  /// The new number of old number k, after the last sortBySize, regroup or drop (0: dropped).
  std::uint32_t remap(std::uint32_t k) const { return remap_[k]; }

  /// A new label image of width x height pixels, to be written in full in the current numbers
  /// (its contents are undefined until then).
  std::uint32_t* newImage(int width, int height);
  /// The image in the current numbers, for reading.
  CurrentLabels labels() const { return {image_.data(), number_.data()}; }
  /// The image in the current numbers, writable: rewritten first, in one pass, if the numbers
  /// changed since it was last written.
  std::uint32_t* writableImage();
  /// Calls visit(image, y) for each row y, top to bottom, with rows y - 1 to y + 1 of `image`
  /// in the current numbers, writable: for a scan that reads a row's neighbours, the image is
  /// rewritten (if the numbers changed) a row ahead of it, in the same pass. Afterwards the
  /// whole image is in the current numbers.
  template <class VisitRow>
  void forEachWritableRow(VisitRow&& visit);
  /// Hands the image over in the current numbers (swapped into `out`); no image is left.
  void releaseImage(std::vector<std::uint32_t>& out);

 private:
  // Orders the candidates by size (see sortBySize) without recording the renumbering.
  bool sortCandidates(std::uint32_t min_inliers, const Params* recheck);
  // Adds remap() to the numbering the image is read through.
  void recordRenumbering();
  // Whether the image's numbers differ from the current ones.
  bool imageOutOfDate() const;
  // Rewrites pixels [begin, end) of the image in the current numbers.
  void renumberPixels(std::size_t begin, std::size_t end);
  // The image's numbers are the current ones.
  void imageUpToDate();

  std::vector<PlaneCandidate> candidates_;
  std::vector<PlaneCandidate> kept_;
  std::vector<std::uint32_t> remap_;
  std::vector<std::size_t> order_;
  std::vector<std::uint32_t> image_;   // the label image, in the numbers it was written in
  std::vector<std::uint32_t> number_;  // image number -> current number (empty: no image)
  int width_ = 0, height_ = 0;
};

template <class VisitRow>
void PlaneCandidates::forEachWritableRow(VisitRow&& visit) {
  const bool renumber = imageOutOfDate();
  const std::size_t width = static_cast<std::size_t>(width_);
  if (renumber && height_ > 0) renumberPixels(0, width);
  for (int y = 0; y < height_; ++y) {
    if (renumber && y + 1 < height_)
      renumberPixels(static_cast<std::size_t>(y + 1) * width, static_cast<std::size_t>(y + 2) * width);
    visit(image_.data(), y);
  }
  if (renumber) imageUpToDate();
}

/// What a reported plane must be: a valid fit, no more curved than allowed, facing the sensor.
bool acceptablePlane(const PlaneFit& fit, const Params& params);

/// A plane's membership test for pixels that join it after merging, from its fit. The
/// Euclidean tolerance follows from the plane itself: neighbouring pixels on n.P + d = 0 are
/// alpha r^2 / |d| apart (see FloodCriterion).
FloodCriterion planeCriterion(const PlaneFit& fit, const Tolerances& tolerances, float angular_pitch);

}  // namespace floodplane
