#pragma once
// The labeler's logic, without any window: frames are read and analysed one ahead (in a background thread,
// while the person decides), each candidate not answered before is presented in turn, and every answer is
// stored before the next candidate is presented:
//   y  a positive sample (label 1, origin labeler) is appended to the set
//   n  nothing is stored, unless keep_rejected: then a negative (label 0, origin labeler)
//   s  skipped: nothing is stored, the candidate is not presented again
//   u  undoes the last answer given in this session (across frames too): its sample is retracted from the
//      set and the candidate is presented again
// Every answer also goes to the set's answer journal (labeler-answers.tsv), so a rerun on the same sources
// and set resumes at the first unanswered candidate and never presents an answered one again.
// With ground truth (assisted mode), candidates overlapping a person with IoU >= 0.5 are answered y and
// those below 0.3 n without asking; only the uncertain band in between is presented.
// With a model (model answers, on unless model_answers is false), candidates the model is sure about are
// answered by it and never presented: P(person) >= accept_probability is y, P <= reject_probability is n;
// they are journalled with by = "model NAME/vN H=... P=..." and their samples have origin "labeler-model".
// Ask order: in_order presents frame after frame (the thesis's way); uncertain scores every frame of every
// source first (on the read-ahead thread) and presents the whole session's candidates closest to the
// model's operating point first (P = 0.5 for a model that states none, operating_point.hpp), ties in frame
// order (without a model yet: in a seeded random order); likely reads the session in the same way and presents
// the highest P(person) first. rescore() replaces the model mid-session (the active-learning loop).
// Only what an option adds (only_added_beyond): each frame is analysed again with the other parameters, and
// a candidate that analysis makes too (labelling boxes at IoU >= 0.5) is never presented, answered or stored.
// Per track (per_track, uncertain or likely order): a human y or n is followed through the frames before and
// after by track propagation (track_propagation.hpp, the rule there) and every candidate on the sure part
// of the track gets the same answer (origin "labeler-track", journalled with by = "track FRAME X,Y,W,H");
// the candidates where the track became unsure are presented next. Undo of the answer undoes them all. A
// skip (s) is propagated too: the track is not presented again, nothing is stored.
// One answer per place (per_track with propagation.per_place): a human n also labels n the candidates of
// other frames of the same source at the same place (track_propagation.hpp, propagate_place), beyond its
// track: origin "labeler-place", journalled with by = "place FRAME X,Y,W,H"; they count as propagated
// labels and are undone with the answer, as its track is.
// From the model's answers (per_track with propagation.from_model): once the whole session is read, before
// the questions are ordered, every candidate the model answered (its sure y and n, this session's or
// journalled before) is followed along its track as a person's answer is (the track only, no place), in
// frame order, and the unanswered candidates on the sure part get the model's answer: origin
// "labeler-model-track", journalled with by = "model-track FRAME X,Y,W,H"; they leave the queue. They are
// no person's answer: u does not undo them.
#include <cstdint>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/pipeline/model_scorer.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/labeling/answer_journal.hpp"
#include "rdsf/labeling/track_propagation.hpp"

