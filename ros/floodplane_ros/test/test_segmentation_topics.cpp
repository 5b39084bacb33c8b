// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The rostest of the node and the nodelet, in a camera's namespace as floodplane.launch puts
// them (~cameras names the cameras; the first one's instance gets the SegmentationNode tests,
// two get TwoCameras'): frames in on their topics (the real frames of
// ../shared/data/real when they are there, rendered ones otherwise; rendered depth images in
// millimetres and in metres), the published planes, label cloud, label image, the largest
// plane's inliers and model, and markers compared with the library's own output for the same
// frames, parameters changed by dynamic_reconfigure, track
// ids, frames without a finite point (a cloud of NaN, a depth image of zeros) answered with no
// planes, and bad messages (an unorganized cloud, a wrong encoding) answered by an error in
// the log and nothing else: the node goes on with the next frame. Each frame's time comes in
// its planes, at debug level in the log, and in the node's status on /diagnostics.
//
// The tests run in order against one node, whose stream of frames the test follows with its
// own Segmenter and PlaneTracker (head starts make a frame's result depend on the frames
// before it).
//
// ~input says what the launch file told the nodes to segment: both (clouds and depth images,
// the default here) or points.

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <floodplane_ros/Planes.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <pcl_msgs/PointIndices.h>
#include <ros/ros.h>
#include <roscpp/SetLoggerLevel.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <visualization_msgs/MarkerArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "floodplane/io/depth_camera.h"
#include "floodplane/io/label_palette.h"
#include "floodplane/io/pcd_input.h"
#include "floodplane/object_segmentation.h"
#include "floodplane/plane_tracker.h"
#include "floodplane/segmenter.h"
#include "synth/room_walk.h"

namespace {

using floodplane::Segmentation;

constexpr double kWaitSeconds = 60.0;

// One frame: x y z on its grid (stride 3, NaN for no return) and, when it was rendered, the
// camera that saw it (for depth images).
struct Frame {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<float> xyz;
  floodplane::io::DepthCamera camera;
  floodplane::PointGrid grid() const {
    floodplane::PointGrid grid;
    grid.data = xyz.data();
    grid.width = width;
    grid.height = height;
    return grid;
  }
};

std::vector<Frame> renderedFrames() {
  std::vector<Frame> frames;
  int index = 0;
  for (const auto& rendered : floodplane::synth::renderRoomWalk(11, 3, floodplane::synth::SensorModel::kinect)) {
    Frame frame;
    frame.name = "rendered walk frame " + std::to_string(index++);
    frame.width = rendered.intrinsics.width;
    frame.height = rendered.intrinsics.height;
    for (const auto& p : rendered.points) frame.xyz.insert(frame.xyz.end(), {p.x(), p.y(), p.z()});
    frame.camera = {rendered.intrinsics.fx, rendered.intrinsics.fy, rendered.intrinsics.cx, rendered.intrinsics.cy,
                    1000.0};
    frames.push_back(std::move(frame));
  }
  return frames;
}

// The real frames when ../shared/data/real is there (sorted by name: the three consecutive
// desk frames stay in order), rendered ones otherwise.
std::vector<Frame> cloudFrames() {
  namespace fs = std::filesystem;
  std::vector<std::string> paths;
  const fs::path folder(FLOODPLANE_REAL_DATA_DIR);
  if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder)) {
      if (entry.path().extension() == ".pcd") paths.push_back(entry.path().string());
    }
  }
  if (paths.empty()) {
    std::cout << "[ INFO     ] no real frames in " << folder << ": playing rendered ones\n";
    return renderedFrames();
  }
  std::sort(paths.begin(), paths.end());
  std::vector<Frame> frames;
  for (const std::string& path : paths) {
    const auto input = floodplane::io::readPcdFrame(path);
    Frame frame;
    frame.name = fs::path(path).filename().string();
    frame.width = static_cast<int>(input.xyz.width);
    frame.height = static_cast<int>(input.xyz.height);
    for (const auto& p : input.xyz.points) frame.xyz.insert(frame.xyz.end(), {p.x, p.y, p.z});
    frames.push_back(std::move(frame));
  }
  return frames;
}

// PCL's PointXYZRGB layout as a driver publishes it (x y z, padding, rgb: 32 bytes).
sensor_msgs::PointCloud2 cloudMessage(const Frame& frame) {
  sensor_msgs::PointCloud2 cloud;
  cloud.header.frame_id = "camera_depth_optical_frame";
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2FieldsByString(2, "xyz", "rgb");
  modifier.resize(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height));
  cloud.width = static_cast<std::uint32_t>(frame.width);
  cloud.height = static_cast<std::uint32_t>(frame.height);
  cloud.row_step = cloud.width * cloud.point_step;
  cloud.is_dense = false;
  sensor_msgs::PointCloud2Iterator<float> x(cloud, "x");
  for (std::size_t i = 0; i < frame.xyz.size() / 3; ++i, ++x) {
    x[0] = frame.xyz[3 * i];
    x[1] = frame.xyz[3 * i + 1];
    x[2] = frame.xyz[3 * i + 2];
  }
  return cloud;
}

// A frame's depth image (16UC1 millimetres, rounded, or 32FC1 metres) and its CameraInfo,
// and the points the library makes of them (io::backProjectPixel, as pcd_segment does).
struct DepthFrame {
  sensor_msgs::Image image;
  sensor_msgs::CameraInfo info;
  Frame points;
};

