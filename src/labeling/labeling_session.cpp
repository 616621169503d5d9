#include "rdsf/labeling/labeling_session.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <filesystem>
#include <numeric>
#include <set>
#include <unordered_set>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/classifier/seeded_sampling.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/ordered_pool.hpp"
#include "rdsf/dataset/sample_source.hpp"
#include "rdsf/labeling/active_learning.hpp"
#include "rdsf/pipeline/model_fit.hpp"

namespace rdsf {
namespace {

// "model tree2/v3 H=0.532 P=0.981": who answered, journalled with the answer.
std::string model_answerer(const BoostedModel& model, double score, double probability) {
  char text[96];
  std::snprintf(text, sizeof text, " H=%.4f P=%.4f", score, probability);
  return "model " + model_reference(model) + text;
}

}  // namespace

AskOrder parse_ask_order(const std::string& text) {
  if (text == "order") return AskOrder::in_order;
  if (text == "uncertain") return AskOrder::uncertain;
  if (text == "likely") return AskOrder::likely;
  throw Error("unknown ask order '" + text + "' (known: order, uncertain, likely)");
}

CandidateKey PresentedCandidate::key() const { return {frame->source, frame->frame.name, candidate().strict_box}; }

LabelingSession::LabelingSession(LabelingConfig config, SampleSetWriter& writer, const BoostedModel* model,
                                 const GroundTruth* truth, ScoringProgress progress)
    : config_(std::move(config)),
      writer_(writer),
      model_(model),
      progress_(std::move(progress)),
      truth_(truth),
      analyser_(config_.analyser),
      journal_((std::filesystem::path(writer.dir()) / "labeler-answers.tsv").string()) {
  if (config_.sources.empty()) throw Error("no --source given");
  if (!(config_.reject_probability >= 0 && config_.reject_probability <= config_.accept_probability &&
        config_.accept_probability <= 1)) {
    throw Error("--accept " + std::to_string(config_.accept_probability) + " must be at least --reject " +
                std::to_string(config_.reject_probability) + ", both in [0, 1]");
  }
  if (config_.per_track && !reads_whole_session(config_.ask)) {
    throw Error("one answer per track needs the uncertain or likely ask order (the whole session read first)");
  }
  if (config_.only_added_beyond) beyond_.emplace(*config_.only_added_beyond);
  if (model_ != nullptr && !(model_->feature_spec() == writer_.manifest().feature_spec)) {
    throw Error(model_->path() + ": the model reads feature spec " + model_->feature_spec().hash() +
                ", the sample set " + writer_.dir() + " holds " + writer_.manifest().feature_spec.hash() +
                ": use a model trained on this set's features");
  }
  std::unordered_set<std::int64_t> ids;  // an undo cut short by a failed write or a power cut is finished
  for (const SampleRecord& r : writer_.records()) ids.insert(r.id);
  journal_.finish_interrupted_undos([&ids](std::int64_t id) { return ids.count(id) != 0; });
  if (model_ != nullptr) {
    check_model_fits(*model_, config_.analyser);  // the same crops as the detector cuts (model_fit.hpp)
    scorer_.emplace(*model_);
  }
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
  std::shared_ptr<LoadedFrame> loaded = read_next();
  if (loaded) analyse_loaded(*loaded);
  return loaded;
}

std::shared_ptr<LoadedFrame> LabelingSession::read_next() {
  while (true) {
    if (!source_) {
      if (source_index_ >= config_.sources.size()) return nullptr;
      source_name_ = sample_source(config_.sources[source_index_]);  // the one rule (sample_source.hpp)
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
    return loaded;
  }
}

void LabelingSession::analyse_loaded(LoadedFrame& loaded) const {
  loaded.analysis = analyser_.analyse(loaded.frame, /*with_features=*/false);
  if (beyond_) {
    const std::vector<Candidate> without = beyond_->analyse(loaded.frame, /*with_features=*/false).candidates;
    const BoxKind box = config_.analyser.reported_box;
    for (const Candidate& c : loaded.analysis.candidates) {
      loaded.made_without.push_back(std::any_of(without.begin(), without.end(), [&](const Candidate& o) {
        return iou(labelling_box(c, box), labelling_box(o, box)) >= 0.5;
      }));
    }
  }
  score(loaded);
  if (truth_ == nullptr) return;
  for (const Candidate& c : loaded.analysis.candidates) {
    const TruthOverlap overlap =
        truth_overlap(labelling_box(c, config_.analyser.reported_box), truth_->in(loaded.frame.name));
    loaded.truth_iou.push_back(overlap.counted);
    loaded.ignored_iou.push_back(overlap.ignored);
  }
}

void LabelingSession::score(LoadedFrame& frame) const {
  if (!scorer_) return;
  frame.scores = scorer_->score(frame.analysis.candidates);
  frame.probabilities.resize(frame.scores.size());
  for (std::size_t i = 0; i < frame.scores.size(); ++i) frame.probabilities[i] = model_->probability(frame.scores[i]);
}

void LabelingSession::start_prefetch() {
  prefetch_ = std::async(std::launch::async, [this] { return load_next(); });
}

void LabelingSession::take_frame(std::shared_ptr<const LoadedFrame> frame) {
  ++stats_.frames_loaded;
  if (config_.per_track) frames_.push_back(frame);
  std::vector<std::size_t> order(frame->analysis.candidates.size());
  std::iota(order.begin(), order.end(), 0);
  if (config_.order_by_score && !frame->scores.empty()) {
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return frame->scores[a] > frame->scores[b]; });
  }
  for (std::size_t i : order) {
    const PresentedCandidate p{frame, i};
    if (!frame->made_without.empty() && frame->made_without[i]) {
      ++stats_.not_added;
      continue;
    }
    if (journal_.answered(p.key())) {
      ++stats_.already_answered;
      continue;
    }
    if (!answer_without_asking(p)) queue_.push_back(p);
  }
}

