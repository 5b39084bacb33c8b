// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/pcl_base.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/planar_region.h>

#include "floodplane/object_segmentation.h"
#include "floodplane/params.h"
#include "floodplane/plane_tracker.h"
#include "floodplane/segmenter.h"

/// \file
/// The PCL class, floodplane::FloodFillPlaneSegmentation, in place of
/// pcl::OrganizedMultiPlaneSegmentation. Explicitly instantiated for PCL's xyz point types;
/// other point types: define PCL_NO_PRECOMPILE first, or include
/// floodplane/impl/flood_fill_plane_segmentation.hpp after this header.

namespace floodplane {

namespace detail {
/// Throws std::invalid_argument "floodplane::FloodFillPlaneSegmentation::<setter>: <message>".
[[noreturn]] void throwBadParameter(const char* setter, const std::string& message);
}  // namespace detail

/// Plane segmentation of organized point clouds by seeded span flood fill (Roychoudhury,
/// Missura, Bennewitz: "Plane Segmentation in Organized Point Clouds using Flood Fill"),
/// a drop-in for pcl::OrganizedMultiPlaneSegmentation that needs no normals:
///
///   floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> seg;   // was OMPS<..., Normal, Label>
///   seg.setInputCloud(cloud);                                    // no setInputNormals
///   seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
///
/// Outputs mean what they mean for OMPS, with these definitions:
/// - planes are numbered 1..K by inlier count, largest first; `inlier_indices[k-1]`,
///   `model_coefficients[k-1]`, `regions[k-1]` describe plane k;
/// - `labels` is an organized cloud of the input's size: label k for an inlier of plane k,
///   0 for every other point ("no plane");
/// - `label_indices[k]` holds the points labelled k; `label_indices[0]` the finite points
///   that belong to no plane;
/// - coefficients (a, b, c, d) describe a x + b y + c z + d = 0 with (a, b, c) unit length and
///   pointing towards the sensor (the cloud's sensor_origin_), for every plane;
/// - centroids and covariances (population, 1/N) are those of the inliers;
/// - a region's contour is its ordered outer boundary (8-connected, clockwise in the image).
///
/// Input: any organized cloud (height > 1). Non-finite points are holes. The cloud's sensor
/// pose (sensor_origin_, sensor_orientation_) is honoured: results do not change when cloud
/// and pose move together. setIndices() is ignored, as by OMPS: the whole grid is segmented.
/// An unorganized or missing cloud gives a PCL_ERROR and empty outputs.
///
/// Over a stream of clouds, setTracking(true) gives the planes ids that persist from cloud to
/// cloud (floodplane::PlaneTracker); the labels then carry those ids instead of size ranks.
///
/// After the planes, segmentObjects() gives the objects standing on them (the tabletop
/// pipeline of OrganizedMultiPlaneSegmentation + OrganizedConnectedComponentSegmentation in
/// one class; floodplane/object_segmentation.h).
///
/// Bad parameter values throw std::invalid_argument from the setter, naming it.
/// Not thread-safe; use one instance per thread. Buffers are reused between calls.
///
/// \tparam PointT  the cloud's point type: any with x, y, z (PCL's xyz types are instantiated
///                 in the library)
/// \tparam PointLT the label cloud's point type, with a `label` field (pcl::Label)
template <typename PointT, typename PointLT = pcl::Label>
class FloodFillPlaneSegmentation : public pcl::PCLBase<PointT> {
  using pcl::PCLBase<PointT>::input_;

 public:
  using PointCloud = pcl::PointCloud<PointT>;                  ///< the input cloud
  using PointCloudPtr = typename PointCloud::Ptr;              ///< shared pointer to an input cloud
  using PointCloudConstPtr = typename PointCloud::ConstPtr;    ///< shared pointer to a const input cloud
  using PointCloudL = pcl::PointCloud<PointLT>;                ///< the label cloud
  using PointCloudLPtr = typename PointCloudL::Ptr;            ///< shared pointer to a label cloud
  using PointCloudLConstPtr = typename PointCloudL::ConstPtr;  ///< shared pointer to a const label cloud
  /// Shared pointer to this class, as PCL's classes have.
  using Ptr = std::shared_ptr<FloodFillPlaneSegmentation<PointT, PointLT>>;
  /// Shared pointer to a const instance of this class.
  using ConstPtr = std::shared_ptr<const FloodFillPlaneSegmentation<PointT, PointLT>>;
  /// The planar regions of segment(Regions&) and segmentAndRefine(), as OMPS's.
  using Regions = std::vector<pcl::PlanarRegion<PointT>, Eigen::aligned_allocator<pcl::PlanarRegion<PointT>>>;
  /// Each plane's inlier centroid (x, y, z, 1).
  using Centroids = std::vector<Eigen::Vector4f, Eigen::aligned_allocator<Eigen::Vector4f>>;
  /// Each plane's inlier covariance (population, 1/N).
  using Covariances = std::vector<Eigen::Matrix3f, Eigen::aligned_allocator<Eigen::Matrix3f>>;

