// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The ROS 1 nodelet: organized PointCloud2 frames (points) or depth images with their
// CameraInfo (image_rect, camera_info, as depth_image_proc subscribes them) in, by ~input; the
// label cloud (plane_labels), the label image (plane_label_image), the planes (planes, in
// ~target_frame when it is set), the largest plane's inliers and model (inliers, model, as
// pcl_ros's SACSegmentation publishes them), rviz markers (plane_markers) and the objects on
// the planes (object_label_image, and object_indices: one pcl_msgs/PointIndices per object) out, and a status
// of the stream on /diagnostics. Each plane is classed (floor, wall, ...) by the up direction:
// ~target_frame's +z axis, or ~up in the sensor's frame. Lazy, as depth_image_proc is: the
// input is subscribed only while an output is (nodelet_topic_tools::NodeletLazy; ~lazy false
// subscribes it always), and a frame is segmented only when an output has a subscriber. The
// work is the ROS-free FrameSegmenter's and the conversions' (conversion/); this file holds the
// topics, the parameters, the transforms, the clock and the logging.

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <floodplane_ros/Planes.h>
#include <floodplane_ros/SegmentationConfig.h>
#include <image_transport/image_transport.h>
#include <nodelet_topic_tools/nodelet_lazy.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <pcl_msgs/PointIndices.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2/exceptions.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>
#include <xmlrpcpp/XmlRpcValue.h>
#include <pluginlib/class_list_macros.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "chained_plane.h"
#include "cloud_points.h"
#include "depth_image.h"
#include "floodplane/object_segmentation.h"
#include "frame_segmenter.h"
#include "label_cloud.h"
#include "plane_descriptions.h"
#include "plane_transform.h"
#include "problem_throttle.h"
#include "ros1_messages.h"
#include "stream_status.h"
#include "up_direction.h"

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

// The outputs that have a subscriber, taken once a frame: only they are computed.
struct Outputs {
  bool planes = false;
  bool labels = false;
  bool label_image = false;
  bool markers = false;
  bool inliers = false;
  bool model = false;
  bool object_image = false;    // the objects on the planes (floodplane::segmentObjects), as a label image
  bool object_indices = false;  // ... and one pcl_msgs/PointIndices per object
  bool objects() const { return object_image || object_indices; }
  bool any() const { return planes || labels || label_image || markers || inliers || model || objects(); }
};

// ~up as the parameter server holds it: text (what a launch file's <param value=...> and a
// command line's _up:= give: "[0, -1, 0]") or a list of numbers (rosparam set, a YAML file).
// Nothing when it is empty.
std::optional<conv::UpDirection> upDirectionOf(XmlRpc::XmlRpcValue& value) {
  if (value.getType() == XmlRpc::XmlRpcValue::TypeString) {
    return conv::parseUpDirection(static_cast<std::string&>(value));
  }
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw std::invalid_argument("~up must be 3 numbers x y z (\"[0, -1, 0]\"), or empty");
  }
  std::vector<double> numbers;
  for (int i = 0; i < value.size(); ++i) {
    XmlRpc::XmlRpcValue& number = value[i];
    if (number.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
      numbers.push_back(static_cast<double>(number));
    } else if (number.getType() == XmlRpc::XmlRpcValue::TypeInt) {
      numbers.push_back(static_cast<int>(number));
    } else {
      throw std::invalid_argument("~up must be 3 numbers x y z, its item " + std::to_string(i) + " is not a number");
    }
  }
  return conv::upDirection(numbers);
}

using Clock = std::chrono::steady_clock;
double secondsOf(Clock::time_point time) { return std::chrono::duration<double>(time.time_since_epoch()).count(); }
double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

class SegmentationNodelet : public nodelet_topic_tools::NodeletLazy {
 private:
  // A parameter it cannot take stops the nodelet from loading, with the reason in the log (the
  // loader drops an exception's message).
  void onInit() override {
    NodeletLazy::onInit();  // ~lazy (default true)
    try {
      start();
    } catch (const std::exception& error) {
      NODELET_FATAL("%s", error.what());
      throw;
    }
    onInitPostProcess();  // with ~lazy false: the inputs subscribed now, for good
  }