namespace rdsf {

/// Defaults of the model answers: measured on synthetic recordings (docs/labeler.md, bench/bench_labeler):
/// at these thresholds fewer than 1% of the model's answers were wrong.
inline constexpr double kDefaultAcceptProbability = 0.99;
inline constexpr double kDefaultRejectProbability = 0.01;

/// in_order: frame after frame; uncertain: the whole session, closest to the model's operating point first;
/// likely: the whole session, the highest P(person) first (which of the candidates an option adds are people:
/// rdsf-adapt's trials of the candidate switches).
enum class AskOrder { in_order, uncertain, likely };

/// "order", "uncertain" or "likely"; throws Error naming the known ones otherwise.
AskOrder parse_ask_order(const std::string& text);

/// Whether the order reads (analyses and scores) the whole session before the first question.
inline bool reads_whole_session(AskOrder order) { return order != AskOrder::in_order; }

struct LabelingConfig {
  std::vector<std::string> sources;
  /// With a model: answer the candidates it is sure about (P >= accept_probability: y, <= reject: n).
  bool model_answers = true;
  double accept_probability = kDefaultAcceptProbability;
  double reject_probability = kDefaultRejectProbability;
  AskOrder ask = AskOrder::in_order;  ///< uncertain without a model: a seeded random order (the loop's start)
  /// Uncertain order reads the whole session first: its frames are read in order and analysed and scored
  /// on this many threads (the library's ordered pool, core/ordered_pool.hpp; 0: one per core), taken in
  /// frame order, so the session is the same for every thread count.
  int threads = 0;
  std::uint64_t seed = 1;
  /// Uncertain order with exploration: every explore_every-th candidate presented is a seeded random one
  /// instead of the next most uncertain, so that kinds of candidates the model has never seen (and is
  /// wrongly sure about) are found too. 0 = off (plain uncertainty order); the loop uses 5.
  int explore_every = 0;
  bool keep_rejected = false;
  bool order_by_score = false;  ///< present a frame's candidates highest score first (needs a model)
  /// Assisted mode: IoU of the box detections report (detector.reported_box: fitted by default, as the
  /// evaluation matches) with a truth box; >= this is a person.
  double certain_iou = 0.5;
  double uncertain_iou = 0.3;   ///< assisted mode: IoU < this is not a person; in between is asked
  /// Assisted mode: a candidate covering (IoU >= uncertain_iou) a person marked ignored in the truth
  /// (hardly visible, see ignore_hardly_visible) and no counted one is asked, never answered, as the
  /// evaluation counts it neither right nor wrong.
  /// The truth is the person (benchmarks): it answers only the candidates presented (as a human answer,
  /// see oracle_key()) instead of the sure ones silently.
  bool truth_is_oracle = false;
  /// One answer per track (the header's comment); needs an order that reads the whole session first.
  bool per_track = false;
  /// Only what an option adds: a candidate that the analyser with these parameters makes too (a candidate
  /// of it whose labelling box overlaps its own at IoU >= 0.5 in the frame) is neither asked, nor answered,
  /// nor stored (rdsf-label --only-added-by NAME: the same options with NAME at its default).
  std::optional<AnalyserParams> only_added_beyond;
  PropagationParams propagation;
  AnalyserParams analyser;
  CameraModel camera;
};

struct LoadedFrame {
  std::string source;              ///< the source as recorded in samples (absolute path when a file)
  DepthFrame frame;
  FrameAnalysis analysis;
  std::vector<double> scores;      ///< per candidate H(x); empty without a model
  std::vector<double> probabilities;  ///< per candidate P(person) = model calibration of scores
  std::vector<double> truth_iou;   ///< per candidate, best IoU with a counted ground-truth person; empty without truth
  std::vector<double> ignored_iou; ///< per candidate, best IoU with a don't-care (hardly visible) person
  /// With only_added_beyond: per candidate, whether that analyser makes it too (never presented); else empty.
  std::vector<bool> made_without;
  std::int64_t ordinal = 0;        ///< 1-based over all sources
};

struct PresentedCandidate {
  std::shared_ptr<const LoadedFrame> frame;
  std::size_t index = 0;  ///< candidate index in the frame
  const Candidate& candidate() const { return frame->analysis.candidates[index]; }
  CandidateKey key() const;
};

struct LabelingStats {
  long positives = 0, negatives = 0, rejected = 0, skipped = 0, undone = 0;  ///< human answers this session
  long auto_positives = 0, auto_negatives = 0;                               ///< assisted mode
  long model_positives = 0, model_negatives = 0;                             ///< answered by the model
  /// truth_is_oracle: model answers the truth contradicts (y for a sure not-person or n for a sure person),
  /// and those in the truth's uncertain band (neither right nor wrong)
  long model_wrong = 0, model_in_band = 0;
  long already_answered = 0;                                                 ///< skipped on resume
  long not_added = 0;  ///< only_added_beyond: candidates left out, the other analyser makes them too
  /// per_track: labels given by propagation, and (with truth) those the truth contradicts or leaves in
  /// its uncertain band
  long propagated_positives = 0, propagated_negatives = 0, propagated_wrong = 0, propagated_in_band = 0;
  long propagated_skips = 0;  ///< per_track: candidates skipped with a skipped one (nothing stored)
  /// per place: of the propagated negatives (and of the wrong and in-band ones), those labelled at the
  /// answer's place beyond its track
  long placed_negatives = 0, placed_wrong = 0, placed_in_band = 0;
  /// per_track with propagation.from_model: labels given along the tracks of the model's answers, and
  /// (with truth) those the truth contradicts or leaves in its uncertain band; not in propagated_*
  long model_track_positives = 0, model_track_negatives = 0, model_track_wrong = 0, model_track_in_band = 0;
  long unanswered = 0;      ///< presented but left without an answer (answers ran out)
  std::int64_t frames_loaded = 0;
  long answers() const { return positives + negatives + skipped; }
};

class LabelingSession {
 public:
  /// Called after each frame is scored in uncertain mode, before the first candidate: frames done.
  using ScoringProgress = std::function<void(std::int64_t frames)>;