bool LabelingSession::answer_without_asking(const PresentedCandidate& p) {
  const LoadedFrame& frame = *p.frame;
  const std::size_t i = p.index;
  const CandidateKey key = p.key();
  if (!frame.truth_iou.empty() && !config_.truth_is_oracle) {
    const double overlap = frame.truth_iou[i];
    if (overlap >= config_.certain_iou) {
      journal_.record({key, 'y', store(p, 1, "labeler"), "truth"});
      ++stats_.auto_positives;
      return true;
    }
    if (overlap < config_.uncertain_iou && frame.ignored_iou[i] < config_.uncertain_iou) {
      journal_.record({key, 'n', config_.keep_rejected ? store(p, 0, "labeler") : -1, "truth"});
      ++stats_.auto_negatives;
      return true;
    }
  }
  if (config_.model_answers && !frame.probabilities.empty()) {
    const double pr = frame.probabilities[i];
    const std::string by = model_answerer(*model_, frame.scores[i], pr);
    if (config_.truth_is_oracle && (pr >= config_.accept_probability || pr <= config_.reject_probability)) {
      const char truth = oracle_key(p);
      if (truth == 's') ++stats_.model_in_band;
      if (truth == (pr >= config_.accept_probability ? 'n' : 'y')) ++stats_.model_wrong;
    }
    if (pr >= config_.accept_probability) {
      journal_.record({key, 'y', store(p, 1, "labeler-model"), by});
      ++stats_.model_positives;
      return true;
    }
    if (pr <= config_.reject_probability) {
      journal_.record({key, 'n', config_.keep_rejected ? store(p, 0, "labeler-model") : -1, by});
      ++stats_.model_negatives;
      return true;
    }
  }
  return false;
}

