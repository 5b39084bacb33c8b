// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/pcd_file.h"

#include <pcl/io/pcd_io.h>

#include <stdexcept>

#include "io/atomic_file.h"

namespace floodplane::io {

template <typename PointT>
void savePcd(const std::string& path, const pcl::PointCloud<PointT>& cloud, PcdEncoding encoding) {
  writeFileAtomically(path, [&](const std::string& temporary) {
    pcl::PCDWriter writer;
    int status = -1;
    // PCL reports most failures by return code but some by pcl::IOException; both become
    // one std::runtime_error that names the file the caller asked for.
    try {
      switch (encoding) {
        case PcdEncoding::binary_compressed:
          status = writer.writeBinaryCompressed(temporary, cloud);
          break;
        case PcdEncoding::binary:
          status = writer.writeBinary(temporary, cloud);
          break;
        case PcdEncoding::ascii:
          // 9 significant digits round-trip every float exactly (PCL's default is 8).
          status = writer.writeASCII(temporary, cloud, 9);
          break;
      }
    } catch (const pcl::IOException& error) {
      throw std::runtime_error("cannot write PCD file '" + path + "': " + error.what());
    }
    if (status != 0) {
      throw std::runtime_error("cannot write PCD file '" + path + "'");
    }
  });
}

#define FLOODPLANE_INSTANTIATE_SAVE_PCD(PointT) \
  template void savePcd<PointT>(const std::string&, const pcl::PointCloud<PointT>&, PcdEncoding);
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZ)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZI)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZL)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZRGB)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZRGBA)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZRGBL)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointNormal)
#undef FLOODPLANE_INSTANTIATE_SAVE_PCD

}  // namespace floodplane::io