DepthFrame depthFrame(const Frame& frame, bool millimetres) {
  DepthFrame depth;
  depth.image.header.frame_id = depth.info.header.frame_id = "camera_depth_optical_frame";
  depth.image.width = depth.info.width = static_cast<std::uint32_t>(frame.width);
  depth.image.height = depth.info.height = static_cast<std::uint32_t>(frame.height);
  depth.image.encoding = millimetres ? "16UC1" : "32FC1";
  depth.image.step = depth.image.width * (millimetres ? 2 : 4);
  depth.image.data.resize(static_cast<std::size_t>(depth.image.step) * depth.image.height);
  depth.info.K = {frame.camera.fx, 0.0, frame.camera.cx, 0.0, frame.camera.fy, frame.camera.cy, 0.0, 0.0, 1.0};
  depth.info.distortion_model = "plumb_bob";
  depth.points = frame;
  floodplane::io::DepthCamera camera = frame.camera;
  camera.depth_scale = millimetres ? 1000.0 : 1.0;
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const std::size_t i =
          static_cast<std::size_t>(v) * static_cast<std::size_t>(frame.width) + static_cast<std::size_t>(u);
      const float z = frame.xyz[3 * i + 2];
      double units = 0.0;
      if (millimetres) {
        const auto mm = static_cast<std::uint16_t>(std::isfinite(z) ? std::lround(z * 1000.0) : 0);
        std::memcpy(depth.image.data.data() + 2 * i, &mm, 2);
        units = mm;
      } else {
        const float metres = std::isfinite(z) ? z : std::numeric_limits<float>::quiet_NaN();
        std::memcpy(depth.image.data.data() + 4 * i, &metres, 4);
        units = std::isfinite(metres) ? metres : 0.0;
      }
      floodplane::io::backProjectPixel(u, v, units, camera, &depth.points.xyz[3 * i]);
    }
  }
  return depth;
}

// The points of a cloud message as the library reads them in place (cloudMessage's layout).
floodplane::PointGrid pointsOf(const sensor_msgs::PointCloud2& cloud) {
  floodplane::PointGrid grid;
  grid.data = reinterpret_cast<const float*>(cloud.data.data());
  grid.stride = cloud.point_step / sizeof(float);
  grid.width = static_cast<int>(cloud.width);
  grid.height = static_cast<int>(cloud.height);
  return grid;
}

using Clock = std::chrono::steady_clock;

// The largest id in a 32SC1 label image (its objects' count: ids 1..K are all there).
std::size_t largestLabel(const sensor_msgs::Image& image) {
  std::int32_t largest = 0;
  for (std::size_t i = 0; i + 4 <= image.data.size(); i += 4) {
    std::int32_t pixel;
    std::memcpy(&pixel, image.data.data() + i, 4);
    largest = std::max(largest, pixel);
  }
  return static_cast<std::size_t>(largest);
}

// What the node published for one frame.
struct Published {
  floodplane_ros::PlanesConstPtr planes;
  sensor_msgs::PointCloud2ConstPtr labels;
  sensor_msgs::ImageConstPtr label_image;
  pcl_msgs::PointIndicesConstPtr inliers;
  pcl_msgs::ModelCoefficientsConstPtr model;
  visualization_msgs::MarkerArrayConstPtr markers;
  // The objects on the planes: their label image and one PointIndices per object.
  sensor_msgs::ImageConstPtr object_image;
  std::vector<pcl_msgs::PointIndicesConstPtr> object_indices;
  // From just before the frame was sent to the planes' arrival: the node's time for the frame
  // lies within it.
  Clock::time_point sent;
  Clock::time_point planes_arrived;
  double roundTripMilliseconds() const {
    return std::chrono::duration<double, std::milli>(planes_arrived - sent).count();
  }
  bool complete() const {
    return planes && labels && label_image && inliers && model && markers && object_image &&
           object_indices.size() == largestLabel(*object_image);
  }
  bool any() const {
    return planes || labels || label_image || inliers || model || markers || object_image || !object_indices.empty();
  }
};

// The node's report on /diagnostics: its level and its values by key.
struct Status {
  std::uint8_t level = 0;
  std::string message;
  std::string hardware_id;
  std::map<std::string, std::string> values;
};

// The node's topics in its camera's namespace, seen from outside, and the test's mirror of its
// stream.
class NodeUnderTest {
 public:
  // `depth_images`: the node segments depth images too (input:=both), not only clouds.
  NodeUnderTest(const std::string& camera, bool depth_images)
      : camera_(camera), depth_images_(depth_images), nh_("/" + camera) {
    points_ = nh_.advertise<sensor_msgs::PointCloud2>("depth/points", 2);
    image_ = nh_.advertise<sensor_msgs::Image>("depth/image_rect", 2);
    camera_info_ = nh_.advertise<sensor_msgs::CameraInfo>("depth/camera_info", 2);
    planes_sub_ = nh_.subscribe("planes", 10, &NodeUnderTest::onPlanes, this);
    labels_sub_ = nh_.subscribe("plane_labels", 10, &NodeUnderTest::onLabels, this);
    markers_sub_ = nh_.subscribe("plane_markers", 10, &NodeUnderTest::onMarkers, this);
    label_image_sub_ = nh_.subscribe("plane_label_image", 10, &NodeUnderTest::onLabelImage, this);
    inliers_sub_ = nh_.subscribe("inliers", 10, &NodeUnderTest::onInliers, this);
    model_sub_ = nh_.subscribe("model", 10, &NodeUnderTest::onModel, this);
    object_image_sub_ = nh_.subscribe("object_label_image", 10, &NodeUnderTest::onObjectImage, this);
    object_indices_sub_ = nh_.subscribe("object_indices", 4096, &NodeUnderTest::onObjectIndices, this);
    rosout_sub_ = nh_.subscribe("/rosout", 100, &NodeUnderTest::onLog, this);
    diagnostics_sub_ = nh_.subscribe("/diagnostics", 10, &NodeUnderTest::onDiagnostics, this);
    options_.head_start = true;  // the node's default
  }

