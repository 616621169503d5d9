// One answer per place (labeling/track_propagation.hpp, propagate_place) on hand-built frames and depth
// images: a static piece that flickers (its track breaks at once) is labelled n in non-consecutive frames
// from one n; not across a camera move, not where a person came in front, not at another layer depth or a
// score the model is sure of, never for a y or a skip; the journal's "place" entries are undone with their
// answer. The labelling session with per_place: TrackPropagation.SessionLabelsThePlaceAndUndoTakesItAllBack
// (tests/test_track_propagation.cpp, beside the session's track test).
#include <gtest/gtest.h>

#include <algorithm>

#include "rdsf/labeling/track_propagation.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

const cv::Rect kPiece(300, 200, 40, 60);  // a piece of furniture at 3 m, strict box

// A still room: a wall at 4 m, the piece at 3 m in front of it.
cv::Mat1w room_depth() {
  cv::Mat1w depth(480, 640, std::uint16_t{4000});
  depth(kPiece).setTo(3000);
  return depth;
}

// `frames` frames of the still room; the piece's candidate is there only in `seen` (a flicker: it is
// missed in the frames between, so its track breaks at once), a person walks on the left in every frame.
struct Sequence {
  std::vector<std::vector<TrackCandidate>> frames;
  std::vector<cv::Mat1w> depth;
};

Sequence flickering_piece(int frames, const std::vector<int>& seen) {
  Sequence s;
  for (int f = 0; f < frames; ++f) {
    cv::Mat1w depth = room_depth();
    const cv::Rect person(40 + 5 * f, 150, 60, 120);
    depth(person).setTo(2500);
    s.depth.push_back(depth);
    s.frames.push_back({{person, 2500, 0.6}});
    if (std::find(seen.begin(), seen.end(), f) != seen.end()) s.frames.back().push_back({kPiece, 3000, 0.3});
  }
  return s;
}

std::vector<std::size_t> frames_of(const std::vector<TrackLink>& links) {
  std::vector<std::size_t> out;
  for (const TrackLink& l : links) {
    EXPECT_EQ(l.index, 1u) << "frame " << l.frame;  // only the piece, never the person
    out.push_back(l.frame);
  }
  return out;
}

}  // namespace

