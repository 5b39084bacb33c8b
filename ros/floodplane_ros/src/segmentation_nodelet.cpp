// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The ROS 1 nodelet: organized PointCloud2 frames (points) or depth images with their
// CameraInfo (image_rect, camera_info, as depth_image_proc subscribes them) in, by ~input; the
// label cloud (plane_labels), the planes (planes) and rviz markers (plane_markers) out, and a
// status of the stream on /diagnostics. The work is the ROS-free FrameSegmenter's and the conversions'
// (conversion/); this file holds the topics, the parameters, the clock and the logging.

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <floodplane_ros/Planes.h>
#include <floodplane_ros/SegmentationConfig.h>
#include <image_transport/image_transport.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/MarkerArray.h>
#include <pluginlib/class_list_macros.hpp>

#include <chrono>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "cloud_points.h"
#include "depth_image.h"
#include "frame_segmenter.h"
#include "label_cloud.h"
#include "plane_descriptions.h"
#include "problem_throttle.h"
#include "ros1_messages.h"
#include "stream_status.h"

namespace floodplane_ros {
namespace conv = floodplane::conversion;

namespace {

conv::SegmentationSettings settingsFromConfig(const SegmentationConfig& config) {
  conv::SegmentationSettings settings;
  floodplane::Params& params = settings.params;
  params.distance_threshold = conv::lengthOrDerived(config.distance_threshold);
  params.seed_size = conv::lengthOrDerived(config.seed_size);
  params.angular_threshold = config.angular_threshold;
  params.merge_distance = conv::lengthOrDerived(config.merge_distance);
  if (config.min_inliers > 0) params.min_inliers = static_cast<std::uint32_t>(config.min_inliers);
  params.maximum_curvature = config.maximum_curvature;
  params.subsampling = config.subsampling;
  if (!config.measure_noise) {
    params.depth_noise_coefficient = config.depth_noise_coefficient;
    params.depth_noise_constant = config.depth_noise_constant;
  }
  settings.head_start = config.head_start;
  settings.tracking = config.tracking;
  return settings;
}

// What ~input asks to segment. A camera driver computes its cloud for subscribers only: a node
// that listened to both would make it compute the cloud and segment every frame twice.
struct Inputs {
  bool points = false;
  bool depth_image = false;
};
Inputs inputsNamed(const std::string& name) {
  if (name == "points") return {true, false};
  if (name == "depth_image") return {false, true};
  if (name == "both") return {true, true};
  throw std::invalid_argument("~input must be points, depth_image or both, got '" + name + "'");
}

using Clock = std::chrono::steady_clock;
double secondsOf(Clock::time_point time) { return std::chrono::duration<double>(time.time_since_epoch()).count(); }
double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

class SegmentationNodelet : public nodelet::Nodelet {
 private:
  // A parameter it cannot take stops the nodelet from loading, with the reason in the log (the
  // loader drops an exception's message).
  void onInit() override {
    try {
      start();
    } catch (const std::exception& error) {
      NODELET_FATAL("%s", error.what());
      throw;
    }
  }