  // Whether every topic is connected both ways within the wait.
  bool connect() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kWaitSeconds);
    while (std::chrono::steady_clock::now() < deadline) {
      const bool depth_connected = image_.getNumSubscribers() > 0 && camera_info_.getNumSubscribers() > 0;
      if (points_.getNumSubscribers() > 0 && (depth_connected || !depth_images_) &&
          planes_sub_.getNumPublishers() > 0 && labels_sub_.getNumPublishers() > 0 &&
          markers_sub_.getNumPublishers() > 0 && label_image_sub_.getNumPublishers() > 0 &&
          inliers_sub_.getNumPublishers() > 0 && model_sub_.getNumPublishers() > 0 &&
          object_image_sub_.getNumPublishers() > 0 && object_indices_sub_.getNumPublishers() > 0 &&
          ros::service::exists(nodeName() + "/set_parameters", false)) {
        return true;
      }
      ros::WallDuration(0.05).sleep();
    }
    return false;
  }

  Published sendCloud(sensor_msgs::PointCloud2 cloud) {
    cloud.header.stamp = nextStamp();
    markSent(cloud.header.stamp);
    points_.publish(cloud);
    return waitFor(cloud.header.stamp);
  }

  Published sendDepth(DepthFrame depth) {
    depth.image.header.stamp = depth.info.header.stamp = nextStamp();
    markSent(depth.image.header.stamp);
    camera_info_.publish(depth.info);
    image_.publish(depth.image);
    return waitFor(depth.image.header.stamp);
  }

  // Sets a logger's level in the process that runs the node, as `rosconsole set` does.
  bool setLoggerLevel(const std::string& process, const std::string& logger, const std::string& level) {
    roscpp::SetLoggerLevel service;
    service.request.logger = logger;
    service.request.level = level;
    return ros::service::call(process + "/set_logger_level", service);
  }

  // The first debug line of a frame's time logged after `since` such lines came ("" if none
  // came within the wait). /rosout names the node, not the logger.
  std::size_t timingLineCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return timing_lines_.size();
  }
  std::string waitForTimingLine(std::size_t since) {
    std::unique_lock<std::mutex> lock(mutex_);
    const bool logged = arrived_.wait_for(lock, std::chrono::duration<double>(kWaitSeconds),
                                          [&] { return timing_lines_.size() > since || !ros::ok(); });
    return logged ? timing_lines_[since] : std::string();
  }

  // The first report on /diagnostics named `name` that counts at least `frames` frames
  // segmented and `skipped` messages skipped since the node started (an empty Status if none
  // came within the wait).
  Status waitForStatus(const std::string& name, std::size_t frames, std::size_t skipped) {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto counts = [](const Status& status, const char* key, std::size_t least) {
      const auto value = status.values.find(key);
      return value != status.values.end() && std::stoul(value->second) >= least;
    };
    Status found;
    arrived_.wait_for(lock, std::chrono::duration<double>(kWaitSeconds), [&] {
      for (const Status& status : statuses_[name]) {
        if (counts(status, "Frames segmented since start", frames) &&
            counts(status, "Messages skipped since start", skipped)) {
          found = status;
          return true;
        }
      }
      return !ros::ok();
    });
    return found;
  }

  // Frames the node published a complete result for.
  std::size_t framesAnswered() {
    std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<std::size_t>(
        std::count_if(published_.begin(), published_.end(), [](const auto& entry) { return entry.second.complete(); }));
  }

  // Sends a bad cloud or depth image and returns the error the node logged ("" if none came
  // within the wait); nothing may have been published for it.
  std::string sendBadCloud(sensor_msgs::PointCloud2 cloud) {
    cloud.header.stamp = nextStamp();
    const std::size_t logs = logCount();
    points_.publish(cloud);
    return waitForError(logs, cloud.header.stamp);
  }
  std::string sendBadDepth(DepthFrame depth) {
    depth.image.header.stamp = depth.info.header.stamp = nextStamp();
    const std::size_t logs = logCount();
    camera_info_.publish(depth.info);
    image_.publish(depth.image);
    return waitForError(logs, depth.image.header.stamp);
  }

  // Sets parameters through dynamic_reconfigure as rqt_reconfigure would.
  bool reconfigure(const std::map<std::string, int>& ints, const std::map<std::string, bool>& bools) {
    dynamic_reconfigure::Reconfigure service;
    for (const auto& [name, value] : ints) {
      dynamic_reconfigure::IntParameter parameter;
      parameter.name = name;
      parameter.value = value;
      service.request.config.ints.push_back(parameter);
    }
    for (const auto& [name, value] : bools) {
      dynamic_reconfigure::BoolParameter parameter;
      parameter.name = name;
      parameter.value = value;
      service.request.config.bools.push_back(parameter);
    }
    return ros::service::call(nodeName() + "/set_parameters", service);
  }

  const std::string& camera() const { return camera_; }
  std::uint32_t depthImageSubscribers() const { return image_.getNumSubscribers(); }
  // The node's (or the nodelet's) name: floodplane in the camera's namespace.
  std::string nodeName() const { return "/" + camera_ + "/floodplane"; }

  // The test's own copy of the node's stream: what the library gives for the same frames.
  floodplane::Segmenter library;
  floodplane::PlaneTracker tracker;
  floodplane::Segmenter::Options options_;
  bool tracking = false;

 private:
  ros::Time nextStamp() { return ros::Time(1000 + ++frames_sent_, 0); }

  void markSent(const ros::Time& stamp) {
    std::lock_guard<std::mutex> lock(mutex_);
    published_[stamp].sent = Clock::now();
  }

  Published waitFor(const ros::Time& stamp) {
    std::unique_lock<std::mutex> lock(mutex_);
    arrived_.wait_for(lock, std::chrono::duration<double>(kWaitSeconds),
                      [&] { return published_[stamp].complete() || !ros::ok(); });
    return published_[stamp];
  }

  std::size_t logCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return errors_.size();
  }

  std::string waitForError(std::size_t before, const ros::Time& stamp) {
    std::unique_lock<std::mutex> lock(mutex_);
    const bool logged = arrived_.wait_for(lock, std::chrono::duration<double>(kWaitSeconds),
                                          [&] { return errors_.size() > before || !ros::ok(); });
    const Published& published = published_[stamp];
    EXPECT_FALSE(published.any()) << "published for a bad frame";
    return logged ? errors_[before] : std::string();
  }

  void onPlanes(const floodplane_ros::PlanesConstPtr& planes) {
    const Clock::time_point arrived = Clock::now();
    store(planes->header.stamp, [&](Published& p) {
      p.planes = planes;
      p.planes_arrived = arrived;
    });
  }
  void onLabels(const sensor_msgs::PointCloud2ConstPtr& labels) {
    store(labels->header.stamp, [&](Published& p) { p.labels = labels; });
  }
  void onLabelImage(const sensor_msgs::ImageConstPtr& image) {
    store(image->header.stamp, [&](Published& p) { p.label_image = image; });
  }
  void onInliers(const pcl_msgs::PointIndicesConstPtr& inliers) {
    store(inliers->header.stamp, [&](Published& p) { p.inliers = inliers; });
  }
  void onModel(const pcl_msgs::ModelCoefficientsConstPtr& model) {
    store(model->header.stamp, [&](Published& p) { p.model = model; });
  }
  void onObjectImage(const sensor_msgs::ImageConstPtr& image) {
    store(image->header.stamp, [&](Published& p) { p.object_image = image; });
  }
  void onObjectIndices(const pcl_msgs::PointIndicesConstPtr& indices) {
    store(indices->header.stamp, [&](Published& p) { p.object_indices.push_back(indices); });
  }
  void onMarkers(const visualization_msgs::MarkerArrayConstPtr& markers) {
    if (markers->markers.empty()) return;  // never: a DELETEALL leads every array
    store(markers->markers.front().header.stamp, [&](Published& p) { p.markers = markers; });
  }
  void onLog(const rosgraph_msgs::LogConstPtr& log) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (log->level == rosgraph_msgs::Log::ERROR && log->msg.find("frame skipped") != std::string::npos) {
      errors_.push_back(log->msg);
    } else if (log->level == rosgraph_msgs::Log::DEBUG && log->msg.find(" segmented in ") != std::string::npos) {
      timing_lines_.push_back(log->msg);
    } else {
      return;
    }
    arrived_.notify_all();
  }
  void onDiagnostics(const diagnostic_msgs::DiagnosticArrayConstPtr& array) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& message : array->status) {
      Status status;
      status.level = message.level;
      status.message = message.message;
      status.hardware_id = message.hardware_id;
      for (const auto& value : message.values) status.values[value.key] = value.value;
      statuses_[message.name].push_back(std::move(status));
    }
    arrived_.notify_all();
  }
  template <typename Set>
  void store(const ros::Time& stamp, Set set) {
    std::lock_guard<std::mutex> lock(mutex_);
    set(published_[stamp]);
    arrived_.notify_all();
  }

  std::string camera_;
  bool depth_images_;
  ros::NodeHandle nh_;
  ros::Publisher points_, image_, camera_info_;
  ros::Subscriber planes_sub_, labels_sub_, markers_sub_, label_image_sub_, inliers_sub_, model_sub_, object_image_sub_,
      object_indices_sub_, rosout_sub_, diagnostics_sub_;
  std::mutex mutex_;
  std::condition_variable arrived_;
  std::map<ros::Time, Published> published_;
  std::vector<std::string> errors_;
  std::vector<std::string> timing_lines_;
  std::map<std::string, std::vector<Status>> statuses_;
  std::uint32_t frames_sent_ = 0;
};

