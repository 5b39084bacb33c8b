// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Each competitor registers its benchmarks from its own file.
#pragma once

#include <string>

namespace floodplane::bench {

/// The configuration a method prints before the numbers.
std::string floodplaneConfiguration();
std::string ompsConfiguration();

void registerFloodplane();
void registerOmps();
/// The soak run: 10 000 segmentations in one process, resident memory first and last.
void registerSoak();
/// The depth smoothing alone, four points at a time and as wide as the CPU runs.
void registerSmoothing();
/// The noise estimation alone: a fixed cost per call, whatever the frame's size.
void registerNoiseEstimation();
/// Planes then objects (segmentObjects) on the real and mOSD frames, each timed (issue 59).
void registerObjects();
/// PlaneTracker::update and relabel on the three consecutive real frames (issue 28).
void registerTracking();
/// Cold starts against head starts, interleaved, on a rendered walk (issue 28).
void registerHeadStart();
/// One pass that reads every point and writes a label: the floor under any segmentation.
void registerMemoryFloor();
void registerInterleavedMethods();
// The resolution sweep: time, time per pixel and added memory at s = 1 and s = 4.
void registerResolutionSweep();

}  // namespace floodplane::bench
