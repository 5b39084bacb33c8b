// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Speckle along the structured-light scanner's depth discontinuities and shadow edges
// (ScannerParams::speckle). Where the pattern falls on an edge, a camera pixel sees parts of
// two surfaces, or of a stripe and its shadow: the pattern's code is read wrong or not at all.
// Real scans therefore show, near such edges, isolated returns where there should be none (a
// misread stripe puts them centimetres off any surface) and short runs of missing returns along
// the pattern's stripes, which with the projector beside the camera (the baseline along x) run
// down the image's columns. Both cut faces along their edges.
//
// Edges: two 4-neighbouring pixels meet at an edge when
//   - their exact hits differ in depth by more than speckle_depth_jump times the nearer depth
//     (1 cm at 1 m, 17 pixel footprints: steeper than any face that still returns light), or
//     only one of them hits anything; or
//   - one is lit and the other lies in the projector's shadow (inside its field but unlit: a
//     face turned away from it, or something in between). The edge of the projector's field is
//     no edge: the pattern fades out there evenly.
// The band: every pixel within speckle_band pixels (Chebyshev distance) of a pixel at an edge.
// In the band, decided on the frame as measured, so that the order of the pixels does not
// matter:
//   - a pixel with a return starts a stripe with probability speckle_stripe_probability: it and
//     the next L - 1 pixels down its column (L uniform from speckle_stripe_min_length to
//     _max_length) lose their returns, as far as they lie in the band;
//   - a pixel without a return whose ray hits a surface gets a spurious return with
//     probability speckle_spurious_probability, at its exact depth z plus an error uniform in
//     +- speckle_spurious_error_at_1m (z / 1 m)^2 (a triangulation error), reported as any depth
//     is (range code or lattice, range limits), with label 0: it lies on no plane.
// Random draws: each pixel of the band draws four uniforms, in this order, from a generator of
// its own, PixelRandom(seed, kSpeckleStream + pixel index): the stripe's start, its length, the
// spurious return, its error. The measuring's generators are not touched, so a frame rendered
// with speckle differs from the one without only inside the band.

#include <cstdint>
#include <vector>

#include "synth/rendered_frame.h"
#include "synth/scanner_model.h"

namespace floodplane::synth {

/// How the projector lights the surface a pixel's ray hits.
enum class ProjectorLight : std::uint8_t {
  no_surface,     ///< the ray hits nothing
  lit,            ///< inside the projector's field, facing it, nothing in between
  shadowed,       ///< inside the field, but turned away or behind something
  outside_field,  ///< beyond the projector's field
};

/// Adds the speckle to `frame` (scanner model, measured, before faces are merged): returns
/// lost in stripes (their labels set to 0 and their planes' pixel counts lowered) and spurious
/// returns with label 0. `exact_depth` (the hit's depth, infinity where the ray hits nothing)
/// and `light` hold one entry per pixel, row-major. Does nothing unless params.speckle.
void addScannerSpeckle(const std::vector<double>& exact_depth, const std::vector<ProjectorLight>& light,
                       const ScannerParams& params, std::uint64_t seed, RenderedFrame& frame);

/// Which pixels lie in the band of addScannerSpeckle (1) and which not (0), row-major: for
/// tests and pictures.
std::vector<std::uint8_t> scannerSpeckleBand(const std::vector<double>& exact_depth,
                                             const std::vector<ProjectorLight>& light, const ScannerParams& params,
                                             int width, int height);

}  // namespace floodplane::synth