void LabelingSession::order_by_uncertainty() {
  if (model_ == nullptr) {  // no model yet (the loop's first batch): a seeded random order over the session
    const std::vector<std::size_t> order = seeded_permutation(queue_.size(), config_.seed);
    std::deque<PresentedCandidate> shuffled;
    for (std::size_t i : order) shuffled.push_back(queue_[i]);
    queue_ = std::move(shuffled);
    return;
  }
  if (config_.ask == AskOrder::likely) {  // the likeliest people first, no exploration
    std::stable_sort(queue_.begin(), queue_.end(), [](const PresentedCandidate& a, const PresentedCandidate& b) {
      return a.frame->probabilities[a.index] > b.frame->probabilities[b.index];
    });
    return;
  }
  // Closest to where the model is read first: its operating point (0.5 for a model that states none).
  const double boundary = model_->operating_probability();
  auto doubt = [boundary](const PresentedCandidate& p) {
    return uncertainty(p.frame->probabilities[p.index], boundary);
  };
  std::stable_sort(queue_.begin(), queue_.end(),
                   [&](const PresentedCandidate& a, const PresentedCandidate& b) { return doubt(a) < doubt(b); });
  if (config_.explore_every <= 0 || queue_.size() < 2) return;
  const std::vector<std::size_t> random = seeded_permutation(queue_.size(), config_.seed + ++reorders_);
  std::vector<bool> taken(queue_.size(), false);
  std::deque<PresentedCandidate> mixed;
  std::size_t next_sorted = 0, next_random = 0;
  const auto every = static_cast<std::size_t>(config_.explore_every);
  for (std::size_t k = 0; k < queue_.size(); ++k) {
    std::size_t i = 0;
    if ((k + 1) % every == 0) {
      while (taken[random[next_random]]) ++next_random;
      i = random[next_random];
    } else {
      while (taken[next_sorted]) ++next_sorted;
      i = next_sorted;
    }
    taken[i] = true;
    mixed.push_back(queue_[i]);
  }
  queue_ = std::move(mixed);
}

void LabelingSession::rescore(const BoostedModel& model, bool may_answer) {
  if (!(model.feature_spec() == writer_.manifest().feature_spec)) {
    throw Error(model.path() + ": the model reads another feature spec than the sample set " + writer_.dir());
  }
  model_ = &model;
  scorer_.emplace(model);
  // Every pending candidate's frame is scored again once (frames are shared by their candidates).
  std::map<const LoadedFrame*, std::shared_ptr<LoadedFrame>> rescored;
  for (PresentedCandidate& p : queue_) {
    auto& copy = rescored[p.frame.get()];
    if (!copy) {
      copy = std::make_shared<LoadedFrame>(*p.frame);
      score(*copy);
    }
    p.frame = copy;
  }
  for (auto& frame : frames_) {  // per_track: the score gate reads every frame's new probabilities
    auto& copy = rescored[frame.get()];
    if (!copy) {
      copy = std::make_shared<LoadedFrame>(*frame);
      score(*copy);
    }
    frame = copy;
  }
  auto renew = [&rescored](PresentedCandidate& p) {
    if (auto it = rescored.find(p.frame.get()); it != rescored.end()) p.frame = it->second;
  };
  for (Given& g : history_) {
    renew(g.presented);
    for (PresentedCandidate& t : g.track) renew(t);
  }
  std::deque<PresentedCandidate> kept;
  const bool answers = config_.model_answers;
  config_.model_answers = answers && may_answer;
  for (const PresentedCandidate& p : queue_) {
    if (!answer_without_asking(p)) kept.push_back(p);
  }
  config_.model_answers = answers;
  queue_ = std::move(kept);
  if (reads_whole_session(config_.ask)) order_by_uncertainty();
}