  /// Every parameter at its default (Params()).
  FloodFillPlaneSegmentation() = default;
  /// The parameters given; throws std::invalid_argument naming the first bad one.
  /// \param params the parameters of the segmentation
  explicit FloodFillPlaneSegmentation(const Params& params) { setParams(params); }
  ~FloodFillPlaneSegmentation() override = default;

  // ---- OrganizedMultiPlaneSegmentation's parameters ----------------------------------------
  // Lengths left unset are derived from each frame's depth noise and pixel footprint (see
  // Params); their getters then return 0.

  /// Smallest number of inliers of a reported plane. Default: one pixel in a thousand.
  /// \param min_inliers points at full resolution
  void setMinInliers(unsigned min_inliers) {
    setParam(&Params::min_inliers, std::optional<std::uint32_t>(min_inliers), "setMinInliers");
  }
  /// \return the value setMinInliers() set; 0 while it is derived from the frame's size
  unsigned getMinInliers() const { return params_.min_inliers.value_or(0u); }
  /// theta_angle [rad]: the largest angle between normals in the seed tests (Eqs. 6, 7) and
  /// between merging planes (Eq. 9). Must be in (0, pi/2). Default 0.1.
  /// \param angular_threshold [rad], in (0, pi/2)
  void setAngularThreshold(double angular_threshold) {
    setParam(&Params::angular_threshold, angular_threshold, "setAngularThreshold");
  }
  /// \return theta_angle [rad] (setAngularThreshold())
  double getAngularThreshold() const { return params_.angular_threshold; }
  /// sigma_plane [m]: the largest point-to-plane distance in the flood (Eq. 2), widened to
  /// three noise deviations where those are more. Default: derived (the paper's is 0.01).
  /// \param distance_threshold [m], finite and more than 0
  void setDistanceThreshold(double distance_threshold) {
    setParam(&Params::distance_threshold, std::optional<double>(distance_threshold), "setDistanceThreshold");
  }
  /// \return sigma_plane [m] as set; 0 while it is derived from the frame's noise
  double getDistanceThreshold() const { return params_.distance_threshold.value_or(0.0); }
  /// Largest curvature lambda_0 / (lambda_0 + lambda_1 + lambda_2) of a reported plane, as
  /// in OMPS. Default 1/3, which accepts every plane (OMPS's 0.001 rejects far Kinect walls).
  /// \param maximum_curvature a finite number, 0 or more (1/3 or more: every plane)
  void setMaximumCurvature(double maximum_curvature) {
    setParam(&Params::maximum_curvature, maximum_curvature, "setMaximumCurvature");
  }
  /// \return the largest curvature of a reported plane (setMaximumCurvature())
  double getMaximumCurvature() const { return params_.maximum_curvature; }
  /// Project the regions' contour points onto their plane along the viewing rays, as OMPS's
  /// segmentAndRefine does. Default false.
  /// Not a parameter of the segmentation (Params): it only changes the contours this class
  /// builds.
  /// \param project_points true: contour points on their plane; false: the measured points
  void setProjectPoints(bool project_points) { project_points_ = project_points; }
  /// \return whether contour points are projected onto their plane (setProjectPoints())
  bool getProjectPoints() const { return project_points_; }

