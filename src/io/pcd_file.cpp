// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/pcd_file.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>

#include <cstring>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"

namespace floodplane::io {
namespace {

// PCL's binary layout, as its writeBinary<PointT> lays it out: the header, then each point's
// fields packed without the struct's padding ("_" fields).
template <typename PointT>
std::string binaryPcd(const pcl::PointCloud<PointT>& cloud) {
  std::vector<pcl::PCLPointField> fields;
  pcl::getFields<PointT>(fields);
  std::vector<std::pair<std::size_t, std::size_t>> copied;  // offset in PointT, bytes
  std::size_t point_bytes = 0;
  for (const pcl::PCLPointField& field : fields) {
    if (field.name == "_") continue;
    const std::size_t bytes = field.count * pcl::getFieldSize(field.datatype);
    copied.emplace_back(field.offset, bytes);
    point_bytes += bytes;
  }
  std::string bytes = pcl::PCDWriter::generateHeader<PointT>(cloud) + "DATA binary\n";
  std::size_t at = bytes.size();
  bytes.resize(at + cloud.size() * point_bytes);
  for (const PointT& point : cloud) {
    for (const auto& [offset, size] : copied) {
      std::memcpy(&bytes[at], reinterpret_cast<const char*>(&point) + offset, size);
      at += size;
    }
  }
  return bytes;
}

}  // namespace

template <typename PointT>
std::string encodePcd(const pcl::PointCloud<PointT>& cloud, PcdEncoding encoding) {
  switch (encoding) {
    case PcdEncoding::binary:
      return binaryPcd(cloud);
    case PcdEncoding::binary_compressed: {
      pcl::PCLPointCloud2 blob;
      pcl::toPCLPointCloud2(cloud, blob);
      std::ostringstream out;
      int status = -1;
      // PCL reports most failures by return code but some by pcl::IOException.
      try {
        status = pcl::PCDWriter().writeBinaryCompressed(out, blob, cloud.sensor_origin_, cloud.sensor_orientation_);
      } catch (const pcl::IOException& error) {
        throw std::runtime_error(std::string("cannot encode the PCD data: ") + error.what());
      }
      if (status != 0) throw std::runtime_error("cannot encode the PCD data");
      return std::move(out).str();
    }
    case PcdEncoding::ascii:
      break;
  }
  throw std::invalid_argument("encodePcd: ASCII is written by savePcd only");
}

template <typename PointT>
void savePcd(const std::string& path, const pcl::PointCloud<PointT>& cloud, PcdEncoding encoding) {
  if (encoding != PcdEncoding::ascii) {
    std::string bytes;
    try {
      bytes = encodePcd(cloud, encoding);
    } catch (const std::runtime_error& error) {
      throw std::runtime_error("cannot write PCD file '" + path + "': " + error.what());
    }
    writeBytesAtomically(path, bytes);
    return;
  }
  writeFileAtomically(path, [&](const std::string& temporary) {
    int status = -1;
    try {
      // 9 significant digits round-trip every float exactly (PCL's default is 8).
      status = pcl::PCDWriter().writeASCII(temporary, cloud, 9);
    } catch (const pcl::IOException& error) {
      throw std::runtime_error("cannot write PCD file '" + path + "': " + error.what());
    }
    if (status != 0) throw std::runtime_error("cannot write PCD file '" + path + "'");
  });
}

#define FLOODPLANE_INSTANTIATE_SAVE_PCD(PointT)                                                   \
  template void savePcd<PointT>(const std::string&, const pcl::PointCloud<PointT>&, PcdEncoding); \
  template std::string encodePcd<PointT>(const pcl::PointCloud<PointT>&, PcdEncoding);
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZ)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZI)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZL)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZRGB)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZRGBA)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointXYZRGBL)
FLOODPLANE_INSTANTIATE_SAVE_PCD(pcl::PointNormal)
#undef FLOODPLANE_INSTANTIATE_SAVE_PCD

}  // namespace floodplane::io
