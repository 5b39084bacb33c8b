#pragma once
// Reading the inputs: PCD files, or directories of them, into an XYZ cloud plus the
// ground-truth labels when the file has a `label` field.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "method.h"

namespace pcd_compare {

struct InputCloud {
  std::string path;
  std::string name;  ///< the file name without ".pcd", used in tables and image names
  Cloud::Ptr cloud;
  /// The file's `label` field (ground-truth plane id, 0 = none), when it has one.
  std::optional<std::vector<std::uint32_t>> ground_truth;
  /// 1 where x, y and z are finite: the pixels the metrics count.
  std::vector<std::uint8_t> valid;
};

/// The PCD files named by `inputs`: files as given, directories replaced by their *.pcd
/// files in sorted order. Paths that do not exist are kept, so that loading reports them.
std::vector<std::string> expandInputs(const std::vector<std::string>& inputs);

/// Loads an organized cloud with x, y and z fields. Throws std::runtime_error with a
/// one-line message naming the file if it is missing, not a readable PCD file, not
/// organized, or has no x, y, z.
InputCloud loadInputCloud(const std::string& path);

}  // namespace pcd_compare
