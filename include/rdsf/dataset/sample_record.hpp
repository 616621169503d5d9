#pragma once
// One sample of a sample set: one row of its append-only index samples.tsv (see datasets/README.md for the
// exact columns). Boxes are in pixels of the frame the sample came from; times are ISO 8601 UTC.
#include <cstdint>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "rdsf/core/utc_time.hpp"  // utc_now_iso8601(), the time samples record

namespace rdsf {

struct SampleRecord {
  std::int64_t id = 0;
  int label = 0;                ///< 1 person, 0 not
  std::string origin;           ///< "labeler", "miner", "import"
  std::string source;           ///< recording / folder the frame came from
  std::string frame;            ///< frame name
  cv::Rect strict_box, window;  ///< pixels
  double layer_depth_mm = 0;
  std::string model;            ///< model used (empty if none)
  std::optional<double> score;  ///< its score
  std::string time;             ///< ISO 8601 UTC, "2026-11-22T05:30:00Z"
  bool has_crop = true;         ///< false for imported thesis-text samples (their feature vector is stored)
  // Members beyond the shared contract:
  bool has_colour = false;      ///< a colour crop crops/NNNNNNNN.rgb.png exists
  std::string crop_hash;        ///< 16 hex digits: stable hash of the depth crop's values (empty without crop)
};


}  // namespace rdsf
