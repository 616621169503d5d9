// The ROS 1 node rdsf_people against rdsf-detect, with every component real: a roscore on a free port
// (ROS_MASTER_URI, so parallel tests do not meet), the node, a bag written from ../shared/realdata/people by
// scripts/frames-to-bag.py and played by `rosbag play`, and this test subscribed to /people. The bag is
// played at 0.2 x its 30 frames/s (6 frames/s, 7.7 s) so that the node (about 1 ms a frame) drops no frame
// and the comparison is frame for frame; the node's own count of drops is checked to be 0. Everything
// started is stopped (SIGINT, then SIGKILL after a bound). Skips with a message without ROS or real frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.hpp"

#if RDSF_TEST_WITH_ROS
#include <mutex>

#include <cv_bridge/cv_bridge.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <opencv2/imgcodecs.hpp>
#include <rdsf_people/People.h>
#include <ros/ros.h>

#include "rdsf/classifier/boosted_model.hpp"
#include "support/background_process.hpp"
#endif

namespace rdsf {
namespace {

#if RDSF_TEST_WITH_ROS

using test::BackgroundProcess;

struct CsvPerson {
  int x = 0, y = 0, w = 0, h = 0;
  std::string score, distance_cm;  // as rdsf-detect prints them (%.4f, %.1f)
  int person = 0;
};
struct CsvFrame {
  std::string name;
  int candidates = 0;
  std::vector<CsvPerson> people;
};

// rdsf-detect's CSV (frame,candidate,x,y,w,h,depth_mm,score,person,distance_cm), frames in file order.
std::vector<CsvFrame> read_detect_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<CsvFrame> frames;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) f.push_back(field);
    if (line.back() == ',') f.emplace_back();
    if (f.size() != 10) ADD_FAILURE() << "unexpected CSV row: " << line;
    if (f.size() != 10) continue;
    if (frames.empty() || frames.back().name != f[0]) frames.push_back({f[0], 0, {}});
    ++frames.back().candidates;
    if (!f[8].empty()) {
      frames.back().people.push_back({std::stoi(f[2]), std::stoi(f[3]), std::stoi(f[4]), std::stoi(f[5]), f[7], f[9],
                                      std::stoi(f[8])});
    }
  }
  return frames;
}

