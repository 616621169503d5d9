// The library's only rosbag include (built when RDSF_WITH_ROSBAG is on; frame_source.cpp refuses .bag
// without it). See rdsf/frame/bag_source.hpp for the rules.
#include "rdsf/frame/bag_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Float32.h>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/bag_layout.hpp"
#include "rdsf/frame/compressed_image.hpp"
#include "rdsf/frame/depth_units.hpp"

namespace rdsf {
namespace {

using ImagePtr = boost::shared_ptr<sensor_msgs::Image>;
using CompressedPtr = boost::shared_ptr<sensor_msgs::CompressedImage>;

constexpr const char* kImageType = "sensor_msgs/Image";
constexpr const char* kCompressedType = "sensor_msgs/CompressedImage";

bool is_depth_encoding(const std::string& e) { return e == "16UC1" || e == "mono16" || e == "32FC1"; }
bool is_colour_encoding(const std::string& e) { return e == "rgb8" || e == "bgr8"; }
bool is_image_type(const std::string& datatype) { return datatype == kImageType || datatype == kCompressedType; }

// A message of an image topic: a sensor_msgs/Image, or a CompressedImage (frame/compressed_image.hpp).
struct ImageMessage {
  ImagePtr raw;
  CompressedPtr compressed;
  explicit operator bool() const { return raw || compressed; }
  const std_msgs::Header& header() const { return raw ? raw->header : compressed->header; }
};

std::string parent_of(const std::string& topic) {
  const auto slash = topic.find_last_of('/');
  return slash == std::string::npos ? std::string() : topic.substr(0, slash);
}

/// "/device_0/sensor_0" of a RealSense topic "/device_0/sensor_0/Depth_0/image/data", empty otherwise.
std::string realsense_sensor_prefix(const std::string& topic) {
  if (topic.rfind("/device_", 0) != 0) return {};
  const auto second = topic.find("/sensor_", 1);
  if (second == std::string::npos) return {};
  const auto end = topic.find('/', second + 1);
  return end == std::string::npos ? std::string() : topic.substr(0, end);
}

bool is_realsense_depth_topic(const std::string& topic) {
  return !realsense_sensor_prefix(topic).empty() && topic.find("/Depth_") != std::string::npos &&
         topic.size() > 11 && topic.compare(topic.size() - 11, 11, "/image/data") == 0;
}

std::int64_t stamp_us(const ros::Time& stamp) {
  return static_cast<std::int64_t>(stamp.sec) * 1000000 + static_cast<std::int64_t>(stamp.nsec) / 1000;
}

struct TopicInfo {
  std::string name, datatype, encoding;  // encoding of the first image (Image), format (CompressedImage)
  std::string frame_id;                  // the first message's header.frame_id (Image and CameraInfo topics)
  int width = 0, height = 0;  // the first image's, or the first CameraInfo's
  std::string problem;        // why the first compressed image could not be decoded, or empty

  /// The encoding of its images: an Image's, or what a CompressedImage's format names.
  std::string image_encoding() const {
    return datatype == kCompressedType ? compressed_image_encoding(encoding) : encoding;
  }
  bool is_depth() const {
    if (datatype == kImageType) return is_depth_encoding(encoding);
    return datatype == kCompressedType && is_compressed_depth_format(encoding) && is_depth_encoding(image_encoding());
  }
  bool is_colour() const {
    if (datatype == kImageType) return is_colour_encoding(encoding);
    return datatype == kCompressedType && !is_compressed_depth_format(encoding) &&
           (encoding.find("jpeg") != std::string::npos || encoding.find("png") != std::string::npos);
  }
};

}  // namespace

struct BagSource::Impl {
  std::string path;
  FrameSourceOptions options;
  rosbag::Bag bag;
  std::vector<TopicInfo> topics;
  std::string depth_topic, colour_topic, camera_note, depth_encoding, colour_note;
  double unit_mm = 1.0;
  std::string unit_note;
  CameraModel camera;
  std::unique_ptr<rosbag::View> depth_view, colour_view;
  rosbag::View::iterator depth_it, colour_it;
  std::int64_t count = 0, delivered = 0;
  ImageMessage after;      // the next colour frame not yet paired
  ImageMessage lookahead;  // the next depth image (read ahead for its stamp), null at the end
  std::int64_t lookahead_us = 0;
  std::optional<std::int64_t> previous_us;  // the stamp of the depth frame delivered last
  std::int64_t paired = 0, gap_sum_us = 0, gap_max_us = 0;
  std::int64_t beyond = 0, beyond_nearest_us = INT64_MAX;  // depth frames whose nearest colour was too far