  /// `model` and `truth` may be null. The writer, model and truth must outlive the session. Throws Error
  /// when the model's feature spec is not the set's, or accept_probability < reject_probability.
  LabelingSession(LabelingConfig config, SampleSetWriter& writer, const BoostedModel* model,
                  const GroundTruth* truth, ScoringProgress progress = {});
  ~LabelingSession();
  LabelingSession(const LabelingSession&) = delete;
  LabelingSession& operator=(const LabelingSession&) = delete;

  /// The candidate to present, or nullptr when every candidate of every source is answered.
  const PresentedCandidate* current();
  /// Applies a key: 'y', 'n', 's' or 'u'. Returns false when it did nothing (an undo with nothing to
  /// undo in this session, or no current candidate).
  bool answer(char key);
  /// With truth_is_oracle: the key the truth gives the current candidate ('y' IoU >= certain_iou, 'n' below
  /// uncertain_iou with everyone, else 's'); '\0' without truth or candidate.
  char oracle_key() const;
  char oracle_key(const PresentedCandidate& p) const;
  /// Leaves the current candidate unanswered and moves on (answers ran out in headless mode).
  void leave_unanswered();

  const LabelingStats& stats() const { return stats_; }
  /// Frames over all sources when every source knows its length.
  std::optional<std::int64_t> total_frames() const { return total_frames_; }
  /// Candidates of the current frame still to be presented, the current one included.
  std::size_t pending_in_frame() const { return queue_.size(); }
  const AnswerJournal& journal() const { return journal_; }
  const LabelingConfig& config() const { return config_; }
  const BoostedModel* model() const { return model_; }
  /// Candidates still to be presented (uncertain mode: of the whole session), the current one included.
  std::size_t pending() const { return queue_.size(); }

  /// Replaces the model (which must outlive the session) and re-scores every pending candidate; in
  /// uncertain mode reorders them, and with model answers (and `may_answer`) lets the new model answer
  /// those it is sure of.
  void rescore(const BoostedModel& model, bool may_answer = true);
  /// Pending candidates the current model is sure about (it would answer them).
  std::size_t sure_count() const;
  /// Lets the current model answer every pending candidate it is sure about (the loop's end); returns how
  /// many it answered.
  std::size_t finish_with_model();
  /// per_track: the candidates an answer `answer` to the current candidate would label too (the track the
  /// window shows as a strip), frame order; empty otherwise.
  std::vector<PresentedCandidate> track_preview(char answer = 'y') const;
  /// per_track with propagation.per_place: the candidates an 'n' to the current candidate would label at
  /// its place beyond its 'n' track (the window's second strip), frame order; empty otherwise.
  std::vector<PresentedCandidate> place_preview() const;

