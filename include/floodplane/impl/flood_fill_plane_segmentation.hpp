// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include "floodplane/flood_fill_plane_segmentation.h"

namespace floodplane {

// ---- setters -----------------------------------------------------------------------------

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::setParams(const Params& params) {
  const std::string problem = params.problem();
  if (!problem.empty()) detail::throwBadParameter("setParams", problem);
  params_ = params;
  params_changed_ = true;
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::setTracking(bool tracking) {
  if (tracking != tracking_) {
    tracker_.reset();
    has_camera_motion_ = false;
  }
  tracking_ = tracking;
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::setTrackerOptions(const PlaneTracker::Options& options) {
  try {
    tracker_.setOptions(options);
  } catch (const std::invalid_argument& error) {
    detail::throwBadParameter("setTrackerOptions", error.what());
  }
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::setCameraMotion(const Eigen::Matrix4d& motion) {
  // The tracker's own check, on an empty frame of a tracker of its own: one rule, one place.
  try {
    PlaneTracker().update(Segmentation(), motion);
  } catch (const std::invalid_argument&) {
    detail::throwBadParameter("setCameraMotion",
                              "the motion must be a finite rigid transform (orthonormal rotation with determinant "
                              "1, last row 0 0 0 1)");
  }
  camera_motion_ = motion;
  has_camera_motion_ = true;
}

// ---- running the core --------------------------------------------------------------------

template <typename PointT, typename PointLT>
bool FloodFillPlaneSegmentation<PointT, PointLT>::run(bool refine, const char* method) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = measure_phases_ ? Clock::now() : Clock::time_point();
  last_ = &empty_;
  last_grid_ = PointGrid();
  last_input_.reset();
  planes_.clear();
  track_ids_.clear();
  phases_ = PhaseTimes();
  if (!input_) {
    PCL_ERROR("[floodplane::%s::%s] No input cloud: call setInputCloud first.\n", getClassName().c_str(), method);
    return false;
  }
  if (!input_->isOrganized() || input_->size() != static_cast<std::size_t>(input_->width) * input_->height) {
    PCL_ERROR(
        "[floodplane::%s::%s] This method needs an organized point cloud (height > 1); got %u x %u "
        "with %zu points.\n",
        getClassName().c_str(), method, input_->width, input_->height, static_cast<std::size_t>(input_->size()));
    return false;
  }

  // The core needs the sensor at the origin and nothing else of its pose: it uses ranges,
  // distances and dot products only, which a rotation leaves unchanged, so any
  // sensor_orientation_ is fine as it is. A cloud whose sensor is not at the origin is
  // shifted once into a buffer; the usual camera cloud is read in place.
  const Eigen::Vector3f origin = input_->sensor_origin_.template head<3>();
  PointGrid grid;
  grid.width = static_cast<int>(input_->width);
  grid.height = static_cast<int>(input_->height);
  if (origin.isZero(0.0f)) {
    static_assert(sizeof(PointT) % sizeof(float) == 0, "PCL point types are made of 4-byte fields");
    grid.data = &(*input_)[0].x;
    grid.stride = sizeof(PointT) / sizeof(float);
  } else {
    sensor_frame_points_.resize(input_->size() * 3);
    float* out = sensor_frame_points_.data();
    for (const PointT& p : input_->points) {
      *out++ = p.x - origin.x();
      *out++ = p.y - origin.y();
      *out++ = p.z - origin.z();
    }
    grid.data = sensor_frame_points_.data();
    grid.stride = 3;
  }
  if (params_changed_) {
    segmenter_.setParams(params_);
    params_changed_ = false;
  }
  Segmenter::Options options;
  options.refine = refine;
  options.measure_phases = measure_phases_;
  options.head_start = head_start_;
  const Clock::time_point core_start = measure_phases_ ? Clock::now() : Clock::time_point();
  last_ = &segmenter_.segment(grid, options);
  last_grid_ = grid;
  last_input_ = input_;
  if (measure_phases_) {
    phases_ = last_->phases;
    phases_.pcl_conversion = std::chrono::duration<double, std::milli>(core_start - start).count();
    conversion_start_ = Clock::now();
  }
  if (tracking_) {
    // Timed as part of the conversion: the tracker works on the core's result.
    track_ids_ =
        has_camera_motion_ ? tracker_.update(*last_, Eigen::Matrix4d(camera_motion_)) : tracker_.update(*last_);
    has_camera_motion_ = false;
  }

  // The planes in the cloud's frame: only the shift to the sensor's origin is undone.
  planes_.resize(last_->planes.size());
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    const PlaneFit& fit = last_->planes[k].fit;
    const Eigen::Vector3f normal = fit.normal.cast<float>();
    const Eigen::Vector3f centroid = fit.centroid.cast<float>() + origin;
    CloudPlane& plane = planes_[k];
    plane.coefficients << normal, -normal.dot(centroid);
    plane.centroid << centroid, 1.0f;
    plane.covariance = fit.covariance.cast<float>();
  }
  return true;
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::fillCoefficients(
    std::vector<pcl::ModelCoefficients>& model_coefficients) const {
  model_coefficients.resize(planes_.size());
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    model_coefficients[k].header = input_->header;
    const Eigen::Vector4f& c = planes_[k].coefficients;
    model_coefficients[k].values.assign(c.data(), c.data() + 4);
  }
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::fillIndices(std::vector<pcl::PointIndices>& inlier_indices,
                                                              std::vector<pcl::PointIndices>* label_indices) const {
  // Every list is sized before the one pass over the labels writes it (a plane's inlier count
  // is the count of its label in the image) and keeps the storage of the last call: a camera
  // loop that passes the same outputs allocates nothing once they have grown.
  const std::vector<std::uint32_t>& labels = last_->labels;
  const std::size_t size = labels.size();
  inlier_indices.resize(planes_.size());
  std::size_t labelled = 0;
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    inlier_indices[k].header = input_->header;
    inlier_indices[k].indices.resize(last_->planes[k].inlier_count);
    labelled += last_->planes[k].inlier_count;
  }
  pcl::PointIndices* unlabelled = nullptr;
  if (label_indices) {
    // One entry per label up to the largest output label (with tracking, ids not in this
    // cloud have empty entries).
    std::uint32_t largest = 0;
    for (std::size_t k = 0; k < planes_.size(); ++k) largest = std::max(largest, outputLabel(k));
    label_indices->resize(std::size_t{largest} + 1);
    for (pcl::PointIndices& entry : *label_indices) {
      entry.header = input_->header;
      entry.indices.clear();
    }
    for (std::size_t k = 0; k < planes_.size(); ++k)
      (*label_indices)[outputLabel(k)].indices.resize(last_->planes[k].inlier_count);
    unlabelled = &(*label_indices)[0];
    // At most the pixels no plane holds; cut to the finite ones after the pass.
    unlabelled->indices.resize(labelled <= size ? size - labelled : 0);
  }
  // One pass over the labels, a run of one label at a time (a label image is mostly long
  // runs). Each plane's indices go through a cursor into their storage, into the inlier list
  // and, with label_indices, its entry there.
  std::vector<int*> cursor(planes_.size()), label_cursor(label_indices ? planes_.size() : 0);
  std::vector<int*> end(planes_.size());
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    std::vector<int>& indices = inlier_indices[k].indices;
    cursor[k] = indices.data();
    end[k] = indices.data() + indices.size();
    if (label_indices) label_cursor[k] = (*label_indices)[outputLabel(k)].indices.data();
  }
  int* unlabelled_cursor = unlabelled ? unlabelled->indices.data() : nullptr;
  int* const unlabelled_end = unlabelled ? unlabelled_cursor + unlabelled->indices.size() : nullptr;
  bool counts_agree = true;
  for (std::size_t i = 0; i < size && counts_agree;) {
    const std::uint32_t label = labels[i];
    std::size_t run_end = i + 1;
    // Four labels a step while they all match (runs are long), then one at a time.
    while (run_end + 4 <= size && ((labels[run_end] ^ label) | (labels[run_end + 1] ^ label) |
                                   (labels[run_end + 2] ^ label) | (labels[run_end + 3] ^ label)) == 0)
      run_end += 4;
    while (run_end < size && labels[run_end] == label) ++run_end;
    const std::size_t n = run_end - i;
    if (label != 0) {
      const std::size_t k = label - 1;
      if (k >= planes_.size() || static_cast<std::size_t>(end[k] - cursor[k]) < n) {
        counts_agree = false;
        break;
      }
      std::iota(cursor[k], cursor[k] + n, static_cast<int>(i));
      if (label_indices) {
        std::copy(cursor[k], cursor[k] + n, label_cursor[k]);
        label_cursor[k] += n;
      }
      cursor[k] += n;
    } else if (unlabelled) {
      for (std::size_t j = i; j < run_end; ++j) {
        if (!pcl::isXYZFinite((*input_)[j])) continue;
        if (unlabelled_cursor == unlabelled_end) {
          counts_agree = false;
          break;
        }
        *unlabelled_cursor++ = static_cast<int>(j);
      }
    }
    i = run_end;
  }
  for (std::size_t k = 0; counts_agree && k < planes_.size(); ++k) counts_agree = cursor[k] == end[k];
  if (counts_agree) {
    if (unlabelled)
      unlabelled->indices.resize(static_cast<std::size_t>(unlabelled_cursor - unlabelled->indices.data()));
    return;
  }
  // Cannot happen (the core counts what it labels, and its tests check that); if it did,
  // the indices are still right, only slower to make.
  for (pcl::PointIndices& plane : inlier_indices) plane.indices.clear();
  if (label_indices)
    for (pcl::PointIndices& entry : *label_indices) entry.indices.clear();
  for (std::size_t i = 0; i < size; ++i) {
    const std::uint32_t label = labels[i];
    if (label != 0 && label - 1 < planes_.size()) {
      inlier_indices[label - 1].indices.push_back(static_cast<int>(i));
      if (label_indices) (*label_indices)[outputLabel(label - 1)].indices.push_back(static_cast<int>(i));
    } else if (unlabelled && pcl::isXYZFinite((*input_)[i])) {
      unlabelled->indices.push_back(static_cast<int>(i));
    }
  }
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::fillLabels(pcl::PointCloud<PointLT>& labels) const {
  labels.header = input_->header;
  // Sets width, height and size; a cloud of the frame's size already (the last call's) keeps
  // its points, each written once below.
  labels.resize(input_->width, input_->height);
  labels.is_dense = true;
  labels.sensor_origin_ = input_->sensor_origin_;
  labels.sensor_orientation_ = input_->sensor_orientation_;
  const std::uint32_t* core = last_->labels.data();
  const std::size_t size = last_->labels.size();
  if (!tracking_) {
    for (std::size_t i = 0; i < size; ++i) labels[i].label = core[i];
    return;
  }
  std::vector<std::uint32_t> label_of_rank(planes_.size() + 1, 0);  // [core label]; 0 stays 0
  for (std::size_t k = 0; k < planes_.size(); ++k) label_of_rank[k + 1] = outputLabel(k);
  for (std::size_t i = 0; i < size; ++i) labels[i].label = label_of_rank[core[i]];
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::fillRegions(Regions& regions,
                                                              std::vector<pcl::PointIndices>* boundary_indices) {
  // The regions (and boundary lists) of the last call are written over in place: their
  // contours keep their storage, and each contour point is written once.
  regions.resize(planes_.size());
  if (boundary_indices) boundary_indices->resize(planes_.size());
  const Eigen::Vector3f viewpoint = input_->sensor_origin_.template head<3>();
  const typename PointCloud::VectorType no_contour;
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    contour_.clear();
    last_->boundary(k, contour_);
    const CloudPlane& plane = planes_[k];
    // Copy-assigning a region of an empty contour keeps the old contour's storage.
    regions[k] = pcl::PlanarRegion<PointT>(plane.centroid.template head<3>(), plane.covariance,
                                           last_->planes[k].inlier_count, no_contour, plane.coefficients);
    typename PointCloud::VectorType& contour = regions[k].getContour();
    contour.resize(contour_.size());
    const Eigen::Vector3f n = plane.coefficients.template head<3>();
    for (std::size_t j = 0; j < contour_.size(); ++j) {
      contour[j] = (*input_)[contour_[j]];
      if (project_points_) {
        // Along the viewing ray from the viewpoint onto the plane, as OMPS.
        const Eigen::Vector3f ray = contour[j].getVector3fMap() - viewpoint;
        const float denominator = n.dot(ray);
        if (std::abs(denominator) > 1e-12f) {
          const float t = -(n.dot(viewpoint) + plane.coefficients[3]) / denominator;
          contour[j].getVector3fMap() = viewpoint + t * ray;
        }
      }
    }
    if (boundary_indices) {
      (*boundary_indices)[k].header = input_->header;
      (*boundary_indices)[k].indices.assign(contour_.begin(), contour_.end());
    }
  }
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::finishPhases() {
  if (!measure_phases_) return;
  phases_.pcl_conversion +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - conversion_start_).count();
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::clearOutputs(std::vector<pcl::ModelCoefficients>& model_coefficients,
                                                               std::vector<pcl::PointIndices>& inlier_indices) const {
  model_coefficients.clear();
  inlier_indices.clear();
}

// ---- the OMPS-compatible entry points ----------------------------------------------------
// The outputs are cleared when there is nothing to segment; otherwise they are written over,
// keeping their storage (see fillIndices).

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::segment(std::vector<pcl::ModelCoefficients>& model_coefficients,
                                                          std::vector<pcl::PointIndices>& inlier_indices) {
  if (!run(false, "segment")) {
    clearOutputs(model_coefficients, inlier_indices);
    return;
  }
  fillCoefficients(model_coefficients);
  fillIndices(inlier_indices, nullptr);
  finishPhases();
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::segment(std::vector<pcl::ModelCoefficients>& model_coefficients,
                                                          std::vector<pcl::PointIndices>& inlier_indices,
                                                          Centroids& centroids, Covariances& covariances,
                                                          pcl::PointCloud<PointLT>& labels,
                                                          std::vector<pcl::PointIndices>& label_indices) {
  centroids.clear();
  covariances.clear();
  if (!run(false, "segment")) {
    clearOutputs(model_coefficients, inlier_indices);
    labels.clear();
    label_indices.clear();
    return;
  }
  fillCoefficients(model_coefficients);
  fillIndices(inlier_indices, &label_indices);
  fillLabels(labels);
  for (const CloudPlane& plane : planes_) {
    centroids.push_back(plane.centroid);
    covariances.push_back(plane.covariance);
  }
  finishPhases();
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::segment(Regions& regions) {
  if (!run(false, "segment")) {
    regions.clear();
    return;
  }
  fillRegions(regions, nullptr);
  finishPhases();
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::segmentAndRefine(Regions& regions) {
  if (!run(true, "segmentAndRefine")) {
    regions.clear();
    return;
  }
  fillRegions(regions, nullptr);
  finishPhases();
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::segmentAndRefine(
    Regions& regions, std::vector<pcl::ModelCoefficients>& model_coefficients,
    std::vector<pcl::PointIndices>& inlier_indices, PointCloudLPtr& labels,
    std::vector<pcl::PointIndices>& label_indices, std::vector<pcl::PointIndices>& boundary_indices) {
  if (!labels) labels.reset(new PointCloudL);
  if (!run(true, "segmentAndRefine")) {
    regions.clear();
    clearOutputs(model_coefficients, inlier_indices);
    labels->clear();
    label_indices.clear();
    boundary_indices.clear();
    return;
  }
  fillCoefficients(model_coefficients);
  fillIndices(inlier_indices, &label_indices);
  fillLabels(*labels);
  fillRegions(regions, &boundary_indices);
  finishPhases();
}

template <typename PointT, typename PointLT>
void FloodFillPlaneSegmentation<PointT, PointLT>::segmentObjects(pcl::PointCloud<PointLT>& labels,
                                                                 std::vector<pcl::PointIndices>& object_indices,
                                                                 const ObjectOptions& options) {
  labels.clear();
  object_indices.clear();
  objects_ = ObjectSegmentation();
  if (!last_input_ || last_grid_.data == nullptr) {
    PCL_ERROR("[floodplane::%s::segmentObjects] No planes: call segment or segmentAndRefine first.\n",
              getClassName().c_str());
    return;
  }
  objects_ = floodplane::segmentObjects(last_grid_, *last_, options);
  labels.header = last_input_->header;
  labels.resize(last_input_->width, last_input_->height);
  labels.is_dense = true;
  labels.sensor_origin_ = last_input_->sensor_origin_;
  labels.sensor_orientation_ = last_input_->sensor_orientation_;
  object_indices.resize(objects_.objects.size());
  for (std::size_t k = 0; k < objects_.objects.size(); ++k) {
    object_indices[k].header = last_input_->header;
    object_indices[k].indices.reserve(objects_.objects[k].pixel_count);
  }
  for (std::size_t i = 0; i < objects_.labels.size(); ++i) {
    const std::uint32_t id = objects_.labels[i];
    labels[i].label = id;
    if (id != 0) object_indices[id - 1].indices.push_back(static_cast<int>(i));
  }
}

}  // namespace floodplane
