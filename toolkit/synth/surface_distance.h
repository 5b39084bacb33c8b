// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Distances from a point to the surfaces of scene primitives (world frame), for placing
// cameras: no surface nearer than the sensor's minimum range, never inside a solid.

#include <Eigen/Core>

#include "synth/scene.h"

namespace floodplane::synth {

/// The distance from `point` to the nearest point of the primitive's surface (metres): a flat
/// shape's area (holes excluded), a solid's boundary.
double distanceToSurface(const Shape& shape, const Eigen::Vector3d& point);

/// Whether `point` is strictly inside the solid (box, sphere, cylinder, prism); false for flat
/// shapes.
bool insideSolid(const Shape& shape, const Eigen::Vector3d& point);

/// The smallest distanceToSurface over the scene's primitives (infinity for an empty scene).
double nearestSurfaceDistance(const Scene& scene, const Eigen::Vector3d& point);

/// Whether `point` is inside any solid of the scene.
bool insideAnySolid(const Scene& scene, const Eigen::Vector3d& point);

}  // namespace floodplane::synth
