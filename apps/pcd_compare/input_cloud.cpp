#include "input_cloud.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace pcd_compare {

namespace {

namespace fs = std::filesystem;

bool hasField(const pcl::PCLPointCloud2& blob, const std::string& name) {
  return std::any_of(blob.fields.begin(), blob.fields.end(),
                     [&](const pcl::PCLPointField& field) { return field.name == name; });
}

// PCL's reader prints its own multi-line complaints; we report one line per bad file, so it
// is silenced while reading and restored after.
class QuietPcl {
 public:
  QuietPcl() : previous_(pcl::console::getVerbosityLevel()) {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  }
  ~QuietPcl() { pcl::console::setVerbosityLevel(previous_); }
  QuietPcl(const QuietPcl&) = delete;
  QuietPcl& operator=(const QuietPcl&) = delete;

 private:
  pcl::console::VERBOSITY_LEVEL previous_;
};

}  // namespace

std::vector<std::string> expandInputs(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const std::string& input : inputs) {
    std::error_code error;
    if (!fs::is_directory(input, error)) {
      files.push_back(input);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(input, error)) {
      if (entry.path().extension() == ".pcd" && !fs::is_directory(entry.path(), error)) {
        found.push_back(entry.path().string());
      }
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

InputCloud loadInputCloud(const std::string& path) {
  std::error_code error;
  if (!fs::exists(path, error)) {
    throw std::runtime_error(path + ": no such file");
  }
  if (fs::is_directory(path, error)) {
    throw std::runtime_error(path + ": is a directory");
  }
  pcl::PCLPointCloud2 blob;
  int status = 0;
  {
    const QuietPcl quiet;
    pcl::PCDReader reader;
    try {
      // PCL 1.13's read() dereferences the first field without checking that the header
      // had any (a text file crashes it), so the header is read and checked first.
      pcl::PCLPointCloud2 header;
      Eigen::Vector4f origin;
      Eigen::Quaternionf orientation;
      int version = 0;
      int data_type = 0;
      unsigned int data_index = 0;
      if (reader.readHeader(path, header, origin, orientation, version, data_type, data_index) <
              0 ||
          header.fields.empty()) {
        throw std::runtime_error(path + ": not a readable PCD file");
      }
      if (header.width * header.height == 0) {
        throw std::runtime_error(path + ": has no points");
      }
      status = reader.read(path, blob);
    } catch (const std::runtime_error&) {
      throw;
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ": not a readable PCD file (" + e.what() + ")");
    }
  }
  if (status < 0) {
    throw std::runtime_error(path + ": not a readable PCD file");
  }
  if (!hasField(blob, "x") || !hasField(blob, "y") || !hasField(blob, "z")) {
    throw std::runtime_error(path + ": has no x, y, z fields");
  }
  if (blob.height <= 1 || blob.width <= 1) {
    throw std::runtime_error(path + ": not an organized cloud (" + std::to_string(blob.width) +
                             "x" + std::to_string(blob.height) + ")");
  }

  InputCloud input;
  input.path = path;
  input.name = fs::path(path).filename().string();
  if (input.name.size() > 4 && input.name.compare(input.name.size() - 4, 4, ".pcd") == 0) {
    input.name.resize(input.name.size() - 4);
  }
  input.cloud = std::make_shared<Cloud>();
  pcl::fromPCLPointCloud2(blob, *input.cloud);
  input.valid.resize(input.cloud->size());
  for (std::size_t i = 0; i < input.cloud->size(); ++i) {
    const pcl::PointXYZ& p = (*input.cloud)[i];
    input.valid[i] = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) ? 1 : 0;
  }
  if (hasField(blob, "label")) {
    pcl::PointCloud<pcl::Label> labels;
    pcl::fromPCLPointCloud2(blob, labels);
    std::vector<std::uint32_t> ground_truth(labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i) {
      ground_truth[i] = labels[i].label;
    }
    input.ground_truth = std::move(ground_truth);
  }
  return input;
}

}  // namespace pcd_compare