// The instances under test, one a camera; `node` is the first.
std::vector<std::unique_ptr<NodeUnderTest>> cameras;
NodeUnderTest* node = nullptr;

// Compares what the node published for `frame` with the library's result for the points in
// `layout`: the frame's points as the node got them. The layout matters to the last bits of
// the plane fits (the core sums points in another order for PCL's 8-float stride than for 3).
// A frame without a finite point never reaches the node's Segmenter (its noise model stays the
// last real frame's): its result is no plane, every label 0.
bool hasFinitePoint(const floodplane::PointGrid& grid) {
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid.isFinite(i)) return true;
  }
  return false;
}

void expectLibrarysResult(NodeUnderTest& under_test, const Published& published, const Frame& frame,
                          const floodplane::PointGrid& layout) {
  ASSERT_TRUE(published.complete()) << frame.name << ": the node published nothing within " << kWaitSeconds << " s";
  Segmentation no_planes;
  no_planes.width = layout.width;
  no_planes.height = layout.height;
  no_planes.labels.assign(layout.size(), 0);
  const Segmentation& expected =
      hasFinitePoint(layout) ? under_test.library.segment(layout, under_test.options_) : no_planes;
  std::vector<std::uint32_t> labels(expected.planes.size());
  for (std::size_t k = 0; k < labels.size(); ++k) labels[k] = static_cast<std::uint32_t>(k + 1);
  std::vector<std::uint32_t> track_ids;
  if (under_test.tracking) labels = track_ids = under_test.tracker.update(expected);

  // The node's time for the frame: some, and no more than the test waited for it.
  EXPECT_GT(published.planes->segmentation_time_ms, 0.0) << frame.name;
  EXPECT_LT(published.planes->segmentation_time_ms, published.roundTripMilliseconds()) << frame.name;

  const auto& planes = published.planes->planes;
  ASSERT_EQ(planes.size(), expected.planes.size()) << frame.name;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const auto& fit = expected.planes[k].fit;
    EXPECT_EQ(planes[k].label, labels[k]) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].track_id, under_test.tracking ? track_ids[k] : 0u) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].inlier_count, expected.planes[k].inlier_count) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].plane.coef[0], fit.normal.x()) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].plane.coef[1], fit.normal.y()) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].plane.coef[2], fit.normal.z()) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].plane.coef[3], fit.offset) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].centroid.x, fit.centroid.x()) << frame.name << " plane " << k;
    EXPECT_EQ(planes[k].centroid.z, fit.centroid.z()) << frame.name << " plane " << k;
    // No up direction (floodplane.launch's default): not classed.
    EXPECT_EQ(planes[k].plane_class, floodplane_ros::Plane::OTHER) << frame.name << " plane " << k;
    EXPECT_TRUE(std::isnan(planes[k].height_above_floor)) << frame.name << " plane " << k;
  }

  const sensor_msgs::PointCloud2& cloud = *published.labels;
  ASSERT_EQ(cloud.width, static_cast<std::uint32_t>(frame.width));
  ASSERT_EQ(cloud.height, static_cast<std::uint32_t>(frame.height));
  sensor_msgs::PointCloud2ConstIterator<float> x(cloud, "x");
  sensor_msgs::PointCloud2ConstIterator<std::uint32_t> label(cloud, "label");
  std::size_t wrong_labels = 0, wrong_points = 0;
  for (std::size_t i = 0; i < expected.labels.size(); ++i, ++x, ++label) {
    const std::uint32_t k = expected.labels[i];
    if (*label != (k == 0 ? 0u : labels[k - 1])) ++wrong_labels;
    for (int axis = 0; axis < 3; ++axis) {
      const float want = frame.xyz[3 * i + static_cast<std::size_t>(axis)];
      if (!(x[axis] == want || (std::isnan(want) && std::isnan(x[axis])))) ++wrong_points;
    }
  }
  EXPECT_EQ(wrong_labels, 0u) << frame.name;
  EXPECT_EQ(wrong_points, 0u) << frame.name;

  // The label image: the same labels on the same grid, 32SC1, with the input's header.
  const sensor_msgs::Image& image = *published.label_image;
  EXPECT_EQ(image.header.frame_id, cloud.header.frame_id);
  EXPECT_EQ(image.header.stamp, cloud.header.stamp);
  EXPECT_EQ(image.encoding, "32SC1");
  ASSERT_EQ(image.width, static_cast<std::uint32_t>(frame.width));
  ASSERT_EQ(image.height, static_cast<std::uint32_t>(frame.height));
  ASSERT_EQ(image.step, 4 * image.width);
  ASSERT_EQ(image.data.size(), expected.labels.size() * 4);
  std::size_t wrong_pixels = 0;
  for (std::size_t i = 0; i < expected.labels.size(); ++i) {
    std::int32_t pixel;
    std::memcpy(&pixel, image.data.data() + 4 * i, 4);
    const std::uint32_t k = expected.labels[i];
    if (pixel != static_cast<std::int32_t>(k == 0 ? 0u : labels[k - 1])) ++wrong_pixels;
  }
  EXPECT_EQ(wrong_pixels, 0u) << frame.name;

  // The largest plane as pcl_ros's SACSegmentation publishes its model: its pixels' indices in
  // the input cloud, ascending, and its a b c d; both empty without a plane.
  EXPECT_EQ(published.inliers->header, published.planes->header);
  EXPECT_EQ(published.model->header, published.planes->header);
  std::vector<std::int32_t> largest;
  for (std::size_t i = 0; i < expected.labels.size(); ++i) {
    if (expected.labels[i] == 1) largest.push_back(static_cast<std::int32_t>(i));
  }
  EXPECT_EQ(published.inliers->indices, largest) << frame.name;
  if (expected.planes.empty()) {
    EXPECT_TRUE(published.model->values.empty()) << frame.name;
  } else {
    EXPECT_EQ(largest.size(), expected.planes[0].inlier_count) << frame.name;
    const auto& fit = expected.planes[0].fit;
    EXPECT_EQ(published.model->values,
              (std::vector<float>{static_cast<float>(fit.normal.x()), static_cast<float>(fit.normal.y()),
                                  static_cast<float>(fit.normal.z()), static_cast<float>(fit.offset)}))
        << frame.name;
  }

  // The objects on the planes: the library's segmentObjects over the same points and planes,
  // as a label image and one PointIndices per object, in id order, with the input's header.
  const floodplane::ObjectSegmentation objects = floodplane::segmentObjects(layout, expected);
  const sensor_msgs::Image& object_image = *published.object_image;
  EXPECT_EQ(object_image.header.stamp, image.header.stamp);
  EXPECT_EQ(object_image.header.frame_id, image.header.frame_id);
  EXPECT_EQ(object_image.encoding, "32SC1");
  ASSERT_EQ(object_image.data.size(), objects.labels.size() * 4);
  std::size_t wrong_objects = 0;
  std::vector<std::vector<std::int32_t>> object_pixels(objects.objects.size());
  for (std::size_t i = 0; i < objects.labels.size(); ++i) {
    std::int32_t pixel;
    std::memcpy(&pixel, object_image.data.data() + 4 * i, 4);
    if (pixel != static_cast<std::int32_t>(objects.labels[i])) ++wrong_objects;
    if (objects.labels[i] != 0) object_pixels[objects.labels[i] - 1].push_back(static_cast<std::int32_t>(i));
  }
  EXPECT_EQ(wrong_objects, 0u) << frame.name;
  ASSERT_EQ(published.object_indices.size(), objects.objects.size()) << frame.name;
  // Each message is one object's pixels; they arrive in id order on their one topic.
  for (std::size_t k = 0; k < object_pixels.size(); ++k) {
    EXPECT_EQ(published.object_indices[k]->header.stamp, image.header.stamp);
    EXPECT_EQ(published.object_indices[k]->header.frame_id, image.header.frame_id);
    EXPECT_EQ(published.object_indices[k]->indices, object_pixels[k]) << frame.name << " object " << k + 1;
  }

  const auto& markers = published.markers->markers;
  ASSERT_EQ(markers.size(), 1 + 2 * expected.planes.size()) << frame.name;
  EXPECT_EQ(markers[0].action, visualization_msgs::Marker::DELETEALL);
  for (std::size_t k = 0; k < expected.planes.size(); ++k) {
    const auto& outline = markers[1 + 2 * k];
    const auto& arrow = markers[2 + 2 * k];
    EXPECT_EQ(outline.type, visualization_msgs::Marker::LINE_STRIP);
    EXPECT_GE(outline.points.size(), 4u);
    EXPECT_EQ(arrow.type, visualization_msgs::Marker::ARROW);
    ASSERT_EQ(arrow.points.size(), 2u);
    EXPECT_NEAR(arrow.points[0].x, expected.planes[k].fit.centroid.x(), 1e-6);
    EXPECT_EQ(outline.header.frame_id, "camera_depth_optical_frame");
    // Not classed: in its label's colour, as in the label cloud.
    const auto rgb = floodplane::io::labelColor(labels[k]);
    EXPECT_EQ(outline.color.r, rgb[0] / 255.0f) << frame.name << " plane " << k;
    EXPECT_EQ(outline.color.g, rgb[1] / 255.0f) << frame.name << " plane " << k;
    EXPECT_EQ(outline.color.b, rgb[2] / 255.0f) << frame.name << " plane " << k;
  }
}

