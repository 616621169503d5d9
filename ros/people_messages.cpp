#include "ros/people_messages.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rdsf {

rdsf_people::People people_message(const std_msgs::Header& header, const std::vector<Detection>& people,
                                   std::size_t candidates) {
  rdsf_people::People message;
  message.header = header;
  message.candidates = static_cast<std::uint32_t>(candidates);
  for (const Detection& d : people) {
    rdsf_people::Person p;
    p.track_id = d.track_id;
    p.probability = d.probability;
    p.score = d.score;
    p.box.x_offset = static_cast<std::uint32_t>(d.box.x);
    p.box.y_offset = static_cast<std::uint32_t>(d.box.y);
    p.box.width = static_cast<std::uint32_t>(d.box.width);
    p.box.height = static_cast<std::uint32_t>(d.box.height);
    p.box.do_rectify = false;
    p.position_m.x = d.position_m.x;
    p.position_m.y = d.position_m.y;
    p.position_m.z = d.position_m.z;
    p.distance_walked_m = d.distance_walked_m;
    message.people.push_back(p);
  }
  return message;
}

visualization_msgs::MarkerArray people_markers(const rdsf_people::People& people, const CameraModel& camera) {
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker clear;
  clear.header = people.header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  markers.markers.push_back(clear);
  for (const rdsf_people::Person& p : people.people) {
    const double z = p.position_m.z;
    visualization_msgs::Marker box;
    box.header = people.header;
    box.ns = "people";
    box.id = p.track_id;
    box.type = visualization_msgs::Marker::CUBE;
    box.action = visualization_msgs::Marker::ADD;
    box.pose.position = p.position_m;
    box.pose.orientation.w = 1.0;
    box.scale.x = p.box.width * z / camera.fx_px;   // optical frame: x right
    box.scale.y = p.box.height * z / camera.fy_px;  // y down
    box.scale.z = 0.3;                              // z along the optical axis
    // A colour per track id (hue steps of the golden angle), half transparent.
    const double hue = static_cast<double>((p.track_id * 137) % 360);
    auto channel = [hue](double shift) {
      const double h = std::fmod(hue / 60.0 + shift, 6.0);
      return static_cast<float>(std::clamp(std::abs(h - 3.0) - 1.0, 0.0, 1.0));
    };
    box.color.r = channel(0.0);
    box.color.g = channel(4.0);
    box.color.b = channel(2.0);
    box.color.a = 0.5F;
    markers.markers.push_back(box);

    visualization_msgs::Marker label = box;
    label.ns = "labels";
    label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    label.pose.position.y -= box.scale.y / 2 + 0.15;  // above the head (y points down)
    label.scale.x = label.scale.y = 0;
    label.scale.z = 0.15;  // text height, metres
    label.color.a = 1.0F;
    char text[48];
    std::snprintf(text, sizeof text, "#%d P=%.2f", p.track_id, p.probability);
    label.text = text;
    markers.markers.push_back(label);
  }
  return markers;
}

}  // namespace rdsf