  // ---- the paper's parameters and floodplane's own --------------------------------------
  /// sigma_seed [m]: side of the seed cube (Sec. III-C). Default: derived (the paper's 0.06).
  /// \param seed_size [m], finite and more than 0
  void setSeedSize(double seed_size) { setParam(&Params::seed_size, std::optional<double>(seed_size), "setSeedSize"); }
  /// \return sigma_seed [m] as set; 0 while it is derived from the frame's noise
  double getSeedSize() const { return params_.seed_size.value_or(0.0); }
  /// sigma_plane-merge [m] of Eq. 9. Default: derived (the paper's 0.03).
  /// \param merge_distance [m], finite and more than 0
  void setMergeDistance(double merge_distance) {
    setParam(&Params::merge_distance, std::optional<double>(merge_distance), "setMergeDistance");
  }
  /// \return sigma_plane-merge [m] as set; 0 while it is derived from the frame's noise
  double getMergeDistance() const { return params_.merge_distance.value_or(0.0); }
  /// Sub-sampling factor: 1, 2, 4 or 8 (Table III): s > 1 segments s x s blocks of the cloud
  /// (see Params::subsampling). Labels are always full resolution.
  /// \param factor 1, 2, 4 or 8; default 4
  void setSubsampling(int factor) { setParam(&Params::subsampling, factor, "setSubsampling"); }
  /// \return the sub-sampling factor (setSubsampling())
  int getSubsampling() const { return params_.subsampling; }
  /// c [1/m] of the depth noise sigma(r) = sigma_0 + c r^2. Setting it (or sigma_0) turns
  /// the per-frame noise estimate off. Default: measured on each frame.
  /// \param coefficient [1/m], finite, 0 or more
  void setDepthNoiseCoefficient(double coefficient) {
    setParam(&Params::depth_noise_coefficient, std::optional<double>(coefficient), "setDepthNoiseCoefficient");
  }
  /// \return c [1/m] as set; 0 while the noise is measured on each frame
  double getDepthNoiseCoefficient() const { return params_.depth_noise_coefficient.value_or(0.0); }
  /// sigma_0 [m] of the depth noise model (see setDepthNoiseCoefficient).
  /// \param sigma_0 [m], finite, 0 or more
  void setDepthNoiseConstant(double sigma_0) {
    setParam(&Params::depth_noise_constant, std::optional<double>(sigma_0), "setDepthNoiseConstant");
  }
  /// \return sigma_0 [m] as set; 0 while the noise is measured on each frame
  double getDepthNoiseConstant() const { return params_.depth_noise_constant.value_or(0.0); }
  /// All parameters at once; throws std::invalid_argument naming the first bad one.
  /// \param params every parameter of the segmentation (Params)
  void setParams(const Params& params);
  /// \return every parameter of the segmentation, as set
  const Params& getParams() const { return params_; }
  /// Record the time of each phase (Fig. 5) in getLastPhases().
  /// \param measure true: time the phases (a few clock reads per flood); default false
  void setMeasurePhases(bool measure) { measure_phases_ = measure; }
  /// Treat each cloud as the next frame of one stream (Segmenter::Options::head_start): the
  /// previous cloud's sensor noise model is taken again, which saves the noise measurement on
  /// most frames. A cloud of another size, or the first after a parameter changed, starts
  /// cold. Default off.
  /// \param head_start true: each cloud continues the one before
  void setHeadStart(bool head_start) { head_start_ = head_start; }
  /// \return whether each cloud continues the one before (setHeadStart())
  bool getHeadStart() const { return head_start_; }

  // ---- planes over a stream of clouds (floodplane::PlaneTracker) ---------------------------
  /// Follow the planes over the clouds segmented one after another: each keeps an id (1, 2,
  /// ...) while its surface stays in view, and gets it back when it returns within
  /// PlaneTracker::Options::max_lost_frames clouds. On, the label cloud of segment() and
  /// segmentAndRefine() holds track ids instead of size ranks (0 still means "no plane"), and
  /// `label_indices[id]` the points of track `id` (empty for ids not in this cloud); planes,
  /// coefficients, regions and inlier indices stay largest first, plane k + 1 being track
  /// getTrackIds()[k]. Every call that segments is a frame, whichever overload; a call that
  /// fails (no cloud, an unorganized one) is none. Switching it on or off starts a new
  /// sequence (the tracks are forgotten). Default off: labels are size ranks.
  /// \param tracking true: labels are track ids that persist over the clouds
  void setTracking(bool tracking);
  /// \return whether the planes are tracked over the clouds (setTracking())
  bool getTracking() const { return tracking_; }
  /// The tracker's matching limits and smoothing; throws std::invalid_argument naming the
  /// option. Keeps the tracks.
  /// \param options the tracker's options (PlaneTracker::Options)
  void setTrackerOptions(const PlaneTracker::Options& options);
  /// \return the tracker's options (setTrackerOptions())
  const PlaneTracker::Options& getTrackerOptions() const { return tracker_.options(); }
  /// The camera's motion since the previous cloud, for the next cloud segmented (once; then
  /// none until set again): the pose of the next cloud's sensor in the previous one's frame
  /// (T_previous_current, as odometry gives it), 4 x 4 rigid, in metres. The frame meant is
  /// the one the planes are measured in, the cloud's axes at its sensor_origin_: for clouds
  /// in their camera's frame (the usual), the camera's own motion. Optional; it lets a plane
  /// keep its id across a fast move. Throws std::invalid_argument when not finite and rigid.
  /// Used only while tracking.
  /// \param motion T_previous_current, a 4 x 4 rigid transform [m]
  void setCameraMotion(const Eigen::Matrix4d& motion);
  /// The tracks after the last cloud: ids, first and last frame (0 = the first cloud since
  /// tracking started), frames seen, current and smoothed plane parameters (relative to the
  /// sensor origin, axes as the cloud's).
  /// \return the tracker that follows the planes (PlaneTracker::tracks() lists them)
  const PlaneTracker& getTracker() const { return tracker_; }
  /// The track id of each plane of the last call, largest plane first; empty when tracking is
  /// off or the call segmented nothing.
  /// \return one id per plane of the last call, in the order of its outputs
  const std::vector<std::uint32_t>& getTrackIds() const { return track_ids_; }