  [[noreturn]] void fail_topic(const std::string& topic, const std::string& what) const {
    fail(path, "topic " + topic + ": " + what);
  }

  void list_topics() {
    rosbag::View all(bag);
    std::vector<std::string> seen;
    for (const rosbag::ConnectionInfo* c : all.getConnections()) {
      if (std::find(seen.begin(), seen.end(), c->topic) != seen.end()) continue;
      seen.push_back(c->topic);
      TopicInfo t{c->topic, c->datatype, "", "", 0, 0, ""};
      rosbag::View one(bag, rosbag::TopicQuery(c->topic));
      if (c->datatype == kCompressedType && one.begin() != one.end()) {
        CompressedPtr image = one.begin()->instantiate<sensor_msgs::CompressedImage>();
        if (image) {
          t.encoding = image->format;
          t.frame_id = image->header.frame_id;
          // Its size is the first image's, decoded (one frame); a fault is said when the topic is chosen.
          const std::string where = path + ": topic " + c->topic + ": image 0";
          try {
            const cv::Mat decoded = t.is_depth() ? cv::Mat(decode_compressed_depth(where, image->format, image->data.data(),
                                                                                   image->data.size()))
                                  : t.is_colour() ? cv::Mat(decode_compressed_colour(where, image->format,
                                                                                     image->data.data(), image->data.size()))
                                                  : cv::Mat();
            t.width = decoded.cols;
            t.height = decoded.rows;
          } catch (const Error& e) {
            t.problem = e.what();
          }
        }
      } else if (c->datatype == kImageType && one.begin() != one.end()) {
        ImagePtr image = one.begin()->instantiate<sensor_msgs::Image>();
        if (image) {
          t.encoding = image->encoding;
          t.frame_id = image->header.frame_id;
          t.width = static_cast<int>(image->width);
          t.height = static_cast<int>(image->height);
        }
      } else if (c->datatype == "sensor_msgs/CameraInfo" && one.begin() != one.end()) {
        auto info = one.begin()->instantiate<sensor_msgs::CameraInfo>();
        if (info) {
          t.frame_id = info->header.frame_id;
          t.width = static_cast<int>(info->width);
          t.height = static_cast<int>(info->height);
        }
      }
      topics.push_back(t);
    }
    std::sort(topics.begin(), topics.end(), [](const TopicInfo& a, const TopicInfo& b) { return a.name < b.name; });
  }

  const TopicInfo* find(const std::string& name) const {
    for (const TopicInfo& t : topics)
      if (t.name == name) return &t;
    return nullptr;
  }

  std::string image_topics() const {
    std::string out;
    for (const TopicInfo& t : topics) {
      if (!is_image_type(t.datatype)) continue;
      out += (out.empty() ? "" : ", ") + t.name + " (" + (t.encoding.empty() ? "no messages" : t.encoding) + ")";
    }
    return out.empty() ? "none" : out;
  }

  /// Drops the compressed topics whose image topic is among `chosen` too (a recorder that kept both
  /// ".../image_raw" and ".../image_raw/compressedDepth": the same images, raw ones lossless and cheaper).
  static void without_compressed_twins(std::vector<const TopicInfo*>& chosen) {
    const auto twin_in_chosen = [&](const TopicInfo* t) {
      return t->datatype == kCompressedType &&
             std::any_of(chosen.begin(), chosen.end(), [&](const TopicInfo* u) { return u->name == parent_of(t->name); });
    };
    chosen.erase(std::remove_if(chosen.begin(), chosen.end(), twin_in_chosen), chosen.end());
  }