  void start() {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& private_nh = getPrivateNodeHandle();
    const Inputs inputs = inputsNamed(private_nh.param<std::string>("input", "points"));
    const int queue_size = private_nh.param("queue_size", 2);
    outline_points_ = private_nh.param("outline_points", 200);
    normal_length_ = private_nh.param("normal_length", 0.2);
    line_width_ = private_nh.param("line_width", 0.01);
    if (outline_points_ < 3) {
      NODELET_WARN("outline_points must be at least 3, got %d: using 3", outline_points_);
      outline_points_ = 3;
    }

    labels_publisher_ = nh.advertise<sensor_msgs::PointCloud2>("plane_labels", 1);
    planes_publisher_ = nh.advertise<Planes>("planes", 1);
    markers_publisher_ = nh.advertise<visualization_msgs::MarkerArray>("plane_markers", 1);

    // The server calls onReconfigure with the parameters' start values (the parameter server's
    // or the .cfg defaults) before it returns.
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<SegmentationConfig>>(private_nh);
    reconfigure_->setCallback([this](SegmentationConfig& config, std::uint32_t) { onReconfigure(config); });

    // The stream's status on /diagnostics, as camera drivers report theirs: once a second
    // (~diagnostic_period), under the nodelet's name.
    status_ = std::make_unique<conv::StreamStatus>(secondsOf(Clock::now()));
    diagnostics_ = std::make_unique<diagnostic_updater::Updater>(nh, private_nh, getName());
    diagnostics_->setHardwareID("none");  // a node on a camera's topics, not a device
    diagnostics_->add("segmentation", this, &SegmentationNodelet::reportStatus);
    diagnostics_timer_ = nh.createWallTimer(ros::WallDuration(0.1), [this](const ros::WallTimerEvent&) {
      diagnostics_->update();  // publishes when the period is over
    });

    if (inputs.points) {
      cloud_subscriber_ =
          nh.subscribe("points", static_cast<std::uint32_t>(queue_size), &SegmentationNodelet::onCloud, this);
      NODELET_INFO("segmenting the organized clouds on %s", cloud_subscriber_.getTopic().c_str());
    }
    if (inputs.depth_image) {
      image_transport_ = std::make_unique<image_transport::ImageTransport>(nh);
      depth_subscriber_ = image_transport_->subscribeCamera("image_rect", static_cast<std::uint32_t>(queue_size),
                                                            &SegmentationNodelet::onDepth, this);
      NODELET_INFO("segmenting the depth images on %s with their %s", depth_subscriber_.getTopic().c_str(),
                   depth_subscriber_.getInfoTopic().c_str());
    }
  }

  void onReconfigure(const SegmentationConfig& config) {
    std::lock_guard<std::mutex> lock(mutex_);
    try {
      segmenter_.setSettings(settingsFromConfig(config));
    } catch (const std::exception& error) {
      NODELET_ERROR("parameters not taken, the previous ones stay: %s", error.what());
    }
  }

  // A frame's time runs from the message's turn (the lock) to the end of its segmentation.
  void onCloud(const sensor_msgs::PointCloud2ConstPtr& cloud) {
    std::lock_guard<std::mutex> lock(mutex_);
    const Clock::time_point start = Clock::now();
    try {
      const conv::CloudPoints points = conv::readCloudPoints(cloudView(*cloud));
      const floodplane::Segmentation& segmentation = segmenter_.segment(points.grid());
      publish(cloud->header, points.grid(), segmentation, millisecondsSince(start));
    } catch (const std::exception& error) {
      reportProblem(cloud_subscriber_.getTopic(), error.what());
    }
  }

  void onDepth(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info) {
    std::lock_guard<std::mutex> lock(mutex_);
    const Clock::time_point start = Clock::now();
    try {
      conv::backProjectDepthImage(imageView(*image), cameraInfoView(*info), depth_points_);
      floodplane::PointGrid grid;
      grid.data = depth_points_.data();
      grid.stride = 3;
      grid.width = static_cast<int>(image->width);
      grid.height = static_cast<int>(image->height);
      const floodplane::Segmentation& segmentation = segmenter_.segment(grid);
      publish(image->header, grid, segmentation, millisecondsSince(start));
    } catch (const std::exception& error) {
      reportProblem(depth_subscriber_.getTopic(), error.what());
    }
  }

  void reportStatus(diagnostic_updater::DiagnosticStatusWrapper& status) {
    conv::StreamReport report;
    {
      std::lock_guard<std::mutex> lock(status_mutex_);
      report = status_->report(secondsOf(Clock::now()));
    }
    status.summary(static_cast<unsigned char>(report.level), report.summary);
    status.add("Window (s)", report.window_seconds);
    status.add("Frames segmented", report.frames);
    status.add("Messages skipped", report.skipped);
    status.add("Frequency (Hz)", report.frequency);
    status.add("Time per frame, mean (ms)", report.mean_time_ms);
    status.add("Time per frame, max (ms)", report.max_time_ms);
    status.add("Planes in the last frame", report.last_planes);
    status.add("Frames segmented since start", report.total_frames);
    status.add("Messages skipped since start", report.total_skipped);
    if (!report.last_problem.empty()) status.add("Last problem", report.last_problem);
  }

