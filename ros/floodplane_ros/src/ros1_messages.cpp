// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "ros1_messages.h"

#include <stdexcept>
#include <string>

#include "label_image.h"

namespace floodplane_ros {
namespace conv = floodplane::conversion;

// Plane.msg's class constants are the library's values: planeMessage casts one to the other.
static_assert(Plane::OTHER == static_cast<std::uint8_t>(floodplane::PlaneClass::kOther));
static_assert(Plane::FLOOR == static_cast<std::uint8_t>(floodplane::PlaneClass::kFloor));
static_assert(Plane::CEILING == static_cast<std::uint8_t>(floodplane::PlaneClass::kCeiling));
static_assert(Plane::WALL == static_cast<std::uint8_t>(floodplane::PlaneClass::kWall));
static_assert(Plane::HORIZONTAL_SURFACE == static_cast<std::uint8_t>(floodplane::PlaneClass::kHorizontalSurface));

conv::CloudView cloudView(const sensor_msgs::PointCloud2& cloud) {
  conv::CloudView view;
  view.width = cloud.width;
  view.height = cloud.height;
  view.fields.reserve(cloud.fields.size());
  for (const sensor_msgs::PointField& field : cloud.fields) {
    view.fields.push_back({field.name, field.offset, field.datatype, field.count});
  }
  view.is_bigendian = cloud.is_bigendian;
  view.point_step = cloud.point_step;
  view.row_step = cloud.row_step;
  view.data = cloud.data.data();
  view.data_size = cloud.data.size();
  return view;
}

conv::ImageView imageView(const sensor_msgs::Image& image) {
  conv::ImageView view;
  view.width = image.width;
  view.height = image.height;
  view.encoding = image.encoding;
  view.is_bigendian = image.is_bigendian;
  view.step = image.step;
  view.data = image.data.data();
  view.data_size = image.data.size();
  return view;
}

conv::CameraInfoView cameraInfoView(const sensor_msgs::CameraInfo& info) {
  conv::CameraInfoView view;
  view.width = info.width;
  view.height = info.height;
  for (std::size_t i = 0; i < view.k.size(); ++i) view.k[i] = info.K[i];
  return view;
}

Plane planeMessage(const conv::PlaneDescription& plane) {
  Plane message;
  message.label = plane.label;
  message.track_id = plane.track_id;
  for (std::size_t i = 0; i < 4; ++i) message.plane.coef[i] = plane.coefficients[i];
  message.centroid.x = plane.centroid[0];
  message.centroid.y = plane.centroid[1];
  message.centroid.z = plane.centroid[2];
  message.inlier_count = plane.inlier_count;
  message.mean_squared_error = plane.mean_squared_error;
  message.plane_class = static_cast<std::uint8_t>(plane.plane_class);
  message.height_above_floor = plane.height_above_floor;
  return message;
}

conv::RigidTransform rigidTransform(const geometry_msgs::Transform& transform) {
  conv::RigidTransform rigid;
  rigid.translation = {transform.translation.x, transform.translation.y, transform.translation.z};
  rigid.rotation = {transform.rotation.x, transform.rotation.y, transform.rotation.z, transform.rotation.w};
  return rigid;
}

pcl_msgs::PointIndices pointIndices(const std_msgs::Header& header, const conv::ChainedPlane& plane) {
  pcl_msgs::PointIndices message;
  message.header = header;
  message.indices = plane.indices;
  return message;
}

pcl_msgs::ModelCoefficients modelCoefficients(const std_msgs::Header& header, const conv::ChainedPlane& plane) {
  pcl_msgs::ModelCoefficients message;
  message.header = header;
  message.values = plane.coefficients;
  return message;
}

sensor_msgs::Image labelImage(const std_msgs::Header& header, int width, int height,
                              const std::vector<std::uint32_t>& labels,
                              const std::vector<std::uint32_t>& plane_labels) {
  if (labels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("labelImage: " + std::to_string(labels.size()) + " labels for a " +
                                std::to_string(width) + "x" + std::to_string(height) + " image");
  }
  sensor_msgs::Image image;
  image.header = header;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.encoding = conv::kLabelImageEncoding;
  image.is_bigendian = conv::labelImageIsBigEndian();
  image.step = image.width * conv::kLabelImageBytesPerPixel;
  image.data.resize(static_cast<std::size_t>(image.step) * image.height);
  conv::writeLabelImage(labels, plane_labels, image.data.data());
  return image;
}

sensor_msgs::PointCloud2 organizedCloud(const std_msgs::Header& header, int width, int height,
                                        const std::vector<conv::PointField>& fields, std::uint32_t point_step) {
  sensor_msgs::PointCloud2 cloud;
  cloud.header = header;
  cloud.width = static_cast<std::uint32_t>(width);
  cloud.height = static_cast<std::uint32_t>(height);
  for (const conv::PointField& field : fields) {
    sensor_msgs::PointField message;
    message.name = field.name;
    message.offset = field.offset;
    message.datatype = field.datatype;
    message.count = field.count;
    cloud.fields.push_back(message);
  }
  cloud.is_bigendian = false;
  cloud.point_step = point_step;
  cloud.row_step = point_step * cloud.width;
  cloud.is_dense = false;  // points without a return stay NaN
  cloud.data.resize(static_cast<std::size_t>(cloud.row_step) * cloud.height);
  return cloud;
}

namespace {

geometry_msgs::Point point(const std::array<float, 3>& p) {
  geometry_msgs::Point message;
  message.x = p[0];
  message.y = p[1];
  message.z = p[2];
  return message;
}

visualization_msgs::Marker marker(const std_msgs::Header& header, const char* ns, int id, int type,
                                  const conv::PlaneOutline& outline) {
  visualization_msgs::Marker m;
  m.header = header;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.color.r = outline.color[0];
  m.color.g = outline.color[1];
  m.color.b = outline.color[2];
  m.color.a = 1.0f;
  return m;
}

}  // namespace

visualization_msgs::MarkerArray planeMarkers(const std_msgs::Header& header,
                                             const std::vector<conv::PlaneOutline>& outlines, double line_width) {
  visualization_msgs::MarkerArray array;
  array.markers.reserve(2 * outlines.size() + 1);
  visualization_msgs::Marker clear;
  clear.header = header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);
  for (std::size_t k = 0; k < outlines.size(); ++k) {
    const conv::PlaneOutline& outline = outlines[k];
    const int id = static_cast<int>(k);
    visualization_msgs::Marker line = marker(header, "outlines", id, visualization_msgs::Marker::LINE_STRIP, outline);
    line.scale.x = line_width;
    line.points.reserve(outline.points.size());
    for (const auto& p : outline.points) line.points.push_back(point(p));
    array.markers.push_back(std::move(line));

    visualization_msgs::Marker arrow = marker(header, "normals", id, visualization_msgs::Marker::ARROW, outline);
    arrow.scale.x = line_width;      // shaft diameter
    arrow.scale.y = 3 * line_width;  // head diameter
    arrow.scale.z = 0.0;             // head length: rviz's default
    arrow.points = {point(outline.normal_start), point(outline.normal_end)};
    array.markers.push_back(std::move(arrow));
  }
  return array;
}

}  // namespace floodplane_ros
