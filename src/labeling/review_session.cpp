#include "rdsf/labeling/review_session.hpp"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <tuple>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/append_only_log.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/utc_time.hpp"
#include "rdsf/features/rdsf_extractor.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/labeling/active_learning.hpp"
#include "rdsf/pipeline/model_scorer.hpp"

namespace rdsf {
namespace {

const char* kJournalHeader = "time\tchange\tsample_id\tnew_id\tmodel";
const char* kReviewOrigin = "review";


}  // namespace

ReviewOrder parse_review_order(const std::string& text) {
  if (text == "suspicion") return ReviewOrder::suspicion;
  if (text == "origin") return ReviewOrder::origin;
  if (text == "source") return ReviewOrder::source;
  throw Error("unknown review order '" + text + "' (known: suspicion, origin, source)");
}

ReviewSession::ReviewSession(const std::string& dir, const BoostedModel* model, ReviewConfig config)
    : writer_(SampleSetWriter::open_existing(dir)),
      reader_(SampleSet::open_read(dir)),
      model_(model),
      config_(config),
      journal_path_((std::filesystem::path(dir) / "review-changes.tsv").string()) {
  if (config_.columns < 1 || config_.rows < 1) throw Error("the review grid needs at least one column and row");
  if (model_ != nullptr && !(model_->feature_spec() == writer_.manifest().feature_spec)) {
    throw Error(model_->path() + ": the model reads feature spec " + model_->feature_spec().hash() +
                ", the sample set " + dir + " holds " + writer_.manifest().feature_spec.hash());
  }
  if (config_.order == ReviewOrder::suspicion && model_ == nullptr && config_.folds < 2) {
    throw Error("most suspicious first needs a model (--model) or --folds, or sort by origin or source");
  }
  finish_interrupted_flips();
  if (stats_.finished_flips > 0) reader_ = SampleSet::open_read(dir);  // the finished retractions
  if (model_ != nullptr) scorer_.emplace(*model_);
  const std::vector<SampleRecord>& records = reader_.records();
  std::vector<double> out_of_fold;  // per reader record, when folds are asked for without a model
  if (model_ == nullptr && config_.folds >= 2) {
    std::vector<std::size_t> with_crop;
    std::vector<int> labels;
    std::vector<SampleOrigin> origins;
    for (std::size_t i = 0; i < records.size(); ++i) {
      if (!records[i].has_crop) continue;
      with_crop.push_back(i);
      labels.push_back(records[i].label);
      origins.push_back({records[i].source, records[i].frame});
    }
    const cv::Mat1f rows = reader_.features(RdsfExtractor(reader_.feature_spec()), with_crop);
    const std::vector<double> p =
        out_of_fold_probabilities(rows, labels, origins, reader_.feature_spec(), LoopTrainingParams{}, config_.folds);
    out_of_fold.assign(records.size(), 0.5);
    for (std::size_t k = 0; k < with_crop.size(); ++k) out_of_fold[with_crop[k]] = p[k];
  }
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (!records[i].has_crop) continue;  // imported vectors: nothing to look at
    ReviewItem item;
    item.record = records[i];
    item.depth_crop = reader_.depth_crop(i);
    if (scorer_) item.probability = model_->probability(scorer_->score(item.depth_crop));
    if (!out_of_fold.empty()) item.probability = out_of_fold[i];
    if (item.probability) item.suspicion = suspicion(item.record.label, *item.probability);
    items_.push_back(std::move(item));
    reader_index_.push_back(i);
  }
  std::vector<std::size_t> order(items_.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto key = [&](std::size_t i) { return items_[i].record.id; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const SampleRecord &ra = items_[a].record, &rb = items_[b].record;
    switch (config_.order) {
      case ReviewOrder::suspicion:
        if (items_[a].suspicion != items_[b].suspicion) return items_[a].suspicion > items_[b].suspicion;
        break;
      case ReviewOrder::origin:
        if (ra.origin != rb.origin) return ra.origin < rb.origin;
        break;
      case ReviewOrder::source:
        if (std::tie(ra.source, ra.frame) != std::tie(rb.source, rb.frame)) {
          return std::tie(ra.source, ra.frame) < std::tie(rb.source, rb.frame);
        }
        break;
    }
    return key(a) < key(b);
  });
  std::vector<ReviewItem> sorted;
  std::vector<std::optional<std::size_t>> index;
  for (std::size_t i : order) {
    sorted.push_back(std::move(items_[i]));
    index.push_back(reader_index_[i]);
  }
  items_ = std::move(sorted);
  reader_index_ = std::move(index);
  colour_copies_.resize(items_.size());
}

