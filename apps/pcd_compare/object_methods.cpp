// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The object methods' table (method.h): a method is a file that makes it and a line here.

#include "method.h"

namespace pcd_compare {

const std::vector<std::pair<std::string, ObjectMethodFactory>>& objectMethods() {
  static const std::vector<std::pair<std::string, ObjectMethodFactory>> methods = {
      {"floodplane", makeFloodplaneObjectsMethod},
      {"pcl_organized", makePclOrganizedObjectsMethod},
      {"lccp", makeLccpObjectsMethod},
      {"lccp_ec_sc", makeLccpExtendedObjectsMethod},
  };
  return methods;
}

}  // namespace pcd_compare
