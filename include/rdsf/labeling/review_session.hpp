#pragma once
// The review of a sample set, without any window: its samples in force in one order (most suspicious first
// under a model, by origin, or by source), paged as a grid, with a selected sample that can be flipped
// (its label corrected) or retracted. Every change is on disk before the call returns:
//   flip     the corrected sample is appended (same crops, source, frame and boxes; origin "review"; the
//            model and score of the review when there is a model), then the original is retracted (reason
//            "review: flipped, now sample N"), then the change is journalled;
//   retract  the sample is retracted (reason "review"), then journalled.
// The journal review-changes.tsv in the set's folder (time, change, sample_id, new_id, model) is appended
// last: a review killed between the append and the retraction of a flip is finished when the set is next
// reviewed (a review sample missing from the journal: its original, the sample in force at the same place
// with the other label, is retracted then). The set's lock (SampleSetWriter) is held for the session's
// lifetime: a set another program writes is refused.
//
// Suspicion (with a model, or out of fold) of a sample: 1 - P(person) for a person, P(person) for a not-person
// (active_learning.hpp); ties in id order. Origin order: origin, then id; source order: source, frame, id.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/pipeline/model_scorer.hpp"

namespace rdsf {

enum class ReviewOrder { suspicion, origin, source };

/// "suspicion", "origin" or "source"; throws Error naming the known ones otherwise.
ReviewOrder parse_review_order(const std::string& text);

struct ReviewConfig {
  ReviewOrder order = ReviewOrder::suspicion;  ///< suspicion needs a model
  int columns = 6, rows = 2;                   ///< samples per page = columns x rows
  /// Without a model: P(person) of each sample out of fold (active_learning.hpp): `folds` models trained
  /// in-process on the set's other groups; 0 = off. Suspicion order needs a model or folds.
  int folds = 0;
};

struct ReviewItem {
  SampleRecord record;                 ///< as in force now (after a flip: the corrected sample)
  cv::Mat1w depth_crop;
  std::optional<double> probability;   ///< P(person) under the review's model
  double suspicion = 0;                ///< with a model; 0 otherwise
  enum class State { kept, flipped, retracted } state = State::kept;
};

struct ReviewStats {
  long flips = 0, retractions = 0;
  long finished_flips = 0;  ///< interrupted flips finished when the set was opened
};

class ReviewSession {
 public:
  /// Opens the set in `dir` for writing (refused while another program writes it) and sorts its samples.
  /// `model` (may be null) must read the set's feature spec and outlive the session; suspicion order
  /// needs one. Throws Error naming the set or the model.
  ReviewSession(const std::string& dir, const BoostedModel* model, ReviewConfig config);

  const std::vector<ReviewItem>& items() const { return items_; }
  std::size_t selected() const { return selected_; }
  std::size_t page() const { return selected_ / per_page(); }
  std::size_t pages() const { return items_.empty() ? 0 : (items_.size() + per_page() - 1) / per_page(); }
  std::size_t per_page() const { return static_cast<std::size_t>(config_.columns * config_.rows); }
  const ReviewConfig& config() const { return config_; }
  const ReviewStats& stats() const { return stats_; }
  const std::vector<std::string>& repairs() const { return writer_.repairs(); }
  const BoostedModel* model() const { return model_; }

  /// Moves the selection by `delta` samples (clamped to the set).
  void move(long delta);
  /// Moves to the first sample of the next (+1) or previous (-1) page.
  void turn_page(int direction);
  /// Flips the selected sample's label (see above); false when it is retracted.
  bool flip();
  /// Retracts the selected sample; false when it is retracted already.
  bool retract();
  /// The colour crop of item `i` (empty without one).
  cv::Mat3b colour_crop(std::size_t i) const;
  /// The frame item `i` came from, read from its source (nullopt when the source or frame is gone).
  std::optional<DepthFrame> frame_of(std::size_t i) const;

 private:
  void journal(const std::string& change, std::int64_t id, std::int64_t new_id);
  void finish_interrupted_flips();
  SampleSetWriter writer_;
  SampleSet reader_;  ///< crops of the samples in force at opening
  const BoostedModel* model_;
  std::optional<ModelScorer> scorer_;
  ReviewConfig config_;
  std::string journal_path_;
  std::vector<ReviewItem> items_;
  std::vector<std::optional<std::size_t>> reader_index_;  ///< per item: its record in reader_ (crops)
  std::vector<cv::Mat3b> colour_copies_;                   ///< colour crops of flipped items
  std::size_t selected_ = 0;
  ReviewStats stats_;
};

}  // namespace rdsf
