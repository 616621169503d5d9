// The duplicate rule (duplicate_candidates.hpp): a whole object and a piece of it are one detection, the
// higher-scoring one; pieces of one object and candidates of different objects are all kept.
#include <gtest/gtest.h>

#include "rdsf/candidates/duplicate_candidates.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/detection_metrics.hpp"

namespace rdsf {
namespace {

const CandidateKin kWhole{0, false}, kLeft{0, true}, kRight{0, true};

TEST(DuplicateCandidates, TheWholeScoringHighestSuppressesItsPieces) {
  EXPECT_EQ(duplicate_candidates({kWhole, kLeft, kRight}, {3, 2, 1}), (std::vector<char>{0, 1, 1}));
}

TEST(DuplicateCandidates, APieceScoringHighestSuppressesTheWholeNotTheOtherPiece) {
  EXPECT_EQ(duplicate_candidates({kWhole, kLeft, kRight}, {2, 3, 1}), (std::vector<char>{1, 0, 0}));
  // The whole is suppressed by the left piece, so it suppresses nothing: the right piece stays.
  EXPECT_EQ(duplicate_candidates({kWhole, kLeft, kRight}, {2, 3, -5}), (std::vector<char>{1, 0, 0}));
}

TEST(DuplicateCandidates, OtherObjectsAndUnrelatedCandidatesAreNeverDuplicates) {
  const CandidateKin other_whole{1, false}, other_piece{1, true}, none{-1, false}, none_piece{-1, true};
  EXPECT_EQ(duplicate_candidates({kWhole, other_piece, none, none_piece}, {4, 3, 2, 1}), (std::vector<char>(4, 0)));
  EXPECT_EQ(duplicate_candidates({other_whole, kLeft}, {1, 2}), (std::vector<char>(2, 0)));
}

TEST(DuplicateCandidates, TiesGoToTheEarlierCandidate) {
  EXPECT_EQ(duplicate_candidates({kLeft, kWhole}, {1, 1}), (std::vector<char>{0, 1}));
  EXPECT_EQ(duplicate_candidates({kWhole, kLeft}, {1, 1}), (std::vector<char>{0, 1}));
}

TEST(DuplicateCandidates, CountsThatDoNotMatchAreAnError) {
  EXPECT_THROW(duplicate_candidates({kWhole}, {1, 2}), Error);
}

// Two people overlapping: the whole object matches the nearer (IoU >= 0.5), the pieces each person. A
// detector that reports the whole and a piece counts one person twice: one false positive.
TEST(DuplicateCandidates, DetectionFiguresCountTheWholeAndAPieceOnce) {
  GroundTruth truth;
  TruthBox a, b;
  a.box = cv::Rect(100, 0, 100, 200);
  b.box = cv::Rect(200, 0, 80, 200);
  truth.frames["f"] = {a, b};
  const cv::Rect whole(100, 0, 150, 200), left(100, 0, 100, 200), right(200, 0, 80, 200);
  FrameCandidates frame{"f", {{whole, 3, kWhole}, {left, 2, kLeft}, {right, 1, kRight}}};
  // The whole scores highest: it detects a, its pieces are duplicates (b is missed, no false positive).
  DetectionFigures f = detection_figures({frame}, truth, 0);
  EXPECT_EQ(f.n_det, 1);
  EXPECT_EQ(f.n_fp, 0);
  // Without kin every candidate is a detection: the whole takes a, the left piece is a false positive.
  for (ScoredCandidate& c : frame.candidates) c.kin = {};
  f = detection_figures({frame}, truth, 0);
  EXPECT_EQ(f.n_det, 2);
  EXPECT_EQ(f.n_fp, 1);
  // The pieces score highest: both people, the whole suppressed.
  frame.candidates = {{whole, 1, kWhole}, {left, 3, kLeft}, {right, 2, kRight}};
  f = detection_figures({frame}, truth, 0);
  EXPECT_EQ(f.n_det, 2);
  EXPECT_EQ(f.n_fp, 0);
}

}  // namespace
}  // namespace rdsf