  void choose_depth_topic() {
    if (!options.depth_topic.empty()) {
      const TopicInfo* t = find(options.depth_topic);
      if (t == nullptr) fail_topic(options.depth_topic, "not in the bag (image topics: " + image_topics() + ")");
      if (!is_image_type(t->datatype)) fail_topic(t->name, t->datatype + " is not sensor_msgs/Image or CompressedImage");
      if (t->encoding.empty()) fail_topic(t->name, "holds no images");
      if (!t->is_depth()) {
        fail_topic(t->name, "encoding " + t->encoding +
                                " is not a depth encoding (16UC1, mono16, 32FC1; compressed: compressedDepth)");
      }
      if (!t->problem.empty()) throw Error(t->problem);
      depth_topic = t->name;
      return;
    }
    std::vector<const TopicInfo*> depth, realsense;
    for (const TopicInfo& t : topics) {
      if (!t.is_depth()) continue;
      depth.push_back(&t);
      if (is_realsense_depth_topic(t.name)) realsense.push_back(&t);
    }
    if (depth.size() != 1 && realsense.size() == 1) depth = realsense;
    without_compressed_twins(depth);
    if (depth.empty()) {
      fail(path, "no depth image topic (16UC1, mono16, 32FC1; compressedDepth); image topics: " + image_topics());
    }
    if (depth.size() > 1) {
      std::string names;
      for (const TopicInfo* t : depth) names += (names.empty() ? "" : ", ") + t->name;
      fail(path, "several depth image topics, choose one: " + names);
    }
    if (!depth.front()->problem.empty()) throw Error(depth.front()->problem);
    depth_topic = depth.front()->name;
  }

  void choose_colour_topic(int width, int height) {
    if (options.colour_topic == "none") return;
    if (!options.colour_topic.empty()) {
      const TopicInfo* t = find(options.colour_topic);
      if (t == nullptr) fail_topic(options.colour_topic, "not in the bag (image topics: " + image_topics() + ")");
      if (!is_image_type(t->datatype)) fail_topic(t->name, t->datatype + " is not sensor_msgs/Image or CompressedImage");
      if (!t->encoding.empty() && !t->is_colour()) {
        fail_topic(t->name, "encoding " + t->encoding + " is not a colour encoding (rgb8, bgr8; compressed: jpeg, png)");
      }
      if (!t->problem.empty()) throw Error(t->problem);
      if (!t->encoding.empty() && (t->width != width || t->height != height)) {
        fail_topic(t->name, "colour is " + std::to_string(t->width) + "x" + std::to_string(t->height) +
                                ", the depth " + std::to_string(width) + "x" + std::to_string(height) +
                                " (colour must be registered to the depth)");
      }
      colour_topic = t->name;
      return;
    }
    std::vector<const TopicInfo*> fitting;
    for (const TopicInfo& t : topics) {
      if (!t.is_colour()) continue;
      if (!t.problem.empty()) {
        colour_note += (colour_note.empty() ? "" : "; ") + t.name + " cannot be decoded: not used";
      } else if (t.width == width && t.height == height) {
        fitting.push_back(&t);
      } else {
        colour_note += (colour_note.empty() ? "" : "; ") + t.name + " is " + std::to_string(t.width) + "x" +
                       std::to_string(t.height) + ", not the depth's size: not used";
      }
    }
    without_compressed_twins(fitting);
    if (fitting.size() == 1) colour_topic = fitting.front()->name;
    if (fitting.size() > 1) colour_note = std::to_string(fitting.size()) + " colour topics: none used";
  }

  void read_depth_scale() {
    const std::string sensor = realsense_sensor_prefix(depth_topic);
    if (sensor.empty() || find(depth_topic)->image_encoding() == "32FC1") return;
    const std::string units = sensor + "/option/Depth Units/value";
    rosbag::View view(bag, rosbag::TopicQuery(units));
    if (view.begin() == view.end()) {
      unit_note = "no " + units + ": 1 mm per unit";
      return;
    }
    auto value = view.begin()->instantiate<std_msgs::Float32>();
    if (!value) fail_topic(units, "is not std_msgs/Float32");
    if (!(value->data > 0.0f) || !(value->data < 1.0f)) {
      fail_topic(units, "depth unit " + std::to_string(value->data) + " m is not in (0, 1)");
    }
    unit_mm = 1000.0 * static_cast<double>(value->data);
    std::ostringstream note;
    note << unit_mm << " mm per unit (" << units << ")";
    unit_note = note.str();
  }