  void start() {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& private_nh = getPrivateNodeHandle();
    inputs_ = inputsNamed(private_nh.param<std::string>("input", "points"));
    queue_size_ = static_cast<std::uint32_t>(std::max(1, private_nh.param("queue_size", 2)));
    outline_points_ = private_nh.param("outline_points", 200);
    normal_length_ = private_nh.param("normal_length", 0.2);
    line_width_ = private_nh.param("line_width", 0.01);
    if (outline_points_ < 3) {
      NODELET_WARN("outline_points must be at least 3, got %d: using 3", outline_points_);
      outline_points_ = 3;
    }
    target_frame_ = private_nh.param<std::string>("target_frame", "");
    transform_timeout_ = private_nh.param("transform_timeout", 0.1);
    if (!(transform_timeout_ >= 0.0)) {
      throw std::invalid_argument("~transform_timeout must be 0 or more seconds, got " +
                                  std::to_string(transform_timeout_));
    }
    readUpDirection(private_nh);
    if (!target_frame_.empty()) {
      tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
      tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, nh);
    }
    // The inputs' names, resolved once: the subscribers come and go.
    cloud_topic_ = nh.resolveName("points");
    depth_topic_ = nh.resolveName("image_rect");
    if (inputs_.depth_image) image_transport_ = std::make_unique<image_transport::ImageTransport>(nh);

    // The server calls onReconfigure with the parameters' start values (the parameter server's
    // or the .cfg defaults) before it returns.
    reconfigure_ = std::make_unique<dynamic_reconfigure::Server<SegmentationConfig>>(private_nh);
    reconfigure_->setCallback([this](SegmentationConfig& config, std::uint32_t) { onReconfigure(config); });

    // The stream's status on /diagnostics, as camera drivers report theirs: once a second
    // (~diagnostic_period), under the nodelet's name, its hardware the input topics.
    status_ = std::make_unique<conv::StreamStatus>(secondsOf(Clock::now()));
    diagnostics_ = std::make_unique<diagnostic_updater::Updater>(nh, private_nh, getName());
    std::string inputs;
    if (inputs_.points) inputs = cloud_topic_;
    if (inputs_.depth_image) inputs += (inputs.empty() ? "" : ", ") + depth_topic_;
    diagnostics_->setHardwareID(inputs);
    diagnostics_->add("segmentation", this, &SegmentationNodelet::reportStatus);

    // A subscriber may connect, and so the inputs be subscribed (with what is set above), as
    // soon as the first output is advertised: frames are dropped until all are.
    labels_publisher_ = advertise<sensor_msgs::PointCloud2>(nh, "plane_labels", 1);
    label_image_publisher_ = advertise<sensor_msgs::Image>(nh, "plane_label_image", 1);
    planes_publisher_ = advertise<Planes>(nh, "planes", 1);
    markers_publisher_ = advertise<visualization_msgs::MarkerArray>(nh, "plane_markers", 1);
    inliers_publisher_ = advertise<pcl_msgs::PointIndices>(nh, "inliers", 1);
    model_publisher_ = advertise<pcl_msgs::ModelCoefficients>(nh, "model", 1);
    object_image_publisher_ = advertise<sensor_msgs::Image>(nh, "object_label_image", 1);
    // One message per object a frame, all of a frame's in a row: a queue deeper than a frame's
    // objects can be (a 640x480 frame holds at most 3072 of ObjectOptions' 100 pixels; a room
    // has over a hundred), so that a subscriber that has not yet read the first loses none of
    // the rest. A queue of 100 dropped the tail of a room's objects under load.
    object_indices_publisher_ = advertise<pcl_msgs::PointIndices>(nh, "object_indices", 4096);
    publishers_ready_ = true;
    diagnostics_timer_ = nh.createWallTimer(ros::WallDuration(0.1), [this](const ros::WallTimerEvent&) {
      diagnostics_->update();  // publishes when the period is over
    });