TEST(PlacePropagation, DepthAgreementOfTheBoxsPixels) {
  const cv::Mat1w a = room_depth();
  EXPECT_DOUBLE_EQ(depth_agreement(a, a, kPiece, 0.03, 0.5), 1.0);
  cv::Mat1w b = a.clone();
  b(cv::Rect(kPiece.x, kPiece.y, kPiece.width / 4, kPiece.height)).setTo(2000);  // a quarter changed
  EXPECT_DOUBLE_EQ(depth_agreement(a, b, kPiece, 0.03, 0.5), 0.75);
  b = a + 80;  // 80 mm: 2.7 % of 3 m agrees at 3 %, not at 2 %
  EXPECT_DOUBLE_EQ(depth_agreement(a, b, kPiece, 0.03, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(depth_agreement(a, b, kPiece, 0.02, 0.5), 0.0);
  b = a.clone();
  b(cv::Rect(kPiece.x, kPiece.y, kPiece.width, kPiece.height * 6 / 10)).setTo(0);  // 60 % without a reading
  EXPECT_DOUBLE_EQ(depth_agreement(a, b, kPiece, 0.03, 0.5), -1.0);                 // nothing to judge by
  EXPECT_DOUBLE_EQ(depth_agreement(a, b, kPiece, 0.03, 0.3), 1.0);
  EXPECT_DOUBLE_EQ(depth_agreement(a, b, cv::Rect(630, 470, 40, 40), 0.03, 0.5), -1.0);  // mostly outside
}

TEST(PlacePropagation, AnNLabelsAStaticPieceInNonConsecutiveFrames) {
  const Sequence s = flickering_piece(30, {2, 9, 17, 18, 29});
  PropagationParams params;
  ASSERT_TRUE(params.per_place);  // the default (docs/adapting-to-your-room.md)
  // Its track breaks at once: the frames next to the answered one have no piece.
  EXPECT_TRUE(propagate_track(s.frames, {9, 1}, 'n', params, CameraModel{}).labelled.empty());
  EXPECT_EQ(frames_of(propagate_place(s.frames, s.depth, {9, 1}, 'n', params)),
            (std::vector<std::size_t>{2, 17, 18, 29}));
  // Off: nothing. Answered before (by anyone): not labelled again.
  PropagationParams off = params;
  off.per_place = false;
  EXPECT_TRUE(propagate_place(s.frames, s.depth, {9, 1}, 'n', off).empty());
  EXPECT_EQ(frames_of(propagate_place(s.frames, s.depth, {9, 1}, 'n', params,
                                      [](const TrackLink& l) { return l.frame == 17 ? 'n' : '\0'; })),
            (std::vector<std::size_t>{2, 18, 29}));
}

TEST(PlacePropagation, NeverForAYesOrASkip) {
  const Sequence s = flickering_piece(30, {2, 9, 17});
  EXPECT_EQ(propagate_place(s.frames, s.depth, {9, 1}, 'n', {}).size(), 2u);
  EXPECT_TRUE(propagate_place(s.frames, s.depth, {9, 1}, 'y', {}).empty());
  EXPECT_TRUE(propagate_place(s.frames, s.depth, {9, 1}, 's', {}).empty());
  // A person standing still passes every gate of the place in every frame, yet a y is never given by place
  // (a person moves: only the track carries a y).
  Sequence still = flickering_piece(10, {});
  for (int f = 0; f < 10; ++f) {
    still.frames[f][0].box = cv::Rect(100, 150, 60, 120);
    still.depth[f] = room_depth();
    still.depth[f](still.frames[f][0].box).setTo(2500);
  }
  EXPECT_EQ(propagate_place(still.frames, still.depth, {4, 0}, 'n', {}).size(), 9u);  // what an n would label
  EXPECT_TRUE(propagate_place(still.frames, still.depth, {4, 0}, 'y', {}).empty());
}

TEST(PlacePropagation, DoesNotCrossACameraMove) {
  Sequence s = flickering_piece(30, {2, 9, 17, 25});
  for (int f = 12; f < 30; ++f) {  // from frame 12 the camera has driven 40 cm nearer: every depth changed
    cv::Mat1w moved = room_depth() - 400;
    s.depth[f] = moved;  // the piece's candidate still at the same pixels by chance, 40 cm nearer
  }
  s.frames[17][1].depth_mm = 3000;  // even with the same layer depth, the pixels say the view changed
  s.frames[25][1].depth_mm = 2600;
  EXPECT_EQ(frames_of(propagate_place(s.frames, s.depth, {9, 1}, 'n', {})), (std::vector<std::size_t>{2}));
  // A turn of the camera (about 2.6 degrees: the image shifted by 24 px) with a candidate at the answered
  // box by chance: 16 of its 40 columns still see the piece, too few.
  s = flickering_piece(30, {2, 9, 17});
  cv::Mat1w turned(480, 640, std::uint16_t{4000});
  room_depth()(cv::Rect(24, 0, 616, 480)).copyTo(turned(cv::Rect(0, 0, 616, 480)));
  s.depth[17] = turned;
  EXPECT_EQ(frames_of(propagate_place(s.frames, s.depth, {9, 1}, 'n', {})), (std::vector<std::size_t>{2}));
}

TEST(PlacePropagation, NotWhereSomeoneCameInFrontNorAtAnotherDepthOrASureScore) {
  Sequence s = flickering_piece(30, {2, 9, 13, 17, 21, 25});
  // Frame 13: a person stands in front of the piece, covering three quarters of its box at 2.6 m.
  s.depth[13](cv::Rect(kPiece.x, kPiece.y, kPiece.width * 3 / 4, kPiece.height)).setTo(2600);
  s.frames[17][1].depth_mm = 3200;   // another layer (200 mm): not the same thing
  s.frames[21][1].probability = 0.97;  // the model is sure it is a person: as an n track, not entered
  s.frames[25][1].box = cv::Rect(310, 205, 40, 60);  // IoU 0.52 with the answered box: not the same pixels
  EXPECT_EQ(frames_of(propagate_place(s.frames, s.depth, {9, 1}, 'n', {})), (std::vector<std::size_t>{2}));
}

TEST(PlacePropagation, UndoOfTheAnswerRemovesItsPlaceLabelsToo) {
  test::TempDir dir;
  const std::string path = dir / "labeler-answers.tsv";
  const Sequence s = flickering_piece(20, {3, 8, 15});
  const CandidateKey seed{"room", "000008", kPiece};
  const auto key = [](std::size_t f, const cv::Rect& box) {
    return CandidateKey{"room", (f < 10 ? "00000" : "0000") + std::to_string(f), box};
  };
  {
    AnswerJournal journal(path);
    journal.record({seed, 'n', 7, "human"});
    const std::vector<TrackLink> place = propagate_place(s.frames, s.depth, {8, 1}, 'n', {});
    ASSERT_EQ(place.size(), 2u);
    for (const TrackLink& l : place) journal.record({key(l.frame, kPiece), 'n', -1, place_answerer(seed)});
    // Its track, had the piece been found in the next frame too, and another answer.
    journal.record({key(9, kPiece), 'n', -1, track_answerer(seed)});
    journal.record({key(4, s.frames[4][0].box), 'y', -1, "human"});
    EXPECT_EQ(journal.answers_in_force(), 5u);
  }
  EXPECT_EQ(place_answerer(seed), "place 000008 300,200,40,60");
  // Replayed after a restart: the answer's place and track labels, oldest first; undone, newest first, then
  // the answer itself (as the session's u does).
  AnswerJournal journal(path);
  const std::vector<JournalEntry> labels = propagated_from(journal, seed);
  ASSERT_EQ(labels.size(), 3u);
  EXPECT_EQ(labels[0].by, place_answerer(seed));
  EXPECT_EQ(labels[2].by, track_answerer(seed));
  std::for_each(labels.rbegin(), labels.rend(), [&](const JournalEntry& e) { journal.record_undo(e); });
  journal.record_undo({seed, 'n', 7, "human"});
  EXPECT_EQ(journal.answers_in_force(), 1u);
  EXPECT_EQ(journal.answer_of(key(4, s.frames[4][0].box)), 'y');  // the other answer stays
  EXPECT_TRUE(propagated_from(AnswerJournal(path), seed).empty());
}