  /// The CameraInfo topics to read the depth images' camera from, in order: beside them (TOPIC's folder +
  /// "/camera_info", TOPIC without its transport for a compressed one, or the RealSense layout's ".../info/camera_info"); else the bag's one CameraInfo topic
  /// in the depth images' optical frame (the same non-empty header.frame_id): a depth image registered to a
  /// colour camera ("depth_registered") has that camera's intrinsics, and a recorder may have kept only the
  /// colour camera's CameraInfo (a Toyota HSR's head camera: datasets/public/tue_hero). Its size must be
  /// the images' (or unstated).
  std::vector<std::string> camera_info_topics(int width, int height) {
    // A compressed topic is its image topic's transport (".../image_raw/compressedDepth"): its camera_info is
    // beside the image topic.
    const std::string image_topic = find(depth_topic)->datatype == kCompressedType ? parent_of(depth_topic) : depth_topic;
    std::vector<std::string> out = {parent_of(image_topic) + "/camera_info",
                                    parent_of(parent_of(image_topic)) + "/info/camera_info"};
    const std::string& frame = find(depth_topic)->frame_id;
    if (frame.empty() || find(out[0]) != nullptr || find(out[1]) != nullptr) return out;
    std::vector<std::string> same_frame;
    for (const TopicInfo& t : topics) {
      const bool same_size = (t.width == width && t.height == height) || (t.width == 0 && t.height == 0);
      if (t.datatype == "sensor_msgs/CameraInfo" && t.frame_id == frame && same_size) same_frame.push_back(t.name);
    }
    if (same_frame.size() == 1) out.push_back(same_frame.front());
    if (same_frame.size() > 1) {
      camera_note = std::to_string(same_frame.size()) + " CameraInfo topics in the depth images' frame " + frame +
                    ", none beside them";
    }
    return out;
  }

  void read_camera_info(int width, int height) {
    const CameraModel fallback = options.camera.width_px == width && options.camera.height_px == height
                                     ? options.camera
                                     : options.camera.scaled_to(width, height);
    const std::vector<std::string> candidates = camera_info_topics(width, height);
    for (const std::string& topic : candidates) {
      const TopicInfo* t = find(topic);
      if (t == nullptr || t->datatype != "sensor_msgs/CameraInfo") continue;
      rosbag::View view(bag, rosbag::TopicQuery(topic));
      if (view.begin() == view.end()) continue;
      auto info = view.begin()->instantiate<sensor_msgs::CameraInfo>();
      const bool has_focal_lengths = info && info->K[0] > 0 && info->K[4] > 0 &&
                                     std::isfinite(info->K[0] + info->K[2] + info->K[4] + info->K[5]);
      if (!has_focal_lengths) {
        camera_note = topic + " has no focal lengths (K[0], K[4])";
        break;
      }
      if ((info->width != 0 || info->height != 0) &&
          (static_cast<int>(info->width) != width || static_cast<int>(info->height) != height)) {
        fail_topic(topic, "camera info is " + std::to_string(info->width) + "x" + std::to_string(info->height) +
                              ", its depth images " + std::to_string(width) + "x" + std::to_string(height));
      }
      camera.width_px = width;
      camera.height_px = height;
      camera.fx_px = info->K[0];
      camera.cx_px = info->K[2];
      camera.fy_px = info->K[4];
      camera.cy_px = info->K[5];
      if (options.camera_given) {
        camera = fallback;
        camera_note = "camera model given (" + topic + " not used)";
      } else {
        camera_note = "camera model from " + topic;
        if (topic == candidates.back() && candidates.size() > 2) {
          camera_note += " (the depth images' optical frame " + find(depth_topic)->frame_id + ")";
        }
      }
      return;
    }
    camera = fallback;
    if (options.camera_given) {
      camera_note = "camera model given";
    } else {
      camera_note = (camera_note.empty() ? "no CameraInfo for " + depth_topic : camera_note) +
                    ": the given camera model is used";
    }
  }