void expectLibrarysResult(const Published& published, const Frame& frame, const floodplane::PointGrid& layout) {
  expectLibrarysResult(*node, published, frame, layout);
}

TEST(SegmentationNode, PublishesTheLibrarysPlanesForEachOrganizedCloud) {
  for (const Frame& frame : cloudFrames()) {
    const sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
    expectLibrarysResult(node->sendCloud(cloud), frame, pointsOf(cloud));
    if (HasFatalFailure()) return;
  }
}

TEST(SegmentationNode, PublishesTheLibrarysPlanesForDepthImagesInMillimetres) {
  for (const Frame& frame : renderedFrames()) {
    const DepthFrame depth = depthFrame(frame, true);
    expectLibrarysResult(node->sendDepth(depth), depth.points, depth.points.grid());
    if (HasFatalFailure()) return;
  }
}

TEST(SegmentationNode, PublishesTheLibrarysPlanesForDepthImagesInMetres) {
  for (const Frame& frame : renderedFrames()) {
    const DepthFrame depth = depthFrame(frame, false);
    expectLibrarysResult(node->sendDepth(depth), depth.points, depth.points.grid());
    if (HasFatalFailure()) return;
  }
}

TEST(SegmentationNode, TakesNewParametersThroughDynamicReconfigure) {
  const Frame frame = renderedFrames().front();
  const sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
  ASSERT_TRUE(node->reconfigure({{"subsampling", 2}}, {}));
  floodplane::Params params;
  params.subsampling = 2;
  node->library.setParams(params);
  const Published subsampled = node->sendCloud(cloud);
  expectLibrarysResult(subsampled, frame, pointsOf(cloud));

  // Back to the default (the tests after this one run at the node's defaults).
  ASSERT_TRUE(node->reconfigure({{"subsampling", floodplane::Params().subsampling}}, {}));
  node->library.setParams(floodplane::Params());
  const Published by_default = node->sendCloud(cloud);
  expectLibrarysResult(by_default, frame, pointsOf(cloud));
  // The parameter reached the segmentation: planes of another sub-sampling are fitted to other
  // points.
  ASSERT_TRUE(subsampled.complete() && by_default.complete());
  EXPECT_NE(subsampled.planes->planes.front().plane.coef, by_default.planes->planes.front().plane.coef);
}