  // ---- segmentation, with OrganizedMultiPlaneSegmentation's signatures -------------------
  /// Planes without the refinement step.
  /// \param[out] model_coefficients each plane's a, b, c, d, largest plane first
  /// \param[out] inlier_indices     each plane's points, as indices into the input cloud
  void segment(std::vector<pcl::ModelCoefficients>& model_coefficients, std::vector<pcl::PointIndices>& inlier_indices);
  /// Planes without the refinement step, with their inliers' centroids and covariances, the
  /// label cloud and the points of every label.
  /// \param[out] model_coefficients each plane's a, b, c, d, largest plane first
  /// \param[out] inlier_indices     each plane's points, as indices into the input cloud
  /// \param[out] centroids          each plane's inlier centroid
  /// \param[out] covariances        each plane's inlier covariance
  /// \param[out] labels             the input's grid: each point's label (0: no plane)
  /// \param[out] label_indices      the points of each label, `label_indices[0]` those of no plane
  void segment(std::vector<pcl::ModelCoefficients>& model_coefficients, std::vector<pcl::PointIndices>& inlier_indices,
               Centroids& centroids, Covariances& covariances, pcl::PointCloud<PointLT>& labels,
               std::vector<pcl::PointIndices>& label_indices);
  /// Planar regions (centroid, covariance, count, contour, coefficients) without refinement.
  /// \param[out] regions the planes, largest first
  void segment(Regions& regions);
  /// Planar regions after refinement: planes grown into adjacent pixels that fit them.
  /// \param[out] regions the planes, largest first
  void segmentAndRefine(Regions& regions);
  /// Everything, after refinement. `labels` is allocated when null.
  /// \param[out] regions            the planes, largest first
  /// \param[out] model_coefficients each plane's a, b, c, d
  /// \param[out] inlier_indices     each plane's points, as indices into the input cloud
  /// \param[in,out] labels          the input's grid: each point's label (0: no plane); allocated when null
  /// \param[out] label_indices      the points of each label, `label_indices[0]` those of no plane
  /// \param[out] boundary_indices   each plane's outer boundary, in order (as the regions' contours)
  void segmentAndRefine(Regions& regions, std::vector<pcl::ModelCoefficients>& model_coefficients,
                        std::vector<pcl::PointIndices>& inlier_indices, PointCloudLPtr& labels,
                        std::vector<pcl::PointIndices>& label_indices,
                        std::vector<pcl::PointIndices>& boundary_indices);

  // ---- the objects on the planes (floodplane/object_segmentation.h) -----------------------
  /// The objects standing on the planes of the last segment() or segmentAndRefine() call
  /// (floodplane::segmentObjects over the same cloud), as OrganizedConnectedComponentSegmentation
  /// gives its clusters: `labels` an organized cloud of the input's size holding object ids
  /// 1..K (largest object first; 0: no object), `object_indices[k - 1]` the points of object
  /// k. The planes' own labels (size ranks) decide the supports, also while tracking. Without
  /// a successful segmentation before it (none yet, or the last call failed), a PCL_ERROR and
  /// empty outputs. Throws std::invalid_argument when an option is out of range (naming it).
  /// \param[out] labels         the input's grid: each point's object id (0: no object)
  /// \param[out] object_indices the points of each object, `object_indices[k - 1]` those of object k
  /// \param options             the objects' limits (ObjectOptions)
  void segmentObjects(pcl::PointCloud<PointLT>& labels, std::vector<pcl::PointIndices>& object_indices,
                      const ObjectOptions& options = ObjectOptions());
  /// The last segmentObjects() result as the core produced it: labels, each object's size,
  /// centroid, bounding box (relative to the sensor origin, axes as the cloud's) and
  /// supporting plane (its size rank, as getLastSegmentation() numbers the planes). Valid until
  /// the next call.
  /// \return the objects of the last segmentObjects() call
  const ObjectSegmentation& getLastObjects() const { return objects_; }