  void open() {
    const std::string layout = bag_layout_problem(path);
    if (!layout.empty()) fail(path, "cannot be read as a ROS 1 bag (" + layout + ")");
    try {
      bag.open(path, rosbag::bagmode::Read);
    } catch (const rosbag::BagException& e) {
      fail(path, std::string("cannot be read as a ROS 1 bag (") + e.what() + ")");
    }
    list_topics();
    choose_depth_topic();
    const TopicInfo& depth = *find(depth_topic);
    depth_encoding = depth.encoding;
    if (depth.width <= 0 || depth.height <= 0) fail_topic(depth_topic, "image of size 0");
    choose_colour_topic(depth.width, depth.height);
    read_depth_scale();
    read_camera_info(depth.width, depth.height);
    depth_view = std::make_unique<rosbag::View>(bag, rosbag::TopicQuery(depth_topic));
    count = depth_view->size();
    depth_it = depth_view->begin();
    if (depth_it != depth_view->end()) {
      lookahead = instantiate_image(*depth_it, depth_topic);
      lookahead_us = depth_stamp_us(lookahead, *depth_it);
    }
    if (!colour_topic.empty()) {
      colour_view = std::make_unique<rosbag::View>(bag, rosbag::TopicQuery(colour_topic));
      colour_it = colour_view->begin();
      after = next_colour();
    }
  }

  ImageMessage next_colour() {
    if (colour_it == colour_view->end()) return {};
    ImageMessage image = instantiate_image(*colour_it, colour_topic);
    ++colour_it;
    return image;
  }

  // The decoding below reads only what open() set, so frames decode on several threads at once (next_deferred);
  // `index` is the frame's, for errors.

  /// A compressed image decoded (`decode`), checked to be of the camera model's size.
  template <typename Decode>
  auto decoded(const std::string& topic, const sensor_msgs::CompressedImage& image, std::int64_t index,
               Decode decode) const {
    const auto out = decode(path + ": topic " + topic + ": image " + std::to_string(index), image.format,
                            image.data.data(), image.data.size());
    check_size(topic, out.cols, out.rows, index);
    return out;
  }

  /// An image must be of the camera model's size.
  void check_size(const std::string& topic, std::int64_t cols, std::int64_t rows, std::int64_t index) const {
    if (cols != camera.width_px || rows != camera.height_px) {
      fail_topic(topic, "image " + std::to_string(index) + " is " + std::to_string(cols) + "x" + std::to_string(rows) +
                            ", the camera model " + camera.describe());
    }
  }

  /// Checks an image's byte order, size (the camera model's) and data length (step x height).
  void check_image(const std::string& topic, const sensor_msgs::Image& image, std::size_t bytes_per_pixel,
                   std::int64_t index) const {
    if (image.is_bigendian) fail_topic(topic, "big-endian images are not read");
    check_size(topic, image.width, image.height, index);
    if (image.step < image.width * bytes_per_pixel ||
        image.data.size() < static_cast<std::size_t>(image.step) * image.height) {
      fail_topic(topic, "image " + std::to_string(index) + " holds " + std::to_string(image.data.size()) +
                            " bytes, step " + std::to_string(image.step) + " x " + std::to_string(image.height) +
                            " rows needed");
    }
  }

