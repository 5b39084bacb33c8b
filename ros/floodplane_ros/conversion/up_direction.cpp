// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "up_direction.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <Eigen/Geometry>

namespace floodplane::conversion {

namespace {

bool isSeparator(char c) { return c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::optional<UpDirection> parseUpDirection(const std::string& text) {
  std::size_t begin = text.find_first_not_of(" \t\n\r");
  if (begin == std::string::npos) return std::nullopt;
  std::size_t end = text.find_last_not_of(" \t\n\r") + 1;
  const std::string quoted = "'" + text + "'";
  if (text[begin] == '[') {
    if (text[end - 1] != ']') throw std::invalid_argument("the up direction " + quoted + " has no closing ']'");
    ++begin;
    --end;
  }
  std::vector<double> values;
  std::size_t i = begin;
  while (i < end) {
    if (isSeparator(text[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < end && !isSeparator(text[j])) ++j;
    const std::string word = text.substr(i, j - i);
    char* parsed_end = nullptr;
    errno = 0;
    const double value = std::strtod(word.c_str(), &parsed_end);
    if (parsed_end != word.c_str() + word.size() || errno == ERANGE) {
      throw std::invalid_argument("the up direction " + quoted + " has '" + word + "', not a finite number");
    }
    values.push_back(value);
    i = j;
  }
  try {
    return upDirection(values);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("the up direction " + quoted + ": " + error.what());
  }
}

UpDirection upDirection(const std::vector<double>& values) {
  if (values.size() != 3) {
    throw std::invalid_argument("an up direction is 3 numbers x y z, got " + std::to_string(values.size()));
  }
  for (const double value : values) {
    if (!std::isfinite(value)) throw std::invalid_argument("an up direction's numbers must be finite");
  }
  if (values[0] == 0.0 && values[1] == 0.0 && values[2] == 0.0) {
    throw std::invalid_argument("an up direction must not be zero");
  }
  return {values[0], values[1], values[2]};
}

UpDirection targetUpInSource(const RigidTransform& source_in_target) {
  for (const double value : source_in_target.rotation) {
    if (!std::isfinite(value)) throw std::invalid_argument("targetUpInSource: the rotation is not finite");
  }
  Eigen::Quaterniond rotation(source_in_target.rotation[3], source_in_target.rotation[0], source_in_target.rotation[1],
                              source_in_target.rotation[2]);
  if (rotation.norm() < 1e-9) throw std::invalid_argument("targetUpInSource: the rotation quaternion is zero");
  rotation.normalize();
  const Eigen::Vector3d up = rotation.conjugate() * Eigen::Vector3d::UnitZ();
  return {up.x(), up.y(), up.z()};
}

}  // namespace floodplane::conversion
