#pragma once
// Why a person has no candidate: the shape of the candidate box that overlaps them most, against theirs.
// A person has a candidate when some candidate's box reaches IoU >= 0.5 with theirs (the evaluation's
// match); the classifier never sees one without. For such a person (box p), the best candidate's box b
// (the highest IoU with p, which is below 0.5) is, tested in this order:
//   none      IoU(b, p) < 0.1 or no candidate at all: nothing of the person became an object
//   wide      b.width  > 1.4 p.width:  joined with something beside them (a chair, a wall, another person)
//   narrow    b.width  < 0.7 p.width:  a piece of them (legs, a torso) or an arm or stride the box misses
//   tall      b.height > 1.3 p.height: joined with something above or below them
//   short     b.height < 0.75 p.height
//   shifted   otherwise: about their size, in the wrong place
// The counts are a diagnosis of the candidate stage (docs/candidates.md, "Where the remaining misses
// are"), not a figure of quality.
#include <array>
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

namespace rdsf {

enum class MissShape { none, wide, narrow, tall, short_box, shifted };
constexpr int kMissShapes = 6;

/// The shape of a miss: `best` is the candidate box with the highest IoU `best_iou` with `person` (any box
/// when best_iou is 0). best_iou must be below 0.5 (else Error).
MissShape miss_shape(const cv::Rect& person, const cv::Rect& best, double best_iou);

/// "none", "wide", "narrow", "tall", "short", "shifted".
const char* miss_shape_name(MissShape shape);

/// Counts per shape, in MissShape's order.
struct MissShapes {
  std::array<std::int64_t, kMissShapes> count{};
  void add(MissShape shape) { ++count[static_cast<std::size_t>(shape)]; }
  std::int64_t total() const;
  /// "11 narrow, 4 wide": the shapes that occur, most first (ties in MissShape's order); "" when none.
  std::string summary() const;
};

}  // namespace rdsf