  cv::Mat1w to_depth_mm(const ImageMessage& message, std::int64_t index) const {
    if (message.compressed) {
      return decoded(depth_topic, *message.compressed, index,
                     [this](const std::string& where, const std::string& format, const std::uint8_t* data, std::size_t size) {
                       return decode_compressed_depth(where, format, data, size, unit_mm);
                     });
    }
    const sensor_msgs::Image& image = *message.raw;
    const int rows = camera.height_px, cols = camera.width_px;
    cv::Mat1w depth(rows, cols);
    if (image.encoding == "32FC1") {
      check_image(depth_topic, image, 4, index);
      for (int y = 0; y < rows; ++y) {
        const std::uint8_t* row = image.data.data() + static_cast<std::size_t>(y) * image.step;
        for (int x = 0; x < cols; ++x) {
          float m;
          std::memcpy(&m, row + 4 * x, 4);
          depth(y, x) = depth_mm_of_metres(m);
        }
      }
      return depth;
    }
    if (image.encoding != "16UC1" && image.encoding != "mono16") {
      fail_topic(depth_topic, "image " + std::to_string(index) + " has encoding " + image.encoding +
                                  ", not a depth encoding (16UC1, mono16, 32FC1)");
    }
    check_image(depth_topic, image, 2, index);
    for (int y = 0; y < rows; ++y) {
      const std::uint8_t* row = image.data.data() + static_cast<std::size_t>(y) * image.step;
      std::memcpy(depth.ptr(y), row, 2 * static_cast<std::size_t>(cols));
      if (unit_mm == 1.0) continue;
      for (int x = 0; x < cols; ++x) depth(y, x) = depth_mm_of_units(depth(y, x), unit_mm);
    }
    return depth;
  }

  cv::Mat3b to_bgr(const ImageMessage& message, std::int64_t index) const {
    if (message.compressed) return decoded(colour_topic, *message.compressed, index, decode_compressed_colour);
    const sensor_msgs::Image& image = *message.raw;
    if (!is_colour_encoding(image.encoding)) {
      fail_topic(colour_topic, "image has encoding " + image.encoding + ", not a colour encoding (rgb8, bgr8)");
    }
    check_image(colour_topic, image, 3, index);
    const cv::Mat3b view(camera.height_px, camera.width_px,
                         reinterpret_cast<cv::Vec3b*>(const_cast<std::uint8_t*>(image.data.data())), image.step);
    cv::Mat3b bgr;
    if (image.encoding == "bgr8") {
      bgr = view.clone();
    } else {
      cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
    }
    return bgr;
  }

  /// The colour image for the depth frame stamped `depth_us` (previous depth frame at `previous`, next
  /// at `next_us`, each optional): of the colour frames nearer to it than to its neighbours (stamps in
  /// ((previous + depth) / 2, (depth + next) / 2]), the nearest, when within options.colour_gap_ms; or null.
  ImageMessage colour_for(std::int64_t depth_us, const std::optional<std::int64_t>& previous,
                          const std::optional<std::int64_t>& next_us, std::int64_t& gap_us) {
    ImageMessage best;
    gap_us = 0;
    std::int64_t best_gap = INT64_MAX;
    while (after) {
      const std::int64_t t = stamp_us(after.header().stamp);
      if (next_us && 2 * t > depth_us + *next_us) break;  // nearer to the next depth frame
      const bool nearer_to_previous = previous && 2 * t <= *previous + depth_us;
      const std::int64_t gap = t > depth_us ? t - depth_us : depth_us - t;
      if (!nearer_to_previous && gap < best_gap) best = after, best_gap = gap;
      after = next_colour();
    }
    if (!best) return {};
    if (static_cast<double>(best_gap) > options.colour_gap_ms * 1000.0) {
      ++beyond;
      beyond_nearest_us = std::min(beyond_nearest_us, best_gap);
      return {};
    }
    gap_us = best_gap;
    return best;
  }

  /// The stamp of a depth image: its header's, or the bag time when the header has none.
  static std::int64_t depth_stamp_us(const ImageMessage& image, const rosbag::MessageInstance& m) {
    const ros::Time& stamp = image.header().stamp;
    return stamp.isZero() ? stamp_us(m.getTime()) : stamp_us(stamp);
  }

