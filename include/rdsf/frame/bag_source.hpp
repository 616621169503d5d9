#pragma once
// Frames from a ROS 1 bag, read with Debian's librosbag (rosbag::Bag, rosbag::View). The library's only
// rosbag include is src/frame/bag_source.cpp; a build without it (RDSF_WITH_ROSBAG 0 in rdsf/version.hpp)
// refuses .bag sources with one line.
//
// Depth: the sensor_msgs/Image messages of one topic (FrameSourceOptions::depth_topic, or the bag's only
// topic whose first image has a depth encoding; when several, a RealSense recording's one
// "/device_N/sensor_N/Depth_N/image/data" topic, else an Error listing them), in the order they were
// recorded (bag time), each exactly once, index 0, 1, 2...; name = the index; timestamp_us = the image
// header's stamp in microseconds (the bag time when the stamp is zero).
//   16UC1, mono16: depth units; depth_mm = round(units * unit_mm), unit_mm = 1 unless the recording states
//                  a depth scale (a RealSense recording's "/device_N/sensor_N/option/Depth Units/value",
//                  std_msgs/Float32 in metres per unit: unit_mm = 1000 * value); > 65535 mm -> 0.
//   32FC1:         metres; depth_mm = round(1000 * m) (nearest millimetre, so a 16UC1 frame written as
//                  float32 metres reads back exactly); NaN, inf, <= 0 and >= 65.5355 m -> 0 (no reading).
// Compressed: a sensor_msgs/CompressedImage topic (image_transport's "compressedDepth" and "compressed",
// as robots record them) is an image topic of the encoding its format names (frame/compressed_image.hpp:
// "16UC1; compressedDepth png" is 16UC1 depth, "rgb8; jpeg compressed bgr8" colour), decoded message by
// message; its camera_info is its image topic's (TOPIC without its last part). Where a bag holds both, the raw
// image topic is chosen over its compressed twin (TOPIC/compressedDepth, TOPIC/compressed): the same images.
// Colour: sensor_msgs/Image rgb8 or bgr8 of FrameSourceOptions::colour_topic ("none": no colour; empty:
// the bag's only rgb8/bgr8 topic of the depth's size, when there is exactly one). Each depth frame gets
// the colour frame whose header stamp is nearest to its own, when that is at most
// FrameSourceOptions::colour_gap_ms away
// (else no colour); DepthFrame::colour_gap_us = |colour stamp - depth stamp|, summary() their mean and
// maximum. A colour image must be of the depth's size (registered pixel for pixel).
// Camera model: the first sensor_msgs/CameraInfo of the depth topic's camera (TOPIC's folder +
// "/camera_info", as ROS drivers publish it, or the RealSense layout's ".../Depth_0/info/camera_info"; when
// neither is in the bag, the one CameraInfo topic in the depth images' optical frame, i.e. with their
// header.frame_id and size: depth registered to a colour camera has that camera's intrinsics, and a robot's
// recorder may keep only its CameraInfo): fx = K[0], cx = K[2], fy = K[4], cy = K[5]. A given model
// (FrameSourceOptions::camera_given) wins; without a CameraInfo (or with K all zero) frames carry the
// fallback model, and description() says so once.
// Bad input (not a bag, truncated or unindexed, no such topic, wrong encoding, a message shorter than its
// step * height, a frame of another size) throws Error: one line naming the file, the topic and the problem.
// The record lengths are checked first (bag_layout_problem(), frame/bag_layout.hpp), so a damaged length
// is refused before librosbag reserves what it says.
#include <cstdint>
#include <memory>
#include <string>

#include "rdsf/frame/frame_source.hpp"

namespace rdsf {

class BagSource : public FrameSource {
 public:
  /// Opens `path` and chooses its topics; throws Error (file, topic, problem) when it cannot.
  BagSource(const std::string& path, const FrameSourceOptions& options);
  ~BagSource() override;
  BagSource(const BagSource&) = delete;
  BagSource& operator=(const BagSource&) = delete;

  bool next(DepthFrame& frame) override;
  /// The messages read and paired in order; their images decoded by `decode` (any thread).
  bool next_deferred(FrameDecode& decode) override;
  /// "bag F.bag: depth /camera/depth/image_raw (16UC1, 46 frames), colour /camera/rgb/image_raw (rgb8),
  /// camera model from /camera/depth/camera_info (640x480 fx=525 ...)".
  std::string description() const override;
  std::optional<std::int64_t> frame_count() const override;
  std::optional<std::vector<std::string>> frame_names() const override;  ///< index_frame_names(frame_count())
  /// "colour paired with 14 of 46 depth frames, gap mean 0 ms, max 0 ms" (empty without a colour topic), and
  /// "; N depth frame(s) had colour only beyond --colour-gap-ms G (the nearest X ms away)" when some had.
  std::string summary() const override;

  const std::string& depth_topic() const;
  const CameraModel& camera() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rdsf
