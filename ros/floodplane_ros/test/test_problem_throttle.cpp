// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The node's error log: a new problem at once, the same one at most once a period with the
// count of those not logged.

#include "problem_throttle.h"

#include <gtest/gtest.h>

namespace {

using floodplane::conversion::ProblemThrottle;

TEST(ProblemThrottle, LogsANewProblemAtOnce) {
  ProblemThrottle throttle(1.0);
  EXPECT_TRUE(throttle.shouldLog("the cloud is not organized", 100.0));
  EXPECT_EQ(throttle.suppressed(), 0u);
  EXPECT_TRUE(throttle.shouldLog("no point is finite", 100.1));
  EXPECT_TRUE(throttle.shouldLog("the cloud is not organized", 100.2));
}

TEST(ProblemThrottle, LogsTheSameProblemAtMostOnceAPeriodWithTheCountNotLogged) {
  ProblemThrottle throttle(1.0);
  EXPECT_TRUE(throttle.shouldLog("wrong encoding", 10.0));
  EXPECT_FALSE(throttle.shouldLog("wrong encoding", 10.3));
  EXPECT_FALSE(throttle.shouldLog("wrong encoding", 10.6));
  EXPECT_FALSE(throttle.shouldLog("wrong encoding", 10.9));
  EXPECT_TRUE(throttle.shouldLog("wrong encoding", 11.0));
  EXPECT_EQ(throttle.suppressed(), 3u);
  EXPECT_FALSE(throttle.shouldLog("wrong encoding", 11.5));
  EXPECT_TRUE(throttle.shouldLog("another problem", 11.6));
  EXPECT_EQ(throttle.suppressed(), 0u);
}

}  // namespace