TEST(SegmentationNode, GivesThePlanesTrackIdsWhenTracking) {
  ASSERT_TRUE(node->reconfigure({}, {{"tracking", true}}));
  node->library.setParams(floodplane::Params());  // the node's reconfigure sets its parameters again
  node->tracking = true;
  std::uint32_t last_id = 0;
  std::size_t planes_seen = 0;
  for (const Frame& frame : renderedFrames()) {
    const sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
    const Published published = node->sendCloud(cloud);
    expectLibrarysResult(published, frame, pointsOf(cloud));
    if (HasFatalFailure()) return;
    for (const auto& plane : published.planes->planes) last_id = std::max(last_id, plane.track_id);
    planes_seen += published.planes->planes.size();
  }
  // Three frames of a walk: ids persist from frame to frame, so fewer ids than planes seen.
  EXPECT_GT(last_id, 0u);
  EXPECT_LT(last_id, planes_seen);
  ASSERT_TRUE(node->reconfigure({}, {{"tracking", false}}));
  node->library.setParams(floodplane::Params());
  node->tracking = false;
}

TEST(SegmentationNode, LogsAnErrorForAnUnorganizedCloud) {
  Frame frame = renderedFrames().front();
  sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
  cloud.width *= cloud.height;
  cloud.height = 1;
  cloud.row_step = cloud.width * cloud.point_step;
  const std::string error = node->sendBadCloud(cloud);
  EXPECT_NE(error.find("frame skipped: /" + node->camera() + "/depth/points: the cloud is not organized"),
            std::string::npos)
      << error;
}

