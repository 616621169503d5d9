#pragma once
// One answer per track: a candidate the person answered is followed forwards and backwards through the
// frames of its recording, and the candidates on its track get the same answer while the track is sure.
//
// The rule, between consecutive frames f and g = f +- 1 (t: the track's candidate in f, c: one in g):
//   c passes the gates from t when
//     IoU(t.box, c.box) >= min_iou                                         (overlap)
//     |t.depth_mm - c.depth_mm| <= max_depth_step_mm                       (depth continuity)
//     lkh(t, c) <= max_lkh, the tracker's match score (tracking/tracker.hpp, colour term dropped:
//       d_cm / 98 - 1 / 49 with d_cm between the two centroids)           (the tracker's matching)
//     and, when candidates have a probability (a model scored them): c.probability >= min_yes_probability
//     for a 'y' track, <= max_no_probability for an 'n' track             (score)
//   the link t -> c is sure when c is the best of g's candidates passing the gates from t (highest IoU),
//   every other one of them has an IoU with t at least ambiguity_margin lower, and the same holds back from
//   c among f's candidates (t best, runner-up at least ambiguity_margin lower): two people crossing, or a
//   person and a piece of them, make both directions ambiguous and the track stops there.
// A frame where no candidate passes the gates from t (t's object has no candidate there, or one that fails a
// gate: a depth glitch, a score the model is sure of) is stepped over, up to max_gap_frames such frames in a
// row: g is then the next frame where one does, and nothing in the frames stepped over is labelled.
// The track stops at the first frame with no sure link; the candidates that passed the gates there (there
// is at least one when the stop was an ambiguity) are returned as the ones to ask. It also stops at a
// candidate answered otherwise before (answer_of gives another answer), and goes through (without
// relabelling) one answered the same. Frames are one recording in time order; a gap (another recording,
// a skipped frame) must be a frame without candidates.
//
// One answer per place (per_place, for 'n' answers only: a person moves, furniture does not): the seed s,
// answered 'n' in frame f, also labels 'n' every candidate c of every OTHER frame g of the recording (any
// distance in time, not only along the track) that is the same static thing seen from the same place:
//     IoU(s.box, c.box) >= place_min_iou                                  (the same pixels)
//     |s.depth_mm - c.depth_mm| <= place_max_depth_step_mm                (the same layer)
//     the camera did not move and nothing came in front: of the pixels of s.box with a reading in both
//       frames' depth images (at least place_min_valid_share of the box), at least place_min_agreeing
//       differ by at most place_pixel_change x the nearer depth (sensor noise and disparity steps grow with
//       depth: 1.2 mm x z^2 and z^2 / 348 mm, z in m, about 3 % at 4 m together)  (the same view)
//     c.probability <= max_no_probability, as an 'n' track                (score)
// and c has no answer yet (answer_of gives '\0'). A person who stands where the thing stood changes the
// depth of the box's pixels; a camera that moved changes them all.
//
// From the model's answers (from_model, off by default): the candidates a model answered without asking (its
// sure y and n) are seeds too, followed by the same track rule (not by one answer per place: a model's n is
// wrong more often than a person's, and a place repeats one wrong n in every frame of a still camera); the
// labelling session does it once, when the whole session is read (labeling_session.hpp). A model's n track
// enters only candidates with P <= model_max_no_probability (not max_no_probability): with 0.95 it walked
// from a thing into a person passing in front of it (16 wrong labels of one track, P 0.04 to 0.19 there).
// A model's track also neither starts at nor enters a candidate cut by the image's edge (its window reaches
// beyond the image: model_within_image): the model is surest and most wrong there (a near person whose head
// the image cuts scored P 0.002-0.009), and its tracks carried those answers into 16 of the 21 wrong labels
// on held-out rooms (docs/adapting-to-your-room.md).
#include <cstddef>
#include <functional>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/labeling/answer_journal.hpp"