 private:
  struct Given {
    PresentedCandidate presented;
    JournalEntry entry;
    std::vector<PresentedCandidate> track;  ///< per_track: labelled by propagation from this answer
    std::vector<JournalEntry> track_entries;
  };
  /// per_track: the track of `p` answered `answer` over the frames of its source and, with per_place, the
  /// candidates labelled at its place beyond the track (links index the source's frames from first_frame).
  struct Followed {
    std::size_t first_frame = 0;
    PropagatedTrack track;
    std::vector<TrackLink> place;
  };
  Followed follow(const PresentedCandidate& p, char answer, bool with_place) const;
  /// The frames of frames_ from `first` to `last` (one source) as track propagation sees them.
  std::vector<std::vector<TrackCandidate>> track_candidates(std::size_t first, std::size_t last) const;
  /// The first and last index in frames_ of the frames of frame `at`'s source (frames_ holds the session's
  /// frames in order, each source's together).
  std::pair<std::size_t, std::size_t> source_span(std::size_t at) const;
  /// per_track with propagation.from_model: labels the tracks of the model's answers (the header's comment).
  void propagate_model_answers();
  /// per_track: labels the track of the answer just given (`given`), presents its unsure ends next.
  void propagate(Given& given);
  std::shared_ptr<LoadedFrame> load_next();  // runs on the prefetch thread: read_next + analyse_loaded
  std::shared_ptr<LoadedFrame> read_next();  // the next frame of the sources, read; null at the end (in order)
  void analyse_loaded(LoadedFrame& frame) const;  // candidates, scores, truth (any thread)
  void start_prefetch();
  void take_frame(std::shared_ptr<const LoadedFrame> frame);
  std::int64_t store(const PresentedCandidate& p, int label, const std::string& origin);
  /// Journals a label propagated to `p` (answer y, n or s; stored as a sample under `origin` when y, or n with
  /// keep_rejected; never for s) and returns its entry.
  JournalEntry record_propagated(const PresentedCandidate& p, char answer, const std::string& by,
                                 const std::string& origin);
  /// With truth: 's' when the truth leaves `p` in its uncertain band, 'x' when it contradicts `answer`, else '\0'.
  char truth_verdict(const PresentedCandidate& p, char answer) const;
  void score(LoadedFrame& frame) const;
  /// Answers the candidate from truth or the model when they are sure; false when it must be asked.
  bool answer_without_asking(const PresentedCandidate& p);
  /// Orders the queue as config_.ask says (uncertain: with exploration; likely: highest P first).
  void order_by_uncertainty();

  LabelingConfig config_;
  SampleSetWriter& writer_;
  const BoostedModel* model_;
  ScoringProgress progress_;
  std::optional<ModelScorer> scorer_;  ///< the model, computing only the features it reads (in its own spec)
  const GroundTruth* truth_;
  FrameAnalyser analyser_;
  std::optional<FrameAnalyser> beyond_;  ///< config_.only_added_beyond's analyser
  AnswerJournal journal_;
  std::size_t source_index_ = 0;
  std::unique_ptr<FrameSource> source_;
  std::string source_name_;
  std::int64_t ordinal_ = 0;
  std::optional<std::int64_t> total_frames_;
  std::future<std::shared_ptr<LoadedFrame>> prefetch_;
  bool sources_done_ = false;
  std::deque<PresentedCandidate> queue_;
  std::uint64_t reorders_ = 0;  ///< exploration draws a new random order each time
  std::vector<Given> history_;
  std::vector<std::shared_ptr<const LoadedFrame>> frames_;  ///< per_track: every frame, in session order
  LabelingStats stats_;
};

}  // namespace rdsf
