// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/pcd_file.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <lzf.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "floodplane/io/atomic_file.h"

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

// One value of a field as PCL's writeASCII writes it: integers as numbers, a float or double
// with `precision` significant digits, NaN as "nan", and a float field named rgb as the
// unsigned integer of its bits (several opaque colours are NaNs as floats).
template <typename T>
void writeAsciiValue(std::ostringstream& out, const char* data) {
  T value;
  std::memcpy(&value, data, sizeof(T));
  if constexpr (std::is_floating_point_v<T>) {
    if (std::isnan(value)) {
      out << "nan";
      return;
    }
    out << value;
  } else if constexpr (std::is_signed_v<T>) {
    out << static_cast<std::int64_t>(value);
  } else {
    out << static_cast<std::uint64_t>(value);
  }
}

// PCL's ASCII layout, as its writeASCII<PointT> writes it with 9 significant digits (every
// float round-trips exactly; PCL's default is 8), made in memory so that the file is written
// by writeBytesAtomically, which checks every write.
template <typename PointT>
std::string asciiPcd(const pcl::PointCloud<PointT>& cloud) {
  std::vector<pcl::PCLPointField> fields;
  pcl::getFields<PointT>(fields);
  fields.erase(std::remove_if(fields.begin(), fields.end(), [](const auto& field) { return field.name == "_"; }),
               fields.end());
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(9);
  out << pcl::PCDWriter::generateHeader<PointT>(cloud) << "DATA ascii\n";
  for (const PointT& point : cloud) {
    const char* base = reinterpret_cast<const char*>(&point);
    bool first = true;
    for (const pcl::PCLPointField& field : fields) {
      const std::uint32_t count = std::max<std::uint32_t>(field.count, 1);
      for (std::uint32_t c = 0; c < count; ++c) {
        if (!first) out << ' ';
        first = false;
        const char* data = base + field.offset + c * static_cast<std::uint32_t>(pcl::getFieldSize(field.datatype));
        switch (field.datatype) {
          case pcl::PCLPointField::INT8:
            writeAsciiValue<std::int8_t>(out, data);
            break;
          case pcl::PCLPointField::UINT8:
            writeAsciiValue<std::uint8_t>(out, data);
            break;
          case pcl::PCLPointField::INT16:
            writeAsciiValue<std::int16_t>(out, data);
            break;
          case pcl::PCLPointField::UINT16:
            writeAsciiValue<std::uint16_t>(out, data);
            break;
          case pcl::PCLPointField::INT32:
            writeAsciiValue<std::int32_t>(out, data);
            break;
          case pcl::PCLPointField::UINT32:
            writeAsciiValue<std::uint32_t>(out, data);
            break;
          case pcl::PCLPointField::FLOAT32:
            if (field.name == "rgb") {
              writeAsciiValue<std::uint32_t>(out, data);
            } else {
              writeAsciiValue<float>(out, data);
            }
            break;
          case pcl::PCLPointField::FLOAT64:
            writeAsciiValue<double>(out, data);
            break;
          default:
            throw std::runtime_error("cannot encode the PCD data: field " + field.name + " of an unknown type");
        }
      }
    }
    out << '\n';
  }
  return std::move(out).str();
}

// PCL's binary_compressed layout, as its writeBinaryCompressed lays it out (and its reader and
// the shared tools' readers expect): the header, then the compressed size and the uncompressed
// size (little-endian 32-bit), then the points' fields one after the other, each field's values
// of all points together ("_" padding left out), compressed with LZF. Made here from whole
// buffers: PCL's writer puts the file through std::ostream one byte at a time, which cost more
// than the segmentation of the frame.
template <typename PointT>
std::string binaryCompressedPcd(const pcl::PointCloud<PointT>& cloud) {
  std::vector<pcl::PCLPointField> fields;
  pcl::getFields<PointT>(fields);
  fields.erase(std::remove_if(fields.begin(), fields.end(), [](const auto& field) { return field.name == "_"; }),
               fields.end());
  const std::size_t points = cloud.size();
  std::size_t point_bytes = 0;
  for (const pcl::PCLPointField& field : fields) point_bytes += field.count * pcl::getFieldSize(field.datatype);
  const std::size_t data_size = points * point_bytes;
  if (data_size > std::numeric_limits<std::uint32_t>::max() / 2) {
    throw std::runtime_error("cannot encode the PCD data: " + std::to_string(data_size) + " bytes are too many");
  }
  // Fields one after the other: field k's values of all points at its offset in `planar`.
  std::vector<char> planar(data_size);
  std::size_t at = 0;
  const char* const first = reinterpret_cast<const char*>(cloud.points.data());
  for (const pcl::PCLPointField& field : fields) {
    const std::size_t bytes = field.count * pcl::getFieldSize(field.datatype);
    char* out = planar.data() + at;
    const char* in = first + field.offset;
    if (bytes == 4) {
      for (std::size_t i = 0; i < points; ++i, out += 4, in += sizeof(PointT)) std::memcpy(out, in, 4);
    } else {
      for (std::size_t i = 0; i < points; ++i, out += bytes, in += sizeof(PointT)) std::memcpy(out, in, bytes);
    }
    at += bytes * points;
  }
  std::string file = pcl::PCDWriter::generateHeader<PointT>(cloud) + "DATA binary_compressed\n";
  const std::size_t header = file.size();
  // As PCL sizes it: LZF never grows data by more than this.
  const std::size_t capacity = data_size * 3 / 2 + 8;
  file.resize(header + 8 + capacity);
  unsigned compressed = 0;
  if (data_size > 0) {
    compressed = lzf_compress(planar.data(), static_cast<unsigned>(data_size), &file[header + 8],
                              static_cast<unsigned>(capacity));
    if (compressed == 0) throw std::runtime_error("cannot encode the PCD data: LZF compression failed");
  }
  const std::uint32_t sizes[2] = {static_cast<std::uint32_t>(compressed), static_cast<std::uint32_t>(data_size)};
  std::memcpy(&file[header], sizes, sizeof(sizes));
  file.resize(header + 8 + compressed);
  return file;
}

}  // namespace

template <typename PointT>
std::string encodePcd(const pcl::PointCloud<PointT>& cloud, PcdEncoding encoding) {
  switch (encoding) {
    case PcdEncoding::binary:
      return binaryPcd(cloud);
    case PcdEncoding::binary_compressed:
      return binaryCompressedPcd(cloud);
    case PcdEncoding::ascii:
      return asciiPcd(cloud);
  }
  throw std::invalid_argument("encodePcd: unknown encoding");
}

template <typename PointT>
void savePcd(const std::string& path, const pcl::PointCloud<PointT>& cloud, PcdEncoding encoding) {
  std::string bytes;
  try {
    bytes = encodePcd(cloud, encoding);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("cannot write PCD file '" + path + "': " + error.what());
  }
  writeBytesAtomically(path, bytes);
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