const PresentedCandidate* LabelingSession::current() {
  if (reads_whole_session(config_.ask) && !sources_done_) {
    // The whole session first: the frame the read-ahead thread holds, then every other frame read in
    // order and analysed and scored on config_.threads workers, taken in frame order (ordered_pool.hpp).
    if (std::shared_ptr<LoadedFrame> first = prefetch_.get()) {  // rethrows a source's error here
      take_frame(first);
      if (progress_) progress_(stats_.frames_loaded);
      ordered_map<std::shared_ptr<LoadedFrame>>(
          config_.threads, default_items_ahead(config_.threads),
          [this](std::shared_ptr<LoadedFrame>& frame) { return (frame = read_next()) != nullptr; },
          [this](std::shared_ptr<LoadedFrame>& frame) {
            analyse_loaded(*frame);
            return frame;
          },
          [this](std::shared_ptr<LoadedFrame> frame) {
            take_frame(std::move(frame));
            if (progress_) progress_(stats_.frames_loaded);
            return true;
          });
    }
    sources_done_ = true;
    if (config_.per_track && config_.propagation.from_model) propagate_model_answers();
    order_by_uncertainty();
  }
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

std::int64_t LabelingSession::store(const PresentedCandidate& p, int label, const std::string& origin) {
  const Candidate& c = p.candidate();
  SampleRecord record;
  record.label = label;
  record.origin = origin;
  record.source = p.frame->source;
  record.frame = p.frame->frame.name;
  record.strict_box = c.strict_box;
  record.window = c.window;
  record.layer_depth_mm = c.layer_depth_mm;
  if (model_ != nullptr && !p.frame->scores.empty()) {
    record.model = model_reference(*model_);
    record.score = p.frame->scores[p.index];
  }
  // Saved before but its journal line was lost (disk full, power cut between the two): not stored twice.
  if (const std::int64_t saved = writer_.id_at_place(record); saved >= 0) return saved;
  return writer_.append(record, c.depth_crop, c.colour_crop).id;
}

JournalEntry LabelingSession::record_propagated(const PresentedCandidate& p, char answer, const std::string& by,
                                               const std::string& origin) {
  const bool yes = answer == 'y';
  const std::int64_t id = answer == 's' ? -1 : yes || config_.keep_rejected ? store(p, yes ? 1 : 0, origin) : -1;
  const JournalEntry e{p.key(), answer, id, by};
  journal_.record(e);
  return e;
}

char LabelingSession::truth_verdict(const PresentedCandidate& p, char answer) const {
  const char truth = oracle_key(p);
  if (truth == 's') return 's';
  return truth != '\0' && truth != answer ? 'x' : '\0';
}

bool LabelingSession::answer(char key) {
  if (key == 'u') {
    if (history_.empty()) return false;
    Given last = history_.back();
    history_.pop_back();
    for (std::size_t k = last.track.size(); k-- > 0;) {  // its track first, newest first
      const JournalEntry& e = last.track_entries[k];
      if (e.sample_id >= 0) writer_.retract(e.sample_id);
      journal_.record_undo(e);
      --(e.answer == 'y' ? stats_.propagated_positives : e.answer == 'n' ? stats_.propagated_negatives : stats_.propagated_skips);
      stats_.placed_negatives -= e.by.rfind("place ", 0) == 0 ? 1 : 0;
      queue_.push_back(last.track[k]);
    }
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
      id = store(p, 1, "labeler");
      ++stats_.positives;
      break;
    case 'n':
      if (config_.keep_rejected) {
        id = store(p, 0, "labeler");
        ++stats_.rejected;
      }
      ++stats_.negatives;
      break;
    case 's': ++stats_.skipped; break;
    default: return false;
  }
  const JournalEntry entry{p.key(), key, id, "human"};
  journal_.record(entry);
  history_.push_back({p, entry, {}, {}});
  queue_.pop_front();
  if (config_.per_track) propagate(history_.back());
  return true;
}

LabelingSession::Followed LabelingSession::follow(const PresentedCandidate& p, char answer, bool with_place) const {
  // The frames of p's source (frames_ holds the session's frames in order, ordinal 1, 2, ...).
  const auto at = static_cast<std::size_t>(p.frame->ordinal - 1);
  const std::pair<std::size_t, std::size_t> span = source_span(at);
  const std::size_t first = span.first, last = span.second;
  const std::vector<std::vector<TrackCandidate>> frames = track_candidates(first, last);
  std::vector<cv::Mat1w> depth;
  for (std::size_t f = first; with_place && f <= last; ++f) depth.push_back(frames_[f]->frame.depth_mm);
  const AnswerOf answer_of = [&](const TrackLink& l) {
    return journal_.answer_of(PresentedCandidate{frames_[first + l.frame], l.index}.key());
  };
  Followed followed;
  followed.first_frame = first;
  const TrackLink seed{at - first, p.index};
  followed.track = propagate_track(frames, seed, answer, config_.propagation, config_.camera, answer_of);
  if (with_place && config_.propagation.per_place) {
    const std::vector<TrackLink>& on_track = followed.track.labelled;
    const AnswerOf unanswered_off_track = [&](const TrackLink& l) {  // the track's own are labelled by it
      return std::find(on_track.begin(), on_track.end(), l) != on_track.end() ? answer : answer_of(l);
    };
    followed.place = propagate_place(frames, depth, seed, answer, config_.propagation, unanswered_off_track);
  }
  return followed;
}

std::pair<std::size_t, std::size_t> LabelingSession::source_span(std::size_t at) const {
  std::size_t first = at, last = at;
  while (first > 0 && frames_[first - 1]->source == frames_[at]->source) --first;
  while (last + 1 < frames_.size() && frames_[last + 1]->source == frames_[at]->source) ++last;
  return {first, last};
}

std::vector<std::vector<TrackCandidate>> LabelingSession::track_candidates(std::size_t first, std::size_t last) const {
  std::vector<std::vector<TrackCandidate>> frames;
  for (std::size_t f = first; f <= last; ++f) {
    const LoadedFrame& lf = *frames_[f];
    std::vector<TrackCandidate> candidates;
    const cv::Rect image(0, 0, lf.frame.depth_mm.cols, lf.frame.depth_mm.rows);
    for (std::size_t i = 0; i < lf.analysis.candidates.size(); ++i) {
      const Candidate& c = lf.analysis.candidates[i];
      candidates.push_back({c.strict_box, c.layer_depth_mm, lf.probabilities.empty() ? -1.0 : lf.probabilities[i],
                            (c.window_unclipped & image) != c.window_unclipped});
    }
    frames.push_back(std::move(candidates));
  }
  return frames;
}

void LabelingSession::propagate_model_answers() {
  // The seeds: the answers in force the model gave (this session's and, on a resume, those journalled before).
  std::map<CandidateKey, char> by_model;
  for (const JournalEntry& e : journal_.in_force()) {
    if (e.by.rfind("model ", 0) == 0 && (e.answer == 'y' || e.answer == 'n')) by_model[e.key] = e.answer;
  }
  if (by_model.empty()) return;
  PropagationParams params = config_.propagation;  // a model's n track: the stricter score gate
  params.max_no_probability = std::min(params.max_no_probability, params.model_max_no_probability);
  params.within_image = params.within_image || params.model_within_image;
  std::set<std::pair<const LoadedFrame*, std::size_t>> labelled;
  for (std::size_t first = 0, last = 0; first < frames_.size(); first = last + 1) {  // source by source
    last = source_span(first).second;
    const std::vector<std::vector<TrackCandidate>> frames = track_candidates(first, last);
    const AnswerOf answer_of = [&](const TrackLink& l) {
      return journal_.answer_of(PresentedCandidate{frames_[first + l.frame], l.index}.key());
    };
    for (std::size_t f = 0; f < frames.size(); ++f) {  // frame order: the session is the same every run
      for (std::size_t i = 0; i < frames[f].size(); ++i) {
        const CandidateKey seed = PresentedCandidate{frames_[first + f], i}.key();
        const auto it = by_model.find(seed);
        if (it == by_model.end() || journal_.answer_of(seed) != it->second) continue;
        const char answer = it->second;
        const std::string by = model_track_answerer(seed);
        const PropagatedTrack track = propagate_track(frames, {f, i}, answer, params, config_.camera, answer_of);
        for (const TrackLink& l : track.labelled) {
          const PresentedCandidate p{frames_[first + l.frame], l.index};
          record_propagated(p, answer, by, "labeler-model-track");
          labelled.insert({p.frame.get(), p.index});
          ++(answer == 'y' ? stats_.model_track_positives : stats_.model_track_negatives);
          if (const char verdict = truth_verdict(p, answer); verdict == 's') {
            ++stats_.model_track_in_band;
          } else if (verdict == 'x') {
            ++stats_.model_track_wrong;
          }
        }
      }
    }
  }
  std::deque<PresentedCandidate> kept;  // the labelled candidates are no longer asked
  for (const PresentedCandidate& p : queue_) {
    if (labelled.count({p.frame.get(), p.index}) == 0) kept.push_back(p);
  }
  queue_ = std::move(kept);
}

std::vector<PresentedCandidate> LabelingSession::track_preview(char answer) const {
  std::vector<PresentedCandidate> track;
  if (!config_.per_track || queue_.empty() || frames_.empty()) return track;
  const Followed f = follow(queue_.front(), answer, /*with_place=*/false);
  for (const TrackLink& l : f.track.labelled) track.push_back({frames_[f.first_frame + l.frame], l.index});
  return track;
}

std::vector<PresentedCandidate> LabelingSession::place_preview() const {
  std::vector<PresentedCandidate> place;
  if (!config_.per_track || !config_.propagation.per_place || queue_.empty() || frames_.empty()) return place;
  const Followed f = follow(queue_.front(), 'n', /*with_place=*/true);
  for (const TrackLink& l : f.place) place.push_back({frames_[f.first_frame + l.frame], l.index});
  return place;
}

void LabelingSession::propagate(Given& given) {
  if (frames_.empty()) return;
  const Followed followed = follow(given.presented, given.entry.answer, /*with_place=*/true);
  std::set<std::pair<const LoadedFrame*, std::size_t>> labelled;
  const auto label = [&](const TrackLink& l, const std::string& by, const std::string& origin) {
    const PresentedCandidate p{frames_[followed.first_frame + l.frame], l.index};
    const bool yes = given.entry.answer == 'y', skip = given.entry.answer == 's', placed = origin == "labeler-place";
    const JournalEntry e = record_propagated(p, given.entry.answer, by, origin);
    given.track.push_back(p);
    given.track_entries.push_back(e);
    labelled.insert({p.frame.get(), p.index});
    if (skip) {
      ++stats_.propagated_skips;
      return;
    }
    ++(yes ? stats_.propagated_positives : stats_.propagated_negatives);
    stats_.placed_negatives += placed ? 1 : 0;
    if (const char verdict = truth_verdict(p, given.entry.answer); verdict == 's') {
      ++stats_.propagated_in_band;
      stats_.placed_in_band += placed ? 1 : 0;
    } else if (verdict == 'x') {
      ++stats_.propagated_wrong;
      stats_.placed_wrong += placed ? 1 : 0;
    }
  };
  const std::string by_track = track_answerer(given.entry.key), by_place = place_answerer(given.entry.key);
  for (const TrackLink& l : followed.track.labelled) label(l, by_track, "labeler-track");
  for (const TrackLink& l : followed.place) label(l, by_place, "labeler-place");
  // The labelled candidates leave the queue; where the track became unsure is asked next.
  std::set<std::pair<const LoadedFrame*, std::size_t>> ask;
  for (const TrackLink& l : followed.track.ask) ask.insert({frames_[followed.first_frame + l.frame].get(), l.index});
  std::deque<PresentedCandidate> front, rest;
  for (const PresentedCandidate& p : queue_) {
    const std::pair<const LoadedFrame*, std::size_t> id{p.frame.get(), p.index};
    if (labelled.count(id) != 0) continue;
    (ask.count(id) != 0 ? front : rest).push_back(p);
  }
  front.insert(front.end(), rest.begin(), rest.end());
  queue_ = std::move(front);
}

std::size_t LabelingSession::sure_count() const {
  std::size_t n = 0;
  for (const PresentedCandidate& p : queue_) {
    if (p.frame->probabilities.empty()) continue;
    const double pr = p.frame->probabilities[p.index];
    n += pr >= config_.accept_probability || pr <= config_.reject_probability ? 1 : 0;
  }
  return n;
}

std::size_t LabelingSession::finish_with_model() {
  if (model_ == nullptr || !config_.model_answers) return 0;
  const std::size_t before = queue_.size();
  std::deque<PresentedCandidate> kept;
  for (const PresentedCandidate& p : queue_) {
    if (!answer_without_asking(p)) kept.push_back(p);
  }
  queue_ = std::move(kept);
  return before - queue_.size();
}

char LabelingSession::oracle_key() const { return queue_.empty() ? '\0' : oracle_key(queue_.front()); }

char LabelingSession::oracle_key(const PresentedCandidate& p) const {
  if (p.frame->truth_iou.empty()) return '\0';
  const double overlap = p.frame->truth_iou[p.index];
  if (overlap >= config_.certain_iou) return 'y';
  if (overlap < config_.uncertain_iou && p.frame->ignored_iou[p.index] < config_.uncertain_iou) return 'n';
  return 's';
}

void LabelingSession::leave_unanswered() {
  if (queue_.empty()) return;
  queue_.pop_front();
  ++stats_.unanswered;
}

}  // namespace rdsf
