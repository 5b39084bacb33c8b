// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The pcd_segment tests' fixture: a temporary folder of its own (AppTest), PCL's console quiet,
// and the program run in it. PCD_SEGMENT_BINARY: the program's path, defined by each test's
// target.
#pragma once

#include <pcl/console/print.h>

#include <string>
#include <vector>

#include "support/app_run.h"

namespace floodplane::test {

class PcdSegmentTest : public AppTest {
 protected:
  void SetUp() override {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    AppTest::SetUp();
  }

  // pcd_segment with `arguments`, its output and exit code.
  Result run(const std::vector<std::string>& arguments) const {
    return runShell("exec " + commandLine(PCD_SEGMENT_BINARY, arguments));
  }
};

}  // namespace floodplane::test
