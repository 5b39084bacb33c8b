#include "load_cloud.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <stdexcept>
#include <system_error>

namespace pcd_segment {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& reason) { throw std::runtime_error(reason); }

// PCL's reader trusts the sizes written in a binary file: a truncated binary_compressed file
// makes it read past the end of its memory map (a crash, not an error code). So the body's
// size is checked against the file's size here, from the header PCL has parsed, before PCL
// reads the body.
void checkBodySize(const std::string& path, std::uintmax_t file_size, int data_type,
                   unsigned data_index, const pcl::PCLPointCloud2& header) {
  const std::uint64_t body_size =
      std::uint64_t{header.width} * header.height * header.point_step;
  if (data_type == 1) {  // binary: the points, raw
    if (data_index + body_size > file_size) {
      fail("truncated PCD file: the header announces " + std::to_string(body_size) +
           " bytes of binary data, the file holds " + std::to_string(file_size - data_index));
    }
  } else if (data_type == 2) {  // binary_compressed: two uint32 sizes, then LZF data
    if (data_index + 8 > file_size) {
      fail("truncated PCD file: the compressed data is missing");
    }
    std::ifstream in(path, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(data_index));
    std::uint32_t sizes[2] = {0, 0};
    in.read(reinterpret_cast<char*>(sizes), sizeof(sizes));
    if (!in) fail("cannot read the compressed data");
    const std::uint32_t compressed_size = sizes[0];
    const std::uint32_t uncompressed_size = sizes[1];
    if (data_index + 8 + std::uint64_t{compressed_size} > file_size) {
      fail("truncated PCD file: the header announces " + std::to_string(compressed_size) +
           " bytes of compressed data, the file holds " +
           std::to_string(file_size - data_index - 8));
    }
    if (uncompressed_size != body_size) {
      fail("corrupt PCD file: the compressed data unpacks to " +
           std::to_string(uncompressed_size) + " bytes, " + std::to_string(header.width) +
           " x " + std::to_string(header.height) + " points need " + std::to_string(body_size));
    }
  }
}

const pcl::PCLPointField* findField(const pcl::PCLPointCloud2& cloud, const std::string& name) {
  for (const auto& field : cloud.fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

// x, y, z may be stored as float or double (both occur in the wild); read either as float.
float readCoordinate(const std::uint8_t* point, const pcl::PCLPointField& field) {
  if (field.datatype == pcl::PCLPointField::FLOAT64) {
    double value;
    std::memcpy(&value, point + field.offset, sizeof(value));
    return static_cast<float>(value);
  }
  float value;
  std::memcpy(&value, point + field.offset, sizeof(value));
  return value;
}

}  // namespace

LoadedCloud loadOrganizedCloud(const std::string& path) {
  std::error_code error;
  const std::uintmax_t file_size = fs::file_size(path, error);
  if (error) fail("cannot read file: " + error.message());
  if (file_size == 0) fail("empty file, not a PCD file");

  pcl::PCDReader reader;
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  int data_type = 0;
  unsigned data_index = 0;
  try {
    if (reader.readHeader(path, cloud, origin, orientation, version, data_type, data_index) < 0) {
      fail("not a PCD file, or its header is invalid");
    }
    if (cloud.fields.empty() || cloud.point_step == 0) {
      fail("not a PCD file, or its header is invalid (no fields)");
    }
    if (data_index > file_size) fail("truncated PCD file: the header is incomplete");
    checkBodySize(path, file_size, data_type, data_index, cloud);
    if (reader.read(path, cloud, origin, orientation, version) < 0) {
      fail("corrupt or truncated PCD file (PCL cannot read its data)");
    }
  } catch (const pcl::PCLException& e) {
    fail(std::string("corrupt PCD file: ") + e.what());
  } catch (const std::bad_alloc&) {
    fail("corrupt PCD file: its header announces more points than fit in memory");
  }

  for (const char* name : {"x", "y", "z"}) {
    const pcl::PCLPointField* field = findField(cloud, name);
    if (!field) fail("the cloud has no x y z fields (this method needs 3D points)");
    if (!(field->datatype == pcl::PCLPointField::FLOAT32 ||
          field->datatype == pcl::PCLPointField::FLOAT64) ||
        field->count != 1) {
      fail(std::string("field ") + name + " is not a single float or double");
    }
  }
  if (cloud.height <= 1) {
    fail("unorganized cloud (" + std::to_string(cloud.width) + " x " +
         std::to_string(cloud.height) +
         "): this method needs an organized cloud (an image grid, height > 1)");
  }
  const std::size_t count = std::size_t{cloud.width} * cloud.height;
  if (cloud.data.size() < count * cloud.point_step) {
    fail("corrupt PCD file: " + std::to_string(cloud.data.size()) + " bytes of point data for " +
         std::to_string(count) + " points");
  }

  const pcl::PCLPointField& x = *findField(cloud, "x");
  const pcl::PCLPointField& y = *findField(cloud, "y");
  const pcl::PCLPointField& z = *findField(cloud, "z");
  const pcl::PCLPointField* color = findField(cloud, "rgb");
  if (!color) color = findField(cloud, "rgba");
  // rgb is packed into 4 bytes whatever type the file declares (PCL writes F, others U).
  if (color && !(color->count == 1 && pcl::getFieldSize(color->datatype) == 4)) color = nullptr;
  for (const pcl::PCLPointField* field : {&x, &y, &z, color}) {
    if (field && field->offset + pcl::getFieldSize(field->datatype) > cloud.point_step) {
      fail("corrupt PCD file: field " + field->name + " lies outside the point");
    }
  }

  LoadedCloud loaded;
  loaded.xyz.resize(cloud.width, cloud.height);
  loaded.xyz.sensor_origin_ = origin;
  loaded.xyz.sensor_orientation_ = orientation;
  bool dense = true;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* point = cloud.data.data() + i * cloud.point_step;
    pcl::PointXYZ& p = loaded.xyz[i];
    p.x = readCoordinate(point, x);
    p.y = readCoordinate(point, y);
    p.z = readCoordinate(point, z);
    dense = dense && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  }
  loaded.xyz.is_dense = dense;
  if (color) {
    loaded.has_color = true;
    loaded.xyzrgb.resize(cloud.width, cloud.height);
    loaded.xyzrgb.sensor_origin_ = origin;
    loaded.xyzrgb.sensor_orientation_ = orientation;
    loaded.xyzrgb.is_dense = dense;
    for (std::size_t i = 0; i < count; ++i) {
      pcl::PointXYZRGB& p = loaded.xyzrgb[i];
      p.getVector3fMap() = loaded.xyz[i].getVector3fMap();
      std::uint32_t rgba;
      std::memcpy(&rgba, cloud.data.data() + i * cloud.point_step + color->offset, sizeof(rgba));
      p.rgba = rgba;
    }
  }
  return loaded;
}

}  // namespace pcd_segment
