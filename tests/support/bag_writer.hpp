#pragma once
// Bags for the tests that read ROS 1 bags: scripts/frames-to-bag.py run with Debian's python3-rosbag.
#include <string>

#include <gtest/gtest.h>

#include "support/test_support.hpp"

namespace rdsf::test {

/// Whether scripts/frames-to-bag.py can run here (its Python packages are installed).
inline bool bag_writer_available() {
  return run("/usr/bin/python3 -c 'import rosbag, sensor_msgs.msg, numpy, png'").exit_code == 0;
}
inline constexpr const char* kBagWriterMissing =
    "python3-rosbag, python3-sensor-msgs, python3-numpy or python3-png missing: bag test skipped";

/// Writes `bag` from the frames of `folder` with scripts/frames-to-bag.py and `arguments`; fails the test on
/// error. Returns `bag`.
inline std::string write_bag(const std::string& folder, const std::string& bag, const std::string& arguments) {
  const RunResult r = run("/usr/bin/python3 " + quote(std::string(RDSF_SOURCE_DIR) + "/scripts/frames-to-bag.py") +
                          " " + quote(folder) + " " + quote(bag) + " " + arguments);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return bag;
}

}  // namespace rdsf::test