  ImageMessage instantiate_image(const rosbag::MessageInstance& m, const std::string& topic) const {
    ImageMessage image;
    image.raw = m.instantiate<sensor_msgs::Image>();
    if (!image.raw) image.compressed = m.instantiate<sensor_msgs::CompressedImage>();
    if (!image) fail_topic(topic, "message is not sensor_msgs/Image or CompressedImage");
    return image;
  }
};

BagSource::BagSource(const std::string& path, const FrameSourceOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->options = options;
  try {
    impl_->open();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {  // rosbag's and ROS serialisation's exceptions
    fail(path, std::string("cannot be read as a ROS 1 bag (") + e.what() + ")");
  }
}

BagSource::~BagSource() = default;

bool BagSource::next(DepthFrame& frame) {
  FrameDecode decode;
  if (!next_deferred(decode)) return false;
  frame = decode();
  return true;
}

// In order: the next depth message (and the one after it, read ahead for its stamp), its colour message by
// the pairing rule, the pairing's figures. Deferred: both images' decoding.
bool BagSource::next_deferred(FrameDecode& decode) {
  Impl& s = *impl_;
  if (!s.lookahead) return false;
  const ImageMessage image = s.lookahead;
  const std::int64_t t_us = s.lookahead_us;
  ImageMessage colour;
  std::int64_t gap_us = 0;
  try {
    // Read the next depth image ahead: its stamp bounds the colour frames that are nearer to this one.
    s.lookahead = {};
    if (++s.depth_it != s.depth_view->end()) {
      s.lookahead = s.instantiate_image(*s.depth_it, s.depth_topic);
      s.lookahead_us = Impl::depth_stamp_us(s.lookahead, *s.depth_it);
    }
    if (s.colour_view) {
      const std::optional<std::int64_t> next_us = s.lookahead ? std::optional<std::int64_t>(s.lookahead_us) : std::nullopt;
      colour = s.colour_for(t_us, s.previous_us, next_us, gap_us);
      if (colour) {
        ++s.paired;
        s.gap_sum_us += gap_us;
        s.gap_max_us = std::max(s.gap_max_us, gap_us);
      }
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {  // a truncated chunk, a bad record: rosbag's exceptions
    s.fail_topic(s.depth_topic, "image " + std::to_string(s.delivered + 1) + " cannot be read (" + e.what() + ")");
  }
  s.previous_us = t_us;
  const std::int64_t index = s.delivered++;
  decode = [impl = impl_.get(), image, colour, gap_us, index, t_us] {
    DepthFrame frame;
    frame.depth_mm = impl->to_depth_mm(image, index);
    if (colour) {
      frame.bgr = impl->to_bgr(colour, index);
      frame.colour_gap_us = gap_us;
    }
    frame.index = index;
    frame.name = std::to_string(index);
    frame.timestamp_us = t_us;
    frame.camera = impl->camera;
    return frame;
  };
  return true;
}

std::string BagSource::description() const {
  const Impl& s = *impl_;
  std::string text = "bag " + s.path + ": depth " + s.depth_topic + " (" + s.depth_encoding + ", " +
                     std::to_string(s.count) + " frames" + (s.unit_note.empty() ? "" : ", " + s.unit_note) + ")";
  text += s.colour_topic.empty() ? ", no colour" : ", colour " + s.colour_topic;
  if (!s.colour_note.empty()) text += " (" + s.colour_note + ")";
  return text + ", " + s.camera_note + " (" + s.camera.describe() + ")";
}

std::optional<std::int64_t> BagSource::frame_count() const { return impl_->count; }
std::optional<std::vector<std::string>> BagSource::frame_names() const { return index_frame_names(impl_->count); }

std::string BagSource::summary() const {
  const Impl& s = *impl_;
  if (s.colour_topic.empty()) return {};
  std::ostringstream out;
  out << "colour " << s.colour_topic << " paired with " << s.paired << " of " << s.delivered << " depth frames";
  if (s.paired > 0) {
    out << ", stamp gap mean " << static_cast<double>(s.gap_sum_us) / s.paired / 1000.0 << " ms, max "
        << s.gap_max_us / 1000.0 << " ms";
  }
  if (s.beyond > 0) {  // what --colour-gap-ms would have to be to pair them
    out << "; " << s.beyond << " depth frame(s) had colour only beyond --colour-gap-ms " << s.options.colour_gap_ms
        << " (the nearest " << static_cast<double>(s.beyond_nearest_us) / 1000.0 << " ms away)";
  }
  return out.str();
}

const std::string& BagSource::depth_topic() const { return impl_->depth_topic; }
const CameraModel& BagSource::camera() const { return impl_->camera; }

}  // namespace rdsf