void ReviewSession::finish_interrupted_flips() {
  std::error_code ec;
  std::set<std::int64_t> journalled;
  if (!std::filesystem::exists(journal_path_, ec)) {
    append_line_synced(journal_path_, kJournalHeader);
  } else {
    const LogLines read = read_log_lines(journal_path_);
    for (std::size_t i = 0; i < read.lines.size(); ++i) {
      if (i == 0) {
        if (read.lines[0] != kJournalHeader) fail(journal_path_, "line 1: not a review journal");
        continue;
      }
      std::stringstream row(read.lines[i]);
      std::string time, change, id, new_id;
      if (!std::getline(row, time, '\t') || !std::getline(row, change, '\t') || !std::getline(row, id, '\t') ||
          !std::getline(row, new_id, '\t')) {
        fail(journal_path_, "line " + std::to_string(i + 1) + ": malformed review row");
      }
      if (change == "flip") journalled.insert(std::stoll(new_id));
    }
    if (read.torn_tail) {
      cut_torn_tail(journal_path_, read.complete_bytes);
      if (read.lines.empty()) append_line_synced(journal_path_, kJournalHeader);
    }
  }
  const std::vector<SampleRecord> records = writer_.records();
  for (const SampleRecord& r : records) {
    if (r.origin != kReviewOrigin || journalled.count(r.id) != 0) continue;
    SampleRecord original = r;
    original.label = 1 - r.label;
    const std::int64_t old_id = writer_.id_at_place(original);
    if (old_id >= 0) writer_.retract(old_id, "review: flipped, now sample " + std::to_string(r.id));
    journal("flip", old_id, r.id);
    ++stats_.finished_flips;
  }
}

void ReviewSession::journal(const std::string& change, std::int64_t id, std::int64_t new_id) {
  append_line_synced(journal_path_, utc_now_iso8601() + "\t" + change + "\t" + std::to_string(id) + "\t" +
                                        std::to_string(new_id) + "\t" + (model_ ? model_reference(*model_) : ""));
}

void ReviewSession::move(long delta) {
  if (items_.empty()) return;
  const long target = static_cast<long>(selected_) + delta;
  selected_ = static_cast<std::size_t>(std::clamp(target, 0L, static_cast<long>(items_.size()) - 1));
}

void ReviewSession::turn_page(int direction) {
  if (items_.empty()) return;
  const long p = static_cast<long>(page()) + direction;
  const long last = static_cast<long>(pages()) - 1;
  selected_ = static_cast<std::size_t>(std::clamp(p, 0L, last)) * per_page();
}

cv::Mat3b ReviewSession::colour_crop(std::size_t i) const {
  if (!colour_copies_[i].empty()) return colour_copies_[i];
  if (!reader_index_[i] || !items_[i].record.has_colour) return {};
  return reader_.colour_crop(*reader_index_[i]);
}

bool ReviewSession::flip() {
  if (items_.empty()) return false;
  ReviewItem& item = items_[selected_];
  if (item.state == ReviewItem::State::retracted) return false;
  SampleRecord corrected = item.record;
  corrected.label = 1 - item.record.label;
  corrected.origin = kReviewOrigin;
  corrected.time.clear();
  corrected.model.clear();
  corrected.score.reset();
  if (scorer_) {
    corrected.model = model_reference(*model_);
    corrected.score = scorer_->score(item.depth_crop);
  }
  const cv::Mat3b colour = colour_crop(selected_);
  const SampleRecord stored = writer_.append(corrected, item.depth_crop, colour);
  writer_.retract(item.record.id, "review: flipped, now sample " + std::to_string(stored.id));
  journal("flip", item.record.id, stored.id);
  item.record = stored;
  item.state = item.state == ReviewItem::State::flipped ? ReviewItem::State::kept : ReviewItem::State::flipped;
  if (item.probability) item.suspicion = suspicion(stored.label, *item.probability);
  colour_copies_[selected_] = colour;
  ++stats_.flips;
  return true;
}

bool ReviewSession::retract() {
  if (items_.empty()) return false;
  ReviewItem& item = items_[selected_];
  if (item.state == ReviewItem::State::retracted) return false;
  writer_.retract(item.record.id, "review");
  journal("retract", item.record.id, -1);
  item.state = ReviewItem::State::retracted;
  ++stats_.retractions;
  return true;
}

std::optional<DepthFrame> ReviewSession::frame_of(std::size_t i) const {
  const SampleRecord& r = items_[i].record;
  std::unique_ptr<FrameSource> source;
  try {
    source = open_frame_source(r.source, writer_.manifest().camera);
  } catch (const Error&) {
    return std::nullopt;
  }
  DepthFrame frame;
  while (source->next(frame)) {
    if (frame.name == r.frame) return frame;
  }
  return std::nullopt;
}

}  // namespace rdsf