  // A bad frame is skipped with an error in the log; the stream goes on with the next one.
  void reportProblem(const std::string& topic, const std::string& problem) {
    const std::string line = "frame skipped: " + topic + ": " + problem;
    {
      std::lock_guard<std::mutex> lock(status_mutex_);
      status_->messageSkipped(topic + ": " + problem);
    }
    if (!throttle_.shouldLog(line, ros::WallTime::now().toSec())) return;
    if (throttle_.suppressed() > 0) {
      NODELET_ERROR("%s (and %zu times more since it was last logged)", line.c_str(), throttle_.suppressed());
    } else {
      NODELET_ERROR("%s", line.c_str());
    }
  }

  void publish(const std_msgs::Header& header, const floodplane::PointGrid& grid,
               const floodplane::Segmentation& segmentation, double time_ms) {
    {
      std::lock_guard<std::mutex> lock(status_mutex_);
      status_->frameSegmented(time_ms, segmentation.planes.size());
    }
    // A line a frame once the logger ros.floodplane_ros.timing is at debug level (README, "Speed
    // in sight").
    ROS_DEBUG_NAMED("timing", "%s: %dx%d frame of %s at %.3f segmented in %.2f ms: %zu planes", getName().c_str(),
                    grid.width, grid.height, header.frame_id.c_str(), header.stamp.toSec(), time_ms,
                    segmentation.planes.size());
    const std::vector<std::uint32_t>& track_ids = segmenter_.trackIds();
    const std::vector<std::uint32_t> labels = conv::publishedLabels(segmentation.planes.size(), track_ids);
    if (planes_publisher_.getNumSubscribers() > 0) {
      auto planes = boost::make_shared<Planes>();
      planes->header = header;
      planes->segmentation_time_ms = time_ms;
      for (const conv::PlaneDescription& plane : conv::describePlanes(segmentation, track_ids)) {
        planes->planes.push_back(planeMessage(plane));
      }
      planes_publisher_.publish(planes);
    }
    if (labels_publisher_.getNumSubscribers() > 0) {
      auto cloud = boost::make_shared<sensor_msgs::PointCloud2>(
          organizedCloud(header, grid.width, grid.height, conv::labelCloudFields(), conv::kLabelCloudPointStep));
      conv::writeLabelCloud(grid, segmentation.labels, labels, cloud->data.data());
      labels_publisher_.publish(cloud);
    }
    if (markers_publisher_.getNumSubscribers() > 0) {
      std::vector<conv::PlaneOutline> outlines;
      outlines.reserve(segmentation.planes.size());
      for (std::size_t k = 0; k < segmentation.planes.size(); ++k) {
        outlines.push_back(conv::outlinePlane(segmentation, grid, k, labels[k],
                                              static_cast<std::size_t>(outline_points_), normal_length_));
      }
      markers_publisher_.publish(
          boost::make_shared<visualization_msgs::MarkerArray>(planeMarkers(header, outlines, line_width_)));
    }
  }

  // The manager may call the callbacks from several threads: one frame at a time goes through
  // the segmenter (a stream's state: head start, tracks) and the buffers. The status has a
  // lock of its own, so that a report never waits for a frame's segmentation.
  std::mutex mutex_;
  std::mutex status_mutex_;
  std::unique_ptr<conv::StreamStatus> status_;
  conv::FrameSegmenter segmenter_;
  conv::ProblemThrottle throttle_;
  std::vector<float> depth_points_;
  int outline_points_ = 200;
  double normal_length_ = 0.2;
  double line_width_ = 0.01;

  ros::Publisher labels_publisher_;
  ros::Publisher planes_publisher_;
  ros::Publisher markers_publisher_;
  ros::Subscriber cloud_subscriber_;
  std::unique_ptr<image_transport::ImageTransport> image_transport_;
  image_transport::CameraSubscriber depth_subscriber_;
  std::unique_ptr<dynamic_reconfigure::Server<SegmentationConfig>> reconfigure_;
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  ros::WallTimer diagnostics_timer_;
};

}  // namespace floodplane_ros

PLUGINLIB_EXPORT_CLASS(floodplane_ros::SegmentationNodelet, nodelet::Nodelet)
