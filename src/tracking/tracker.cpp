#include "rdsf/tracking/tracker.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace rdsf {
namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

cv::Point3d centroid_cm(const cv::Rect& box, double depth_mm, const CameraModel& camera) {
  const double u = box.x + box.width / 2.0;
  const double v = box.y + box.height / 2.0;
  const double z_cm = depth_mm / 10.0;
  return {(u - camera.cx_px) * z_cm / camera.fx_px, (v - camera.cy_px) * z_cm / camera.fy_px, z_cm};
}

double match_lkh(const ColourHistogram& a, const ColourHistogram& b, double distance_cm) {
  const double distance_term = distance_cm / 98.0 - 1.0 / 49.0;
  if (a.empty() || b.empty()) return distance_term;
  return bhattacharyya_distance(a, b) + distance_term;
}

Tracker::Tracker(TrackingParams params, std::uint64_t colour_seed) : params_(params), colour_state_(colour_seed) {}

const TrackedPerson* Tracker::person(int id) const {
  for (const TrackedPerson& p : people_) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

std::vector<int> Tracker::update(const std::vector<TrackInput>& detections, const CameraModel& camera,
                                 std::int64_t frame_index) {
  std::vector<cv::Point3d> centroids;
  for (const TrackInput& d : detections) centroids.push_back(centroid_cm(d.box, d.depth_mm, camera));

  // Every (lkh, detection, person) pair under the threshold, smallest lkh first.
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t p = 0; p < people_.size(); ++p) {
    const TrackedPerson& person = people_[p];
    if (params_.max_missed_frames > 0 && frame_index - person.last_frame > params_.max_missed_frames) continue;
    for (std::size_t d = 0; d < detections.size(); ++d) {
      const double lkh = match_lkh(detections[d].histogram, person.histogram,
                                   cv::norm(centroids[d] - person.centroid_cm));
      if (lkh <= params_.threshold_lkh) pairs.emplace_back(lkh, d, p);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> ids(detections.size(), 0);
  std::vector<bool> person_taken(people_.size(), false);
  for (const auto& [lkh, d, p] : pairs) {
    if (ids[d] != 0 || person_taken[p]) continue;
    TrackedPerson& person = people_[p];
    person_taken[p] = true;
    ids[d] = person.id;
    person.previous_cm = person.centroid_cm;
    person.centroid_cm = centroids[d];
    person.distance_cm += cv::norm(person.centroid_cm - person.previous_cm);
    if (!detections[d].histogram.empty()) person.histogram = detections[d].histogram;
    person.last_frame = frame_index;
    person.box = detections[d].box;
  }
  for (std::size_t d = 0; d < detections.size(); ++d) {
    if (ids[d] != 0) continue;
    TrackedPerson person;
    person.id = static_cast<int>(people_.size()) + 1;
    person.histogram = detections[d].histogram;
    person.centroid_cm = person.previous_cm = centroids[d];
    const std::uint64_t random = splitmix64(colour_state_);
    person.colour = cv::Scalar(64 + random % 192, 64 + (random >> 8) % 192, 64 + (random >> 16) % 192);
    person.last_frame = frame_index;
    person.box = detections[d].box;
    ids[d] = person.id;
    people_.push_back(std::move(person));
  }
  return ids;
}

}  // namespace rdsf