TEST(SegmentationNode, PublishesNoPlanesForACloudOfNaNsOnly) {
  Frame frame = renderedFrames().front();
  const sensor_msgs::PointCloud2 before = cloudMessage(frame);
  const Published planes_before = node->sendCloud(before);
  expectLibrarysResult(planes_before, frame, pointsOf(before));
  ASSERT_TRUE(planes_before.complete());
  ASSERT_GT(planes_before.markers->markers.size(), 1u);
  frame.name = "a cloud of NaNs";
  std::fill(frame.xyz.begin(), frame.xyz.end(), std::numeric_limits<float>::quiet_NaN());
  const sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
  const Published published = node->sendCloud(cloud);
  // No planes, every label 0, and the markers of the frame before cleared (a DELETEALL alone).
  expectLibrarysResult(published, frame, pointsOf(cloud));
  ASSERT_TRUE(published.complete());
  EXPECT_TRUE(published.planes->planes.empty());
  EXPECT_EQ(published.markers->markers.size(), 1u);
}

TEST(SegmentationNode, PublishesNoPlanesForADepthImageOfZeros) {
  DepthFrame depth = depthFrame(renderedFrames().front(), true);
  std::fill(depth.image.data.begin(), depth.image.data.end(), std::uint8_t{0});
  std::fill(depth.points.xyz.begin(), depth.points.xyz.end(), std::numeric_limits<float>::quiet_NaN());
  depth.points.name = "a depth image of zeros";
  const Published published = node->sendDepth(depth);
  expectLibrarysResult(published, depth.points, depth.points.grid());
  ASSERT_TRUE(published.complete());
  EXPECT_TRUE(published.planes->planes.empty());
}

TEST(SegmentationNode, PublishesNoPlanesForACloudTooSmallForOne) {
  Frame frame;
  frame.name = "a cloud of one column of two points";  // organized: a height of 1 would not be
  frame.width = 1;
  frame.height = 2;
  frame.xyz = {0.0f, -0.01f, 1.0f, 0.0f, 0.01f, 1.0f};
  const sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
  const Published published = node->sendCloud(cloud);
  expectLibrarysResult(published, frame, pointsOf(cloud));
  ASSERT_TRUE(published.complete());
  EXPECT_TRUE(published.planes->planes.empty());
}

TEST(SegmentationNode, LogsAnErrorForADepthImageOfAnotherEncoding) {
  DepthFrame depth = depthFrame(renderedFrames().front(), true);
  depth.image.encoding = "mono8";
  const std::string error = node->sendBadDepth(depth);
  EXPECT_NE(error.find("frame skipped: /" + node->camera() + "/depth/image_rect: depth image encoding 'mono8'"),
            std::string::npos)
      << error;
}