namespace rdsf {

struct PropagationParams {
  /// Strict boxes of consecutive frames. 0.4 / 0.1 and 0.5 / 0.2 wrote the same 3 wrong labels on 16 synthetic
  /// rooms (0.33 %, of 899 and 847 propagated; docs/adapting-to-your-room.md); 0.4 / 0.1 asked 655 instead of 722
  /// (both with max_gap_frames 0).
  double min_iou = 0.4;
  double ambiguity_margin = 0.1;     ///< the runner-up's IoU must be this much below the best's
  double max_depth_step_mm = 300;    ///< layer depth change between consecutive frames
  double max_lkh = 0.39;             ///< tracker lkh without colour: centroids at most 40 cm apart
  double min_yes_probability = 0.05; ///< a 'y' track does not enter a candidate the model rejects this surely
  double max_no_probability = 0.95;  ///< an 'n' track does not enter a candidate the model accepts this surely
  int max_frames = 0;                ///< frames followed in each direction (0: no limit)
  /// Frames in a row where no candidate passes the gates that a track steps over (the rule above); 0: it
  /// stops at the first. On the 16 synthetic rooms (docs/adapting-to-your-room.md) 1 asked 554 questions
  /// instead of 655 with the same 3 wrong labels (0.30 % of 1,014); 2 asked 512 with 5 wrong (0.47 %). Default
  /// 0: in the benchmark the real lab's adapted model fell from 0.833 to 0.667 with 1 (docs/adapting-to-your-room.md).
  int max_gap_frames = 0;
  /// One answer per place (the rule above) for 'n' answers; off: only the track is labelled.
  bool per_place = true;
  double place_min_iou = 0.65;              ///< strict boxes of the answered candidate and the labelled one
  double place_max_depth_step_mm = 150;     ///< their layer depths
  double place_pixel_change = 0.03;         ///< a pixel agrees when its depths differ by at most this x depth
  double place_min_agreeing = 0.6;          ///< share of the box's pixels valid in both frames that agree
  double place_min_valid_share = 0.5;       ///< share of the box's pixels valid in both frames, at least
  /// The model's sure answers are followed along their tracks too (the rule above); off: only people's are. With
  /// the tracks within the image (model_within_image) it asked 10-15 % fewer questions than off on four sets of
  /// 16 synthetic rooms, under 1 % of all propagated labels wrong on each, but in the adaptation benchmark the
  /// real lab's model at a budget of 10 answers fell from 0.833 to 0.667 (docs/adapting-to-your-room.md): off.
  bool from_model = false;
  /// from_model: the score gate of a model's n track (a y track's is min_yes_probability). On the 16 synthetic
  /// rooms (docs/adapting-to-your-room.md, people/v2) the model's tracks labelled 989 with 20 wrong at 0.95 (the
  /// people's gate), 976 / 20 at 0.3, 958 / 20 at 0.2, 935 / 18 at 0.15, 880 / 3 at 0.1 and 761 / 2 at 0.05,
  /// asking 272, 276, 283, 285, 310 and 343 questions: 0.1 is one track's P (0.11) below the cliff, tuned on
  /// that benchmark. On 16 held-out rooms (seed 32) 0.1 wrote 21 wrong of 1,134 (1.85 %): it does not hold.
  double model_max_no_probability = 0.1;
  /// A track neither starts at nor enters a candidate cut by the image's edge (TrackCandidate::cut_by_image).
  /// Off for a person's answers (they are as good at the edge); the session turns it on for the model's
  /// tracks when model_within_image.
  bool within_image = false;
  /// from_model: the model's tracks stay within the image (within_image), because its answers are least sure on
  /// crops cut by the image's edge (a near person's torso, a person entering at the side: issue 34).
  bool model_within_image = true;
};

/// What propagation needs of a candidate.
struct TrackCandidate {
  cv::Rect box;              ///< strict box, pixels
  double depth_mm = 0;       ///< layer depth
  double probability = -1;   ///< P(person) of the model; < 0: not scored (no score gate)
  bool cut_by_image = false; ///< its window (Candidate::window_unclipped) reaches beyond the image
};

/// A candidate: frame position in the recording and index among that frame's candidates.
struct TrackLink {
  std::size_t frame = 0, index = 0;
  bool operator==(const TrackLink& o) const { return frame == o.frame && index == o.index; }
};

struct PropagatedTrack {
  std::vector<TrackLink> labelled;  ///< candidates given the answer (the seed not included), frame order
  std::vector<TrackLink> ask;       ///< candidates at the ends where the track was unsure (to be asked)
};

/// The answer already given a candidate: 'y', 'n', 's' or '\0' for none.
using AnswerOf = std::function<char(const TrackLink&)>;

/// True when c passes the gates from t for a track answered `answer` (the rule above).
bool passes_track_gates(const TrackCandidate& t, const TrackCandidate& c, char answer, const PropagationParams& params,
                        const CameraModel& camera);

/// Follows `seed` (answered `answer`, 'y' or 'n') through `frames` both ways (the rule above); with
/// params.within_image a seed cut by the image's edge labels nothing.
PropagatedTrack propagate_track(const std::vector<std::vector<TrackCandidate>>& frames, const TrackLink& seed,
                                char answer, const PropagationParams& params, const CameraModel& camera,
                                const AnswerOf& answer_of = {});

/// Of the pixels of `box` with a reading (> 0) in both depth images `a` and `b` (the same size), the share
/// whose depths differ by at most `max_change` x the nearer of the two; -1 when those pixels are fewer than
/// `min_valid_share` of the box (pixels outside the images have no reading: nothing to judge by). 1 for two
/// identical images. Pixels are taken every s-th row and column, s = ceil(sqrt(box area / 4096)) (all of a
/// box up to 4,096 pixels; about 64 x 64 of a larger one), so the cost is bounded whatever the box.
double depth_agreement(const cv::Mat1w& a, const cv::Mat1w& b, const cv::Rect& box, double max_change,
                       double min_valid_share);

/// One answer per place (the rule above): the candidates of frames other than the seed's that the answer
/// `answer` to `seed` labels, frame order; empty unless params.per_place and answer == 'n'. `depth_mm` holds
/// each frame's depth image (millimetres, 0: no reading), as many as `frames`; a frame whose image is empty
/// or of another size than the seed's is not labelled.
std::vector<TrackLink> propagate_place(const std::vector<std::vector<TrackCandidate>>& frames,
                                       const std::vector<cv::Mat1w>& depth_mm, const TrackLink& seed, char answer,
                                       const PropagationParams& params, const AnswerOf& answer_of = {});

/// The journal's "by" of labels propagated from the answer to `seed`: "track FRAME X,Y,W,H" (the seed's
/// frame and strict box; the source is the entry's own), and "place FRAME X,Y,W,H" for those one answer per
/// place gave. Undoing the seed's answer undoes every entry journalled with either "by" (propagated_from()).
std::string track_answerer(const CandidateKey& seed);
std::string place_answerer(const CandidateKey& seed);
/// The "by" of labels propagated along the track of a MODEL's answer to `seed`: "model-track FRAME X,Y,W,H".
/// No person's answer is undone with them.
std::string model_track_answerer(const CandidateKey& seed);

/// The entries in force in `journal` propagated from the answer to `seed` (along its track and to its
/// place), oldest first.
std::vector<JournalEntry> propagated_from(const AnswerJournal& journal, const CandidateKey& seed);

}  // namespace rdsf
