#pragma once
// Ground truth boxes from a boxes.csv: a header line naming the columns, then one person per line.
// Required columns: frame, person, x, y, w, h (pixels, the tight box around the person's visible pixels).
// Optional: visible_fraction (0..1), track (the identity across frames; defaults to person).
// This is the layout of ../shared/realdata/people/boxes.csv and of rdsf-synth's output.
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct TruthBox {
  cv::Rect box;
  int person = 0;
  int track = 0;
  double visible_fraction = 1.0;
  /// "Don't care": too little of the person is visible to demand a detection. An ignored person is no
  /// miss when not found, and a detection of them is no false positive (see ignore_hardly_visible()).
  bool ignored = false;
};

struct GroundTruth {
  std::map<std::string, std::vector<TruthBox>> frames;  ///< frame name -> people in it
  std::size_t people() const;
  const std::vector<TruthBox>& in(const std::string& frame) const;
};

/// How much a box overlaps the people of a frame: the best IoU with a counted person and with an ignored
/// ("don't care") one, 0 where there is none. Labelling by overlap reads both (a candidate is a person at
/// counted >= 0.5, not one when both are below the uncertain band).
struct TruthOverlap {
  double counted = 0;
  double ignored = 0;
};
TruthOverlap truth_overlap(const cv::Rect& box, const std::vector<TruthBox>& people);

/// Marks people whose visible_fraction is below `min_visible_fraction` as ignored; returns how many.
std::size_t ignore_hardly_visible(GroundTruth& truth, double min_visible_fraction);

/// How a truth's frame names meet the names of a source's frames (FrameSource::frame_names): throws Error
/// naming `truth_path`, with an example of each naming, when the truth names frames and none of them is among
/// `names` (a folder's file stems against a bag's indices: every frame would count as one without people);
/// else returns how many of the truth's frames are not among them.
std::size_t truth_frames_not_in(const GroundTruth& truth, const std::string& truth_path,
                                const std::vector<std::string>& names, const std::string& source);

/// Reads and checks a boxes.csv; throws Error naming the file and the first bad line.
GroundTruth read_ground_truth(const std::string& path);
/// The same from text (for tests and fuzzing); `name` is used in messages.
GroundTruth parse_ground_truth(const std::string& text, const std::string& name);

}  // namespace rdsf