TEST(SegmentationNode, LogsEachFramesTimeAtDebugLevel) {
  // The process that runs the node: the node itself, or the nodelet's manager.
  const std::string process = ros::param::param<std::string>("~process", node->nodeName());
  ASSERT_TRUE(node->setLoggerLevel(process, "ros.floodplane_ros.timing", "debug")) << process;
  const std::size_t lines = node->timingLineCount();
  const Frame frame = renderedFrames().front();
  const sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
  const Published published = node->sendCloud(cloud);
  expectLibrarysResult(published, frame, pointsOf(cloud));
  const std::string line = node->waitForTimingLine(lines);
  ASSERT_TRUE(node->setLoggerLevel(process, "ros.floodplane_ros.timing", "info"));
  EXPECT_NE(line.find(node->nodeName() + ": 640x480 frame of camera_depth_optical_frame at " +
                      std::to_string(published.planes->header.stamp.sec) + ".000 segmented in "),
            std::string::npos)
      << line;
  EXPECT_NE(line.find(" ms: " + std::to_string(published.planes->planes.size()) + " planes"), std::string::npos)
      << line;
}

TEST(SegmentationNode, ReportsItsStreamOnDiagnostics) {
  const std::string name = node->nodeName().substr(1) + ": segmentation";
  // The frames the node published results for, and the bad messages the tests before sent (an
  // unorganized cloud, a mono8 depth image), are all counted.
  const std::size_t frames = node->framesAnswered();
  ASSERT_GT(frames, 0u);
  const Status status = node->waitForStatus(name, frames, 2);
  ASSERT_FALSE(status.values.empty()) << "no report named '" << name << "' on /diagnostics with " << frames
                                      << " frames and 2 skipped messages since the start within " << kWaitSeconds
                                      << " s";
  // The input topics: the launch file's, both segmented here.
  EXPECT_EQ(status.hardware_id, "/" + node->camera() + "/depth/points, /" + node->camera() + "/depth/image_rect");
  for (const char* key :
       {"Window (s)", "Frames segmented", "Messages skipped", "Frequency (Hz)", "Time per frame, mean (ms)",
        "Time per frame, max (ms)", "Planes in the last frame", "Messages skipped since start"}) {
    EXPECT_EQ(status.values.count(key), 1u) << key;
  }
}

TEST(SegmentationNode, GoesOnWithTheNextFrameAfterBadOnes) {
  const Frame frame = renderedFrames().back();
  const sensor_msgs::PointCloud2 cloud = cloudMessage(frame);
  expectLibrarysResult(node->sendCloud(cloud), frame, pointsOf(cloud));
}

// Two instances side by side, one a camera (two_cameras.test: a node, and a nodelet in the
// second camera's manager): each segments the frames of its own camera and publishes its own
// planes, with the same stamps on both, so that a frame or a result that crossed over would be
// compared with the other camera's.
TEST(TwoCameras, EachInstanceSegmentsItsOwnCamerasFrames) {
  ASSERT_GE(cameras.size(), 2u) << "~cameras names fewer than two cameras";
  NodeUnderTest& first = *cameras[0];
  NodeUnderTest& second = *cameras[1];
  // input:=points: a camera driver computes no depth image for them (its cloud is connected).
  EXPECT_EQ(first.depthImageSubscribers(), 0u);
  EXPECT_EQ(second.depthImageSubscribers(), 0u);
  const std::vector<Frame> frames = renderedFrames();
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Frame& first_frame = frames[k];
    const Frame& second_frame = frames[frames.size() - 1 - k];
    const sensor_msgs::PointCloud2 first_cloud = cloudMessage(first_frame);
    const sensor_msgs::PointCloud2 second_cloud = cloudMessage(second_frame);
    const Published first_planes = first.sendCloud(first_cloud);
    const Published second_planes = second.sendCloud(second_cloud);
    expectLibrarysResult(first, first_planes, first_frame, pointsOf(first_cloud));
    expectLibrarysResult(second, second_planes, second_frame, pointsOf(second_cloud));
    if (HasFatalFailure()) return;
    ASSERT_EQ(first_planes.planes->header.stamp, second_planes.planes->header.stamp);
    if (&first_frame != &second_frame) {
      EXPECT_NE(first_planes.planes->planes.front().plane.coef, second_planes.planes->planes.front().plane.coef)
          << "frame " << k << ": the two cameras' frames give the same largest plane";
    }
  }
  // Each reports its own stream on /diagnostics, under its own name.
  for (NodeUnderTest* camera : {&first, &second}) {
    const std::string name = camera->nodeName().substr(1) + ": segmentation";
    const Status status = camera->waitForStatus(name, frames.size(), 0);
    EXPECT_FALSE(status.values.empty()) << "no report named '" << name << "' with " << frames.size()
                                        << " frames on /diagnostics within " << kWaitSeconds << " s";
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "floodplane_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  std::vector<std::string> names{"camera"};
  ros::param::get("~cameras", names);
  const bool depth_images = ros::param::param<std::string>("~input", "both") == "both";
  for (const std::string& name : names) {
    cameras.push_back(std::make_unique<NodeUnderTest>(name, depth_images));
    if (!cameras.back()->connect()) {
      std::cerr << "the topics of " << cameras.back()->nodeName() << " and its set_parameters service did not come "
                << "up within " << kWaitSeconds << " s\n";
      return 1;
    }
  }
  node = cameras.front().get();
  const int result = RUN_ALL_TESTS();
  node = nullptr;
  cameras.clear();
  return result;
}
