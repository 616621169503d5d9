#pragma once
// What the node publishes for one frame: its people as rdsf_people/People (msg/People.msg) and as
// visualization_msgs/MarkerArray for rviz, both with the depth image's header.
#include <vector>

#include <rdsf_people/People.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "rdsf/pipeline/people_detector.hpp"

namespace rdsf {

/// The People message of a frame: `header` is the depth image's, one Person per detection (same order).
rdsf_people::People people_message(const std_msgs::Header& header, const std::vector<Detection>& people,
                                   std::size_t candidates);

/// Markers of a frame, in the depth image's optical frame: first a DELETEALL (people who left disappear),
/// then per person a box (namespace "people", id = track id) at position_m, as wide and tall as the
/// person's box at its depth (width_px z / fx by height_px z / fy, 0.3 m deep), coloured by track id, and
/// a text above it (namespace "labels": "#id P=0.87").
visualization_msgs::MarkerArray people_markers(const rdsf_people::People& people, const CameraModel& camera);

}  // namespace rdsf
