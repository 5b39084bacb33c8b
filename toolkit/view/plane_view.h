// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The 3-D views of a segmentation (PCL's visualizer, VTK): the points coloured by plane as in
// the label PNG (no plane: grey), each plane's normal as a white arrow from its centroid as
// long as the plane is large, its id and inlier count beside it, and its outline. As a
// window to turn around in, or as an image rendered off screen. VTK stays inside
// plane_view.cpp; this header is plain C++.

#include <string>

#include "floodplane/io/rgb_image.h"
#include "view/plane_scene.h"

namespace floodplane::view {

/// What is drawn besides the planes' points; the window's keys toggle each.
struct Layers {
  bool normals = true;     ///< the arrows and their text (key n)
  bool unlabelled = true;  ///< the points on no plane (key z)
  bool outlines = true;    ///< the planes' boundaries (key b)
};

/// Renders `scene` seen by the camera of `view` into a `width` x `height` image, off screen
/// (no window appears). The same scene and size give the same image. Throws
/// std::runtime_error with one line if there is no display to render on
/// (renderingUnavailableReason) or VTK reports an error, std::invalid_argument for a size
/// outside 16..8192 or a scene the cameras cannot place (see sceneCamera).
floodplane::io::RgbImage renderImage(const PlaneScene& scene, CameraView view, int width, int height,
                                     const Layers& layers = {});

/// Opens a window titled `title` showing `scene` from the sensor (CameraView::sensor) and
/// returns when the user closes it (q, or the window's close button). Keys: n normals,
/// z unlabelled points, b outlines, v sensor / oblique camera, and PCL's own (r resets the
/// camera, + and - change the point size, h lists them). Throws as renderImage.
void showWindow(const PlaneScene& scene, const std::string& title);

}  // namespace floodplane::view
