#pragma once
// Bags for the tests that read ROS 1 bags: scripts/frames-to-bag.py run with Debian's python3-rosbag.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rdsf/frame/frame_source.hpp"
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

/// The real people frames the bag tests write into bags.
inline std::string people_frames_dir() { return (realdata_dir() / "people").string(); }

/// Every frame of `source`, in order.
inline std::vector<DepthFrame> all_frames(FrameSource& source) {
  std::vector<DepthFrame> frames;
  DepthFrame frame;
  while (source.next(frame)) frames.push_back(frame);
  return frames;
}

/// The same size, type and pixels (two empty images are the same).
inline bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && (a.empty() || cv::norm(a, b, cv::NORM_INF) == 0);
}

}  // namespace rdsf::test

/// Skips the test when the real frames or the bag writer's Python packages are absent.
#define RDSF_REQUIRE_BAG_WRITER()                                                                    \
  do {                                                                                               \
    RDSF_REQUIRE_REALDATA();                                                                         \
    if (!::rdsf::test::bag_writer_available()) GTEST_SKIP() << ::rdsf::test::kBagWriterMissing;      \
  } while (0)