    if (inputs_.points) NODELET_INFO("segments the organized clouds on %s", cloud_topic_.c_str());
    if (inputs_.depth_image) {
      NODELET_INFO("segments the depth images on %s with their camera_info", depth_topic_.c_str());
    }
    if (!target_frame_.empty()) {
      NODELET_INFO("publishes its planes in %s, classed by its z axis as up", target_frame_.c_str());
    } else if (up_) {
      NODELET_INFO("classes its planes by ~up (%g, %g, %g) in the input's frame", (*up_)[0], (*up_)[1], (*up_)[2]);
    } else {
      NODELET_INFO("no up direction (~up, ~target_frame): its planes are not classed");
    }
  }

  // ~up, the up direction in the sensor's frame, when there is no ~target_frame (whose z axis
  // is up). A bad one is logged and leaves the planes unclassed: they are still worth
  // publishing, and the node stays up for the rest of its outputs.
  void readUpDirection(ros::NodeHandle& private_nh) {
    XmlRpc::XmlRpcValue value;
    if (!private_nh.getParam("up", value)) return;
    if (!target_frame_.empty()) {
      const bool empty = value.getType() == XmlRpc::XmlRpcValue::TypeString &&
                         static_cast<std::string&>(value).find_first_not_of(" \t") == std::string::npos;
      if (!empty) NODELET_WARN("~up is not used: with ~target_frame, up is that frame's z axis");
      return;
    }
    try {
      up_ = upDirectionOf(value);
    } catch (const std::exception& error) {
      NODELET_ERROR("~up not taken, the planes are not classed: %s", error.what());
    }
  }

  // NodeletLazy calls these, under its lock, when the first output gets a subscriber and when
  // the last one goes.
  void subscribe() override {
    ros::NodeHandle& nh = getNodeHandle();
    if (inputs_.points) cloud_subscriber_ = nh.subscribe("points", queue_size_, &SegmentationNodelet::onCloud, this);
    if (inputs_.depth_image) {
      depth_subscriber_ =
          image_transport_->subscribeCamera("image_rect", queue_size_, &SegmentationNodelet::onDepth, this);
    }
    NODELET_DEBUG("an output has a subscriber: inputs subscribed");
  }
  void unsubscribe() override {
    cloud_subscriber_.shutdown();
    depth_subscriber_.shutdown();
    NODELET_DEBUG("no output has a subscriber: inputs unsubscribed");
  }

  Outputs subscribedOutputs() const {
    Outputs outputs;
    outputs.planes = planes_publisher_.getNumSubscribers() > 0;
    outputs.labels = labels_publisher_.getNumSubscribers() > 0;
    outputs.label_image = label_image_publisher_.getNumSubscribers() > 0;
    outputs.markers = markers_publisher_.getNumSubscribers() > 0;
    outputs.inliers = inliers_publisher_.getNumSubscribers() > 0;
    outputs.model = model_publisher_.getNumSubscribers() > 0;
    outputs.object_image = object_image_publisher_.getNumSubscribers() > 0;
    outputs.object_indices = object_indices_publisher_.getNumSubscribers() > 0;
    return outputs;
  }

  // The pose of the frame's sensor in ~target_frame at the frame's time, when the planes go
  // there or are coloured by class (its z axis is up): nothing when ~target_frame is empty or
  // no one listens to the planes or the markers. False (the frame skipped, the reason logged)
  // when tf2 has no such transform within ~transform_timeout.
  bool lookUpTarget(const std_msgs::Header& header, const std::string& topic, const Outputs& outputs,
                    std::optional<conv::RigidTransform>& transform) {
    transform.reset();
    if (target_frame_.empty() || !(outputs.planes || outputs.markers)) return true;
    try {
      transform = rigidTransform(
          tf_buffer_->lookupTransform(target_frame_, header.frame_id, header.stamp, ros::Duration(transform_timeout_))
              .transform);
      return true;
    } catch (const tf2::TransformException& error) {
      char timeout[32];
      std::snprintf(timeout, sizeof timeout, "%.3g", transform_timeout_);
      // tf2's words name the times, which change from frame to frame: the problem does not.
      reportProblem(topic,
                    "no transform from '" + header.frame_id + "' to '" + target_frame_ + "' within " + timeout + " s",
                    error.what());
      return false;
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

  // A frame's time runs from the message's turn (the lock) to the end of its segmentation;
  // waiting for its transform comes before.
  void onCloud(const sensor_msgs::PointCloud2ConstPtr& cloud) {
    if (!publishers_ready_) return;
    const Outputs outputs = subscribedOutputs();
    if (!outputs.any()) return;  // the last subscriber left while the frame was on its way
    std::optional<conv::RigidTransform> to_target;
    if (!lookUpTarget(cloud->header, cloud_topic_, outputs, to_target)) return;
    std::lock_guard<std::mutex> lock(mutex_);
    const Clock::time_point start = Clock::now();
    try {
      const conv::CloudPoints points = conv::readCloudPoints(cloudView(*cloud));
      const floodplane::Segmentation& segmentation = segmenter_.segment(points.grid());
      publish(cloud->header, points.grid(), segmentation, millisecondsSince(start), outputs, to_target);
    } catch (const std::exception& error) {
      reportProblem(cloud_topic_, error.what());
    }
  }

  void onDepth(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info) {
    if (!publishers_ready_) return;
    const Outputs outputs = subscribedOutputs();
    if (!outputs.any()) return;
    std::optional<conv::RigidTransform> to_target;
    if (!lookUpTarget(image->header, depth_topic_, outputs, to_target)) return;
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
      publish(image->header, grid, segmentation, millisecondsSince(start), outputs, to_target);
    } catch (const std::exception& error) {
      reportProblem(depth_topic_, error.what());
    }
  }

  void reportStatus(diagnostic_updater::DiagnosticStatusWrapper& status) {
    conv::StreamReport report;
    const bool idle = !subscribedOutputs().any();
    {
      std::lock_guard<std::mutex> lock(status_mutex_);
      report = status_->report(secondsOf(Clock::now()), idle);
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
  // `detail` is logged after the problem but is not part of it (the same problem with another
  // detail is throttled as the same).
  void reportProblem(const std::string& topic, const std::string& problem, const std::string& detail = "") {
    const std::string line = "frame skipped: " + topic + ": " + problem;
    const std::string more = detail.empty() ? "" : " (" + detail + ")";
    std::lock_guard<std::mutex> lock(status_mutex_);
    status_->messageSkipped(topic + ": " + problem);
    if (!throttle_.shouldLog(line, ros::WallTime::now().toSec())) return;
    if (throttle_.suppressed() > 0) {
      NODELET_ERROR("%s%s (and %zu times more since it was last logged)", line.c_str(), more.c_str(),
                    throttle_.suppressed());
    } else {
      NODELET_ERROR("%s%s", line.c_str(), more.c_str());
    }
  }

  void publish(const std_msgs::Header& header, const floodplane::PointGrid& grid,
               const floodplane::Segmentation& segmentation, double time_ms, const Outputs& outputs,
               const std::optional<conv::RigidTransform>& to_target) {
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
    // Up in the input's frame, where the planes are classed: the target frame's z axis, or ~up.
    const std::optional<conv::UpDirection> up = to_target ? conv::targetUpInSource(*to_target) : up_;
    std::vector<conv::PlaneDescription> descriptions;
    if (outputs.planes || outputs.markers) descriptions = conv::describePlanes(segmentation, track_ids, up);
    if (outputs.planes) {
      auto planes = boost::make_shared<Planes>();
      planes->header = header;
      if (to_target) planes->header.frame_id = target_frame_;
      planes->segmentation_time_ms = time_ms;
      for (const conv::PlaneDescription& plane : descriptions) {
        planes->planes.push_back(planeMessage(to_target ? conv::transformPlane(plane, *to_target) : plane));
      }
      planes_publisher_.publish(planes);
    }
    if (outputs.inliers || outputs.model) {
      // In the input's frame, whatever ~target_frame: the filters apply them to the input cloud.
      const conv::ChainedPlane chained = conv::chainedPlane(segmentation);
      if (outputs.inliers)
        inliers_publisher_.publish(boost::make_shared<pcl_msgs::PointIndices>(pointIndices(header, chained)));
      if (outputs.model) {
        model_publisher_.publish(boost::make_shared<pcl_msgs::ModelCoefficients>(modelCoefficients(header, chained)));
      }
    }
    if (outputs.labels) {
      auto cloud = boost::make_shared<sensor_msgs::PointCloud2>(
          organizedCloud(header, grid.width, grid.height, conv::labelCloudFields(), conv::kLabelCloudPointStep));
      conv::writeLabelCloud(grid, segmentation.labels, labels, cloud->data.data());
      labels_publisher_.publish(cloud);
    }
    if (outputs.label_image) {
      label_image_publisher_.publish(boost::make_shared<sensor_msgs::Image>(
          labelImage(header, segmentation.width, segmentation.height, segmentation.labels, labels)));
    }
    if (outputs.markers) {
      std::vector<conv::PlaneOutline> outlines;
      outlines.reserve(segmentation.planes.size());
      for (std::size_t k = 0; k < segmentation.planes.size(); ++k) {
        outlines.push_back(conv::outlinePlane(segmentation, grid, k, conv::markerColor(descriptions[k], up.has_value()),
                                              static_cast<std::size_t>(outline_points_), normal_length_));
      }
      markers_publisher_.publish(
          boost::make_shared<visualization_msgs::MarkerArray>(planeMarkers(header, outlines, line_width_)));
    }
    if (outputs.objects()) {
      // The objects on the planes, in the input's frame: ids 1..K, largest first (0: none).
      const floodplane::ObjectSegmentation objects = floodplane::segmentObjects(grid, segmentation);
      if (outputs.object_image) {
        std::vector<std::uint32_t> ids(objects.objects.size());
        for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<std::uint32_t>(k + 1);
        object_image_publisher_.publish(boost::make_shared<sensor_msgs::Image>(
            labelImage(header, objects.width, objects.height, objects.labels, ids)));
      }
      if (outputs.object_indices) {
        std::vector<boost::shared_ptr<pcl_msgs::PointIndices>> messages(objects.objects.size());
        for (std::size_t k = 0; k < messages.size(); ++k) {
          messages[k] = boost::make_shared<pcl_msgs::PointIndices>();
          messages[k]->header = header;
          messages[k]->indices.reserve(objects.objects[k].pixel_count);
        }
        for (std::size_t i = 0; i < objects.labels.size(); ++i) {
          if (objects.labels[i] != 0) messages[objects.labels[i] - 1]->indices.push_back(static_cast<std::int32_t>(i));
        }
        for (const auto& message : messages) object_indices_publisher_.publish(message);
      }
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
  Inputs inputs_;
  std::uint32_t queue_size_ = 2;
  int outline_points_ = 200;
  double normal_length_ = 0.2;
  double line_width_ = 0.01;
  std::string target_frame_;
  double transform_timeout_ = 0.1;
  std::optional<conv::UpDirection> up_;  // ~up; unused with a target frame
  std::string cloud_topic_;
  std::string depth_topic_;
  std::atomic<bool> publishers_ready_{false};

  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Publisher labels_publisher_;
  ros::Publisher label_image_publisher_;
  ros::Publisher planes_publisher_;
  ros::Publisher markers_publisher_;
  ros::Publisher inliers_publisher_;
  ros::Publisher model_publisher_;
  ros::Publisher object_image_publisher_;
  ros::Publisher object_indices_publisher_;
  ros::Subscriber cloud_subscriber_;
  std::unique_ptr<image_transport::ImageTransport> image_transport_;
  image_transport::CameraSubscriber depth_subscriber_;
  std::unique_ptr<dynamic_reconfigure::Server<SegmentationConfig>> reconfigure_;
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  ros::WallTimer diagnostics_timer_;
};

}  // namespace floodplane_ros

PLUGINLIB_EXPORT_CLASS(floodplane_ros::SegmentationNodelet, nodelet::Nodelet)