  /// The last result as the core produced it: labels, and planes relative to the sensor origin (axes as the cloud's),
  /// the time per phase and statistics. Valid until the next call.
  /// \return the core's result of the last segment() or segmentAndRefine() call
  const Segmentation& getLastSegmentation() const { return *last_; }
  /// The last call's time per phase when setMeasurePhases(true): the core's phases and this
  /// class's conversion around them (pcl_conversion), which together make up the call.
  /// \return the phases' times [ms]; all 0 without setMeasurePhases(true)
  const PhaseTimes& getLastPhases() const { return phases_; }

 protected:
  /// \return the class's name in its PCL_ERROR messages, as PCL's classes have it
  virtual std::string getClassName() const { return "FloodFillPlaneSegmentation"; }

 private:
  // A plane of the last result, in the cloud's frame.
  struct CloudPlane {
    Eigen::Vector4f coefficients;
    Eigen::Vector4f centroid;
    Eigen::Matrix3f covariance;
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
  };

  // Sets one field after checking the whole set with Params::problem(); a bad value throws
  // std::invalid_argument naming `setter`.
  template <typename Value>
  void setParam(Value Params::*field, Value value, const char* setter) {
    Params changed = params_;
    changed.*field = value;
    const std::string problem = changed.problem();
    if (!problem.empty()) detail::throwBadParameter(setter, problem);
    params_ = changed;
    params_changed_ = true;
  }
  // Validates the input and runs the core; false (after a PCL_ERROR) when there is nothing
  // to segment. Fills last_ and planes_.
  bool run(bool refine, const char* method);
  void clearOutputs(std::vector<pcl::ModelCoefficients>& model_coefficients,
                    std::vector<pcl::PointIndices>& inlier_indices) const;
  void fillCoefficients(std::vector<pcl::ModelCoefficients>& model_coefficients) const;
  void fillIndices(std::vector<pcl::PointIndices>& inlier_indices, std::vector<pcl::PointIndices>* label_indices) const;
  void fillLabels(pcl::PointCloud<PointLT>& labels) const;
  // The label plane k (0-based) carries in the outputs: its track id, or its rank k + 1.
  std::uint32_t outputLabel(std::size_t k) const {
    return tracking_ ? track_ids_[k] : static_cast<std::uint32_t>(k + 1);
  }
  void fillRegions(Regions& regions, std::vector<pcl::PointIndices>* boundary_indices);
  // Adds the time since run() handed over to the conversion phase (when measuring).
  void finishPhases();

  Params params_;
  bool project_points_ = false;
  bool measure_phases_ = false;
  bool head_start_ = false;
  bool params_changed_ = true;  // params_ still to be handed to segmenter_ (which then starts cold)
  bool tracking_ = false;
  PlaneTracker tracker_;
  std::vector<std::uint32_t> track_ids_;  // of the last call's planes, when tracking
  bool has_camera_motion_ = false;        // camera_motion_ is for the next frame
  // Unaligned: storage only, so that the class needs no aligned allocation.
  Eigen::Matrix<double, 4, 4, Eigen::DontAlign> camera_motion_ = Eigen::Matrix4d::Identity();
  Segmenter segmenter_;
  std::vector<float> sensor_frame_points_;  // the cloud shifted to its sensor origin, when not at 0
  std::vector<CloudPlane, Eigen::aligned_allocator<CloudPlane>> planes_;
  std::vector<int> contour_;
  PhaseTimes phases_;
  std::chrono::steady_clock::time_point conversion_start_;  // when run() handed over
  const Segmentation* last_ = &empty_;
  Segmentation empty_;
  // The grid of the last successful run and the cloud it reads (kept alive for segmentObjects).
  PointGrid last_grid_;
  PointCloudConstPtr last_input_;
  ObjectSegmentation objects_;
};

}  // namespace floodplane

#ifdef PCL_NO_PRECOMPILE
#include "floodplane/impl/flood_fill_plane_segmentation.hpp"
#endif