std::string printed(const char* format, double value) {
  char text[48];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

bool have_python_rosbag() {
  return test::run("/usr/bin/python3 -c 'import rosbag, sensor_msgs.msg, numpy, png'").exit_code == 0;
}

// Frame for frame the people rdsf-detect wrote (`want`, the frames of a bag by scripts/frames-to-bag.py) in
// what the node published (`got`, in stamp order): candidate counts, boxes, scores, P(person) by `model`,
// track ids, distances walked. Returns how many people were compared.
int expect_same_people(const std::vector<rdsf_people::People>& got, const std::vector<CsvFrame>& want,
                       const BoostedModel& model) {
  EXPECT_EQ(got.size(), want.size());
  int people_seen = 0;
  for (std::size_t i = 0; i < std::min(got.size(), want.size()); ++i) {
    const rdsf_people::People& m = got[i];
    const CsvFrame& e = want[i];
    SCOPED_TRACE("frame " + std::to_string(i) + " " + e.name);
    EXPECT_EQ(m.header.seq, i);  // frames-to-bag numbers the frames in the folder's order
    EXPECT_EQ(m.header.frame_id, "camera_depth_optical_frame");
    EXPECT_EQ(m.candidates, static_cast<std::uint32_t>(e.candidates));
    EXPECT_EQ(m.people.size(), e.people.size());
    if (m.people.size() != e.people.size()) continue;
    for (std::size_t k = 0; k < e.people.size(); ++k) {
      const rdsf_people::Person& p = m.people[k];
      EXPECT_EQ(static_cast<int>(p.box.x_offset), e.people[k].x);
      EXPECT_EQ(static_cast<int>(p.box.y_offset), e.people[k].y);
      EXPECT_EQ(static_cast<int>(p.box.width), e.people[k].w);
      EXPECT_EQ(static_cast<int>(p.box.height), e.people[k].h);
      EXPECT_EQ(printed("%.4f", p.score), e.people[k].score);
      EXPECT_EQ(p.probability, model.probability(p.score));
      EXPECT_GE(p.probability, model.operating_probability());  // no ~threshold: the model's own
      EXPECT_EQ(p.track_id, e.people[k].person);
      EXPECT_NEAR(p.distance_walked_m * 100.0, std::stod(e.people[k].distance_cm), 0.05 + 1e-9);
      EXPECT_GT(p.position_m.z, 0.5);
      ++people_seen;
    }
  }
  return people_seen;
}

// rdsf-detect --model people on ../shared/realdata/people (its CSV read back), and meanwhile the bag of the same
// frames written by scripts/frames-to-bag.py with `bag_arguments`.
std::vector<CsvFrame> detect_and_write_bag(const test::TempDir& dir, const std::string& bag_arguments,
                                           const std::string& bag) {
  const std::string frames = (test::realdata_dir() / "people").string();
  const std::string models = std::string(RDSF_SOURCE_DIR) + "/models";
  BackgroundProcess detect(test::program("rdsf-detect") + " --source " + test::quote(frames) +
                               " --model people --models-dir " + test::quote(models) + " --out " +
                               test::quote(dir / "detect.csv"),
                           dir / "detect.log");
  const test::RunResult written = test::run("/usr/bin/python3 " +
                                            test::quote(std::string(RDSF_SOURCE_DIR) + "/scripts/frames-to-bag.py") +
                                            " " + test::quote(frames) + " " + test::quote(bag) + " " + bag_arguments);
  EXPECT_EQ(written.exit_code, 0) << written.err;
  EXPECT_EQ(detect.wait(std::chrono::seconds(60)), 0) << detect.log();
  return read_detect_csv(dir / "detect.csv");
}

bool have_ros_tools() {
  return test::run("command -v roscore >/dev/null && command -v rosbag").exit_code == 0 && have_python_rosbag();
}

/// Skips the test without roscore, rosbag and the bag writer's modules, and when roscpp was initialised in
/// this process already (class TestMaster).
#define REQUIRE_ROS_TOOLS()                                                                                     \
  do {                                                                                                        \
    if (!have_ros_tools()) {                                                                                  \
      GTEST_SKIP() << "roscore, rosbag or python3-rosbag/sensor-msgs/numpy/png not installed: rdsf_people test " \
                      "skipped";                                                                              \
    }                                                                                                         \
    if (TestMaster::taken()) {                                                                                \
      GTEST_SKIP() << "roscpp was initialised by a test before in this process: run it alone (ctest does)";     \
    }                                                                                                         \
  } while (0)

// A roscore of the test's own on a free port (ROS_MASTER_URI, so parallel tests do not meet), this process a
// ROS node of it; stopped at the end. roscpp initialises once per process: ctest runs each test in its own
// (gtest_discover_tests); a second master in one process (the binary run whole) is not started.
class TestMaster {
 public:
  static bool taken() { return started_; }

  explicit TestMaster(const std::filesystem::path& dir) : port_(test::free_tcp_port()) {
    setenv("ROS_MASTER_URI", ("http://127.0.0.1:" + std::to_string(port_)).c_str(), 1);
    setenv("ROS_HOSTNAME", "127.0.0.1", 1);
    setenv("ROS_HOME", (dir / "ros_home").c_str(), 1);
    setenv("ROS_LOG_DIR", (dir / "ros_log").c_str(), 1);
    started_ = true;
    core_ = std::make_unique<BackgroundProcess>("roscore -p " + std::to_string(port_), dir / "roscore.log");
  }
  ~TestMaster() {
    if (ros::isInitialized()) ros::shutdown();
    core_->stop();
  }
  /// ros::init and wait for the master; false (with the log) when it did not come up.
  bool connect(std::string& why) {
    int argc = 1;
    char name[] = "test_ros_node";
    char* argv[] = {name, nullptr};
    ros::init(argc, argv, "rdsf_people_test", ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
    for (int i = 0; i < 300 && !ros::master::check(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (ros::master::check()) return true;
    why = "roscore did not come up on port " + std::to_string(port_) + ":\n" + core_->log();
    return false;
  }

 private:
  static inline bool started_ = false;
  int port_;
  std::unique_ptr<BackgroundProcess> core_;
};

// What rdsf_people publishes on /people (and its pictures on /people/image), collected while a bag is played.
class PeopleListener {
 public:
  PeopleListener() : spinner_(1) {
    people_ = nh_.subscribe<rdsf_people::People>("/people", 100, [this](const rdsf_people::PeopleConstPtr& m) {
      const std::lock_guard<std::mutex> lock(mutex_);
      received_.push_back(*m);
    });
    pictures_ = nh_.subscribe<sensor_msgs::Image>("/people/image", 10, [this](const sensor_msgs::ImageConstPtr& m) {
      const std::lock_guard<std::mutex> lock(mutex_);
      received_pictures_.push_back(cv_bridge::toCvCopy(m, "bgr8")->image);
    });
    diagnostics_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 10, [this](const diagnostic_msgs::DiagnosticArrayConstPtr&) {
          const std::lock_guard<std::mutex> lock(mutex_);
          node_up_ = true;
        });
    spinner_.start();
  }
  ~PeopleListener() { spinner_.stop(); }

  /// The pictures of the last play(), in arrival order.
  std::vector<cv::Mat> pictures() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return received_pictures_;
  }

  /// Starts the node with `node_arguments` (as rosrun gives them), waits until it is up (its first
  /// /diagnostics), plays the bag (`play_arguments`: rosbag play's options and the file), waits for up to
  /// `expected` messages, stops the node; returns what it published in stamp order, and its log in `log`.
  std::vector<rdsf_people::People> play(const std::string& node_arguments, const std::string& play_arguments,
                                        std::size_t expected, const std::string& log_path, std::string& log) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      received_.clear();
      received_pictures_.clear();
      node_up_ = false;
    }
    BackgroundProcess node(std::string(RDSF_BINARY_DIR) + "/ros/rdsf_people " + node_arguments +
                               " --diagnostics-period 0.5",
                           log_path);
    auto up = [&] {
      const std::lock_guard<std::mutex> lock(mutex_);
      return node_up_;
    };
    for (int i = 0; i < 300 && !up() && node.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_TRUE(up()) << "rdsf_people did not come up:\n" << node.log();
    const test::RunResult played = test::run("timeout 60 rosbag play -q -d 1 " + play_arguments);
    EXPECT_EQ(played.exit_code, 0) << played.err;
    auto count = [&] {
      const std::lock_guard<std::mutex> lock(mutex_);
      return received_.size();
    };
    for (int i = 0; i < 100 && count() < expected; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(node.stop(), 0) << node.log();
    log = node.log();
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<rdsf_people::People> out = received_;
    std::sort(out.begin(), out.end(),
              [](const rdsf_people::People& a, const rdsf_people::People& b) { return a.header.stamp < b.header.stamp; });
    return out;
  }

 private:
  ros::NodeHandle nh_;
  std::mutex mutex_;
  std::vector<rdsf_people::People> received_;
  std::vector<cv::Mat> received_pictures_;
  bool node_up_ = false;
  ros::Subscriber people_, pictures_, diagnostics_;
  ros::AsyncSpinner spinner_;
};

#endif

[[maybe_unused]] constexpr const char* kWithoutRos =
    "built without ROS 1 (RDSF_WITH_ROS=OFF: Debian's roscpp, cv_bridge, image_transport, gencpp ... not found; "
    "scripts/setup.sh installs them): rdsf_people test skipped";

TEST(RosNode, PublishesTheSamePeopleAsRdsfDetectFromABagOfRealFrames) {
#if !RDSF_TEST_WITH_ROS
  GTEST_SKIP() << kWithoutRos;
#else
  RDSF_REQUIRE_REALDATA();
  REQUIRE_ROS_TOOLS();
  test::TempDir dir("rdsf-ros");
  const std::string frames = (test::realdata_dir() / "people").string();
  const std::string models = std::string(RDSF_SOURCE_DIR) + "/models";

  // A master of our own, and meanwhile rdsf-detect's answer and the bag (46 depth frames with camera_info,
  // 14 with colour; 30 frames/s stamps).
  TestMaster master(dir.path());
  const std::vector<CsvFrame> expected = detect_and_write_bag(dir, "", dir / "people.bag");
  ASSERT_EQ(expected.size(), 46U);

  std::string why;
  ASSERT_TRUE(master.connect(why)) << why;
  PeopleListener listener;
  // The node with the real frames' topics and `parameters`, the bag played at 0.2 x its rate.
  auto play_to_node = [&](const std::string& parameters, const std::string& log_name, std::string& log) {
    return listener.play("depth/image:=/camera/depth/image_raw rgb/image:=/camera/rgb/image_raw _colour:=true "
                         "_model:=people _models_dir:=" + test::quote(models) + parameters,
                         "-r 0.2 " + test::quote(dir / "people.bag"), expected.size(), dir / log_name, log);
  };
  const BoostedModel model = BoostedModel::load("people", models);
  const auto compare = [&](const std::vector<rdsf_people::People>& got, const std::vector<CsvFrame>& want) {
    return expect_same_people(got, want, model);
  };

  std::string log;
  // The default: a frame does not wait for its colour image; it takes the one already there, within 100 ms
  // of its stamp (the previous frame's at 30 frames/s stamps). Candidates and scores do not depend on
  // colour, so they are rdsf-detect's; track ids may not be (the histograms come from another frame).
  const std::vector<rdsf_people::People> no_wait = play_to_node("", "node-no-wait.log", log);
  EXPECT_NE(log.find("46 depth images received, 0 refused, 46 processed, 0 dropped; "), std::string::npos) << log;
  // No ~threshold: the node says it reads the model at the operating point the model states.
  EXPECT_NE(log.find(", people at P >= 0.27 (its operating point)"), std::string::npos) << log;
  const std::size_t with = log.find(" with colour");
  ASSERT_NE(with, std::string::npos) << log;
  const std::size_t count_at = log.rfind(' ', with - 1) + 1;
  EXPECT_GT(std::stoi(log.substr(count_at, with - count_at)), 0) << log;
  ASSERT_EQ(no_wait.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const CsvFrame& e = expected[i];
    EXPECT_EQ(no_wait[i].candidates, static_cast<std::uint32_t>(e.candidates)) << e.name;
    EXPECT_EQ(no_wait[i].people.size(), e.people.size()) << e.name;
  }

  // Waiting for each frame's own colour image (~colour_wait true: a bool parameter reaches the option; it
  // stays on the parameter server for the next node, as rosrun's _NAME:=VALUE does) the node's people are
  // rdsf-detect's frame for frame, track ids included. No frame refused or dropped.
  const std::vector<rdsf_people::People> plain = play_to_node(" _colour_wait:=true", "node.log", log);
  EXPECT_NE(log.find("46 depth images received, 0 refused, 46 processed, 0 dropped; 14 with colour"), std::string::npos)
      << log;
  EXPECT_GT(compare(plain, expected), 20);  // the real frames hold 49 people: most of them are found

  // With a background model of the room (~background, rdsf-background; learned here from the same frames,
  // which suits the comparison, not a room) the node adds the same candidates as rdsf-detect --background.
  const std::string background = dir / "background";
  const test::RunResult learned = test::run(test::program("rdsf-background") + " --source " + test::quote(frames) +
                                            " --out " + test::quote(background));
  ASSERT_EQ(learned.exit_code, 0) << learned.err;
  // rdsf-detect's frames with `options`, written to `file`.
  auto detect_with = [&](const std::string& options, const std::string& file) {
    const test::RunResult run = test::run(test::program("rdsf-detect") + " --source " + test::quote(frames) +
                                          " --model people --models-dir " + test::quote(models) + " " + options +
                                          " --out " + test::quote(dir / file));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return read_detect_csv(dir / file);
  };
  const std::vector<CsvFrame> expected_background = detect_with("--background " + test::quote(background), "detect-background.csv");
  int more = 0;
  for (std::size_t i = 0; i < expected.size() && i < expected_background.size(); ++i) {
    more += expected_background[i].candidates - expected[i].candidates;
  }
  EXPECT_GT(more, 0);  // the background added candidates: the run below compares something new
  const std::vector<rdsf_people::People> in_front = play_to_node(
      " _colour_wait:=true _background:=" + test::quote(background), "node-background.log", log);
  EXPECT_NE(log.find("46 depth images received, 0 refused, 46 processed, 0 dropped; 14 with colour"), std::string::npos)
      << log;
  compare(in_front, expected_background);

  // A switch row as a bool parameter (~relaxed true reaches --relaxed=true; ~background stays on the server):
  // rdsf-detect --background --relaxed's candidates, which differ from the run before.
  const std::vector<CsvFrame> expected_relaxed =
      detect_with("--background " + test::quote(background) + " --relaxed", "detect-relaxed.csv");
  int differ = 0;
  for (std::size_t i = 0; i < expected_background.size() && i < expected_relaxed.size(); ++i) {
    differ += expected_relaxed[i].candidates != expected_background[i].candidates ? 1 : 0;
  }
  EXPECT_GT(differ, 0);  // relaxed heights change the candidates of these frames
  const std::vector<rdsf_people::People> relaxed = play_to_node(" _relaxed:=true", "node-relaxed.log", log);
  EXPECT_NE(log.find("46 depth images received, 0 refused, 46 processed, 0 dropped"), std::string::npos) << log;
  compare(relaxed, expected_relaxed);
#endif
}

// A robot's compressed topics played to the node (~depth_transport compressedDepth, ~colour_transport
// compressed; Debian has no image_transport plugins, so the node decodes them itself): frame for frame
// rdsf-detect's people on the PNG folder (the colour PNG is lossless, so the track ids too), with the
// camera_info of each image's stamp (message_filters) and with the latest one.
TEST(RosNode, CompressedTopicsGiveTheSamePeopleAsTheFolder) {
#if !RDSF_TEST_WITH_ROS
  GTEST_SKIP() << kWithoutRos;
#else
  RDSF_REQUIRE_REALDATA();
  REQUIRE_ROS_TOOLS();
  test::TempDir dir("rdsf-ros-compressed");
  const std::string models = std::string(RDSF_SOURCE_DIR) + "/models";
  TestMaster master(dir.path());
  const std::vector<CsvFrame> expected =
      detect_and_write_bag(dir, "--compressed-depth png --compressed-colour png", dir / "compressed.bag");
  ASSERT_EQ(expected.size(), 46U);
  std::string why;
  ASSERT_TRUE(master.connect(why)) << why;
  PeopleListener listener;
  const BoostedModel model = BoostedModel::load("people", models);
  const std::string arguments = "depth/image:=/camera/depth/image_raw rgb/image:=/camera/rgb/image_raw _colour:=true "
                                "_colour_wait:=true _depth_transport:=compressedDepth _colour_transport:=compressed "
                                "_model:=people _models_dir:=" + test::quote(models);
  const std::string bag = "-r 0.2 " + test::quote(dir / "compressed.bag");
  std::string log;
  const std::vector<rdsf_people::People> by_stamp = listener.play(arguments, bag, 46, dir / "exact.log", log);
  EXPECT_NE(log.find("/camera/depth/image_raw/compressedDepth with /camera/depth/camera_info (by stamp) and "
                     "/camera/rgb/image_raw/compressed"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("46 depth images received, 0 refused, 46 processed, 0 dropped; 14 with colour"), std::string::npos)
      << log;
  EXPECT_GT(expect_same_people(by_stamp, expected, model), 20);

  const std::vector<rdsf_people::People> latest = listener.play(arguments + " _camera_info:=latest", bag, 46,
                                                                dir / "latest.log", log);
  EXPECT_NE(log.find("46 depth images received, 0 refused, 46 processed, 0 dropped; 14 with colour"), std::string::npos)
      << log;
  EXPECT_GT(expect_same_people(latest, expected, model), 20);
#endif
}

// A robot's bag whose only camera_info is the colour camera's, stamped 100 ms apart from the registered depth
// image (datasets/public/tue_hero/hall_1.bag, a Toyota HSR's head camera): by exact stamp the node gets no
// frame; with ~camera_info latest (depth/camera_info remapped to the colour camera's) it publishes
// rdsf-detect's people of the same bag, also when the depth image comes first and waits for the camera_info;
// a camera_info of another optical frame is refused.
TEST(RosNode, ARobotsBagWithTheColourCamerasCameraInfoIsReadWithTheLatestCameraInfo) {
#if !RDSF_TEST_WITH_ROS
  GTEST_SKIP() << kWithoutRos;
#else
  REQUIRE_ROS_TOOLS();
  test::TempDir dir("rdsf-ros-hall");
  const std::string bag = std::string(RDSF_SOURCE_DIR) + "/datasets/public/tue_hero/hall_1.bag";
  const std::string models = std::string(RDSF_SOURCE_DIR) + "/models";
  TestMaster master(dir.path());

  // rdsf-detect's answer (the bag source takes the CameraInfo of the depth images' optical frame).
  const test::RunResult detect = test::run(test::program("rdsf-detect") + " --source " + test::quote(bag) +
                                           " --model people --models-dir " + test::quote(models) + " --out " +
                                           test::quote(dir / "detect.csv") + " --save-dir " + test::quote(dir.path()));
  ASSERT_EQ(detect.exit_code, 0) << detect.err;
  const std::vector<CsvFrame> expected = read_detect_csv(dir / "detect.csv");
  ASSERT_EQ(expected.size(), 1U);
  const cv::Mat saved_picture = cv::imread(dir / "0.detections.png", cv::IMREAD_COLOR);
  ASSERT_FALSE(saved_picture.empty());
  ASSERT_GE(expected[0].people.size(), 1U);  // the man standing in front of the robot (and the seated person)

  // Two copies: the depth image before the camera_info, and a camera_info of another optical frame.
  std::ofstream(dir / "variants.py") << R"(import sys, rosbag, rospy
source, later, other = sys.argv[1:4]
messages = list(rosbag.Bag(source).read_messages())
with rosbag.Bag(later, 'w') as out:
    last = max(t for _, _, t in messages)
    for topic, msg, t in messages:
        out.write(topic, msg, last + rospy.Duration(0.5) if topic.endswith('camera_info') else t)
with rosbag.Bag(other, 'w') as out:
    for topic, msg, t in messages:
        if topic.endswith('camera_info'):
            msg.header.frame_id = 'head_rgbd_sensor_ir_frame'
        out.write(topic, msg, t)
)";
  const test::RunResult variants = test::run("/usr/bin/python3 " + test::quote(dir / "variants.py") + " " +
                                             test::quote(bag) + " " + test::quote(dir / "later.bag") + " " +
                                             test::quote(dir / "other.bag"));
  ASSERT_EQ(variants.exit_code, 0) << variants.err;

  std::string why;
  ASSERT_TRUE(master.connect(why)) << why;
  PeopleListener listener;
  const std::string topics = "depth/image:=/hero/head_rgbd_sensor/depth_registered/image "
                             "depth/camera_info:=/hero/head_rgbd_sensor/rgb/camera_info _models_dir:=" +
                             test::quote(models);
  auto same_as_detect = [&](const std::vector<rdsf_people::People>& got) {
    ASSERT_EQ(got.size(), 1U);
    EXPECT_EQ(got[0].header.frame_id, "head_rgbd_sensor_rgb_frame");
    EXPECT_EQ(got[0].candidates, static_cast<std::uint32_t>(expected[0].candidates));
    ASSERT_EQ(got[0].people.size(), expected[0].people.size());
    int standing = 0;
    for (std::size_t k = 0; k < got[0].people.size(); ++k) {
      const rdsf_people::Person& p = got[0].people[k];
      const CsvPerson& e = expected[0].people[k];
      EXPECT_EQ(static_cast<int>(p.box.x_offset), e.x);
      EXPECT_EQ(static_cast<int>(p.box.y_offset), e.y);
      EXPECT_EQ(static_cast<int>(p.box.width), e.w);
      EXPECT_EQ(static_cast<int>(p.box.height), e.h);
      EXPECT_EQ(printed("%.4f", p.score), e.score);
      standing += p.position_m.z > 1.5 && p.position_m.z < 2.2 ? 1 : 0;  // the man, 1.7-2.0 m in front
    }
    EXPECT_EQ(standing, 1);
  };

  std::string log;
  // By exact stamp (the default): the depth image never meets a camera_info of its stamp.
  const std::vector<rdsf_people::People> exact = listener.play(topics, test::quote(bag), 0, dir / "exact.log", log);
  EXPECT_TRUE(exact.empty());
  EXPECT_NE(log.find("0 depth images received"), std::string::npos) << log;

  const std::vector<rdsf_people::People> latest =
      listener.play(topics + " _camera_info:=latest", test::quote(bag), 1, dir / "latest.log", log);
  same_as_detect(latest);
  EXPECT_NE(log.find("1 depth images received, 0 refused, 1 processed, 0 dropped"), std::string::npos) << log;
  // Watched, the node publishes rdsf-detect --save-dir's picture of the frame, pixel for pixel.
  const std::vector<cv::Mat> pictures = listener.pictures();
  ASSERT_EQ(pictures.size(), 1U);
  ASSERT_EQ(pictures[0].size(), saved_picture.size());
  EXPECT_EQ(cv::norm(pictures[0], saved_picture, cv::NORM_INF), 0);
  EXPECT_NE(log.find("/hero/head_rgbd_sensor/rgb/camera_info (the latest)"), std::string::npos) << log;

  const std::vector<rdsf_people::People> waited = listener.play(topics + " --camera-info latest",
                                                                test::quote(dir / "later.bag"), 1, dir / "later.log", log);
  same_as_detect(waited);
  EXPECT_NE(log.find("waiting for the first camera_info"), std::string::npos) << log;

  const std::vector<rdsf_people::People> other = listener.play(topics + " _camera_info:=latest",
                                                               test::quote(dir / "other.bag"), 0, dir / "other.log", log);
  EXPECT_TRUE(other.empty());
  EXPECT_NE(log.find("1 depth images received, 1 refused, 0 processed"), std::string::npos) << log;
  EXPECT_NE(log.find("camera_info of frame 'head_rgbd_sensor_ir_frame' for a depth image of frame "
                     "'head_rgbd_sensor_rgb_frame'"),
            std::string::npos)
      << log;
#endif
}

}  // namespace
}  // namespace rdsf
