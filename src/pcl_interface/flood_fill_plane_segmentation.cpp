// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Explicit instantiations of FloodFillPlaneSegmentation for PCL's common point types, so
// that users compile none of its template code. For other point types, include
// floodplane/impl/flood_fill_plane_segmentation.hpp (or define PCL_NO_PRECOMPILE).
#include "floodplane/flood_fill_plane_segmentation.h"

#include "floodplane/impl/flood_fill_plane_segmentation.hpp"

namespace floodplane::detail {

[[noreturn]] void throwBadParameter(const char* setter, const std::string& message) {
  throw std::invalid_argument(std::string("floodplane::FloodFillPlaneSegmentation::") + setter + ": " + message);
}

}  // namespace floodplane::detail

#ifndef PCL_NO_PRECOMPILE
template class floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>;
template class floodplane::FloodFillPlaneSegmentation<pcl::PointXYZI>;
template class floodplane::FloodFillPlaneSegmentation<pcl::PointXYZL>;
template class floodplane::FloodFillPlaneSegmentation<pcl::PointXYZRGB>;
template class floodplane::FloodFillPlaneSegmentation<pcl::PointXYZRGBA>;
template class floodplane::FloodFillPlaneSegmentation<pcl::PointXYZRGBL>;
template class floodplane::FloodFillPlaneSegmentation<pcl::PointNormal>;
template class floodplane::FloodFillPlaneSegmentation<pcl::PointXYZRGBNormal>;
#endif
