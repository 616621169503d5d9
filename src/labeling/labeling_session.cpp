#include "rdsf/labeling/labeling_session.hpp"

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <unordered_set>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

// Samples and answers name their source so that a rerun from another folder still matches: files and
// folders by their absolute path, devices as given.
std::string canonical_source(const std::string& spec) {
  if (is_openni_spec(spec) && spec.find("://") != std::string::npos) return spec;
  if (spec == "openni") return spec;
  std::error_code ec;
  const auto path = std::filesystem::weakly_canonical(spec, ec);
  return ec ? spec : path.string();
}

}  // namespace

CandidateKey PresentedCandidate::key() const { return {frame->source, frame->frame.name, candidate().strict_box}; }

LabelingSession::LabelingSession(LabelingConfig config, SampleSetWriter& writer, const BoostedModel* model,
                                 const GroundTruth* truth)
    : config_(std::move(config)),
      writer_(writer),
      model_(model),
      truth_(truth),
      core_(config_.detector),
      journal_((std::filesystem::path(writer.dir()) / "labeler-answers.tsv").string()) {
  if (config_.sources.empty()) throw Error("no --source given");
  std::unordered_set<std::int64_t> ids;  // an undo cut short by a failed write or a power cut is finished
  for (const SampleRecord& r : writer_.records()) ids.insert(r.id);
  journal_.finish_interrupted_undos([&ids](std::int64_t id) { return ids.count(id) != 0; });
  if (model_ != nullptr) scorer_.emplace(*model_);
  // Open every source now, so that a bad one is reported before the first question.
  std::int64_t total = 0;
  bool known = true;
  for (const std::string& spec : config_.sources) {
    auto probe = open_frame_source(spec, config_.camera);
    if (probe->frame_count()) {
      total += *probe->frame_count();
    } else {
      known = false;
    }
  }
  if (known) total_frames_ = total;
  start_prefetch();
}

LabelingSession::~LabelingSession() {
  if (prefetch_.valid()) prefetch_.wait();
}

std::shared_ptr<LoadedFrame> LabelingSession::load_next() {
  while (true) {
    if (!source_) {
      if (source_index_ >= config_.sources.size()) return nullptr;
      source_name_ = canonical_source(config_.sources[source_index_]);
      source_ = open_frame_source(config_.sources[source_index_], config_.camera);
    }
    auto loaded = std::make_shared<LoadedFrame>();
    if (!source_->next(loaded->frame)) {
      source_.reset();
      ++source_index_;
      continue;
    }
    loaded->source = source_name_;
    loaded->ordinal = ++ordinal_;
    loaded->analysis = core_.analyse(loaded->frame, /*with_features=*/false);
    if (scorer_) loaded->scores = scorer_->score(loaded->analysis.candidates);
    if (truth_ != nullptr) {
      for (const Candidate& c : loaded->analysis.candidates) {
        double best = 0, ignored = 0;
        for (const TruthBox& person : truth_->in(loaded->frame.name)) {
          double& to = person.ignored ? ignored : best;
          to = std::max(to, iou(reported_box(c, config_.detector.reported_box), person.box));
        }
        loaded->truth_iou.push_back(best);
        loaded->ignored_iou.push_back(ignored);
      }
    }
    return loaded;
  }
}

void LabelingSession::start_prefetch() {
  prefetch_ = std::async(std::launch::async, [this] { return load_next(); });
}

void LabelingSession::take_frame(std::shared_ptr<const LoadedFrame> frame) {
  ++stats_.frames_loaded;
  std::vector<std::size_t> order(frame->analysis.candidates.size());
  std::iota(order.begin(), order.end(), 0);
  if (config_.order_by_score && !frame->scores.empty()) {
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return frame->scores[a] > frame->scores[b]; });
  }
  for (std::size_t i : order) {
    const PresentedCandidate p{frame, i};
    const CandidateKey key = p.key();
    if (journal_.answered(key)) {
      ++stats_.already_answered;
      continue;
    }
    if (!frame->truth_iou.empty()) {
      const double overlap = frame->truth_iou[i];
      if (overlap >= config_.certain_iou) {
        journal_.record({key, 'y', store(p, 1), "truth"});
        ++stats_.auto_positives;
        continue;
      }
      if (overlap < config_.uncertain_iou && frame->ignored_iou[i] < config_.uncertain_iou) {
        journal_.record({key, 'n', config_.keep_rejected ? store(p, 0) : -1, "truth"});
        ++stats_.auto_negatives;
        continue;
      }
    }
    queue_.push_back(p);
  }
}

const PresentedCandidate* LabelingSession::current() {
  while (queue_.empty()) {
    if (sources_done_) return nullptr;
    std::shared_ptr<LoadedFrame> next = prefetch_.get();  // rethrows a source's error here
    if (!next) {
      sources_done_ = true;
      return nullptr;
    }
    start_prefetch();  // the frame after this one is read while the person decides
    take_frame(next);
  }
  return &queue_.front();
}

std::int64_t LabelingSession::store(const PresentedCandidate& p, int label) {
  const Candidate& c = p.candidate();
  SampleRecord record;
  record.label = label;
  record.origin = "labeler";
  record.source = p.frame->source;
  record.frame = p.frame->frame.name;
  record.strict_box = c.strict_box;
  record.window = c.window;
  record.layer_depth_mm = c.layer_depth_mm;
  if (model_ != nullptr) {
    record.model = model_->name() + "/v" + std::to_string(model_->version());
    record.score = p.frame->scores[p.index];
  }
  // Saved before but its journal line was lost (disk full, power cut between the two): not stored twice.
  if (const std::int64_t saved = writer_.id_at_place(record); saved >= 0) return saved;
  return writer_.append(record, c.depth_crop, c.colour_crop).id;
}

bool LabelingSession::answer(char key) {
  if (key == 'u') {
    if (history_.empty()) return false;
    Given last = history_.back();
    history_.pop_back();
    if (last.entry.sample_id >= 0) writer_.retract(last.entry.sample_id);
    journal_.record_undo(last.entry);
    switch (last.entry.answer) {
      case 'y': --stats_.positives; break;
      case 'n': --stats_.negatives; stats_.rejected -= last.entry.sample_id >= 0 ? 1 : 0; break;
      default: --stats_.skipped; break;
    }
    ++stats_.undone;
    queue_.push_front(last.presented);
    return true;
  }
  if (queue_.empty()) return false;
  const PresentedCandidate p = queue_.front();
  std::int64_t id = -1;
  switch (key) {
    case 'y':
      id = store(p, 1);
      ++stats_.positives;
      break;
    case 'n':
      if (config_.keep_rejected) {
        id = store(p, 0);
        ++stats_.rejected;
      }
      ++stats_.negatives;
      break;
    case 's': ++stats_.skipped; break;
    default: return false;
  }
  const JournalEntry entry{p.key(), key, id, "human"};
  journal_.record(entry);
  history_.push_back({p, entry});
  queue_.pop_front();
  return true;
}

void LabelingSession::leave_unanswered() {
  if (queue_.empty()) return;
  queue_.pop_front();
  ++stats_.unanswered;
}

}  // namespace rdsf
