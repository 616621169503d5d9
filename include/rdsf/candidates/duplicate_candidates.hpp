#pragma once
// Duplicates among scored candidates: a whole object and a piece cut out of it (CandidateParams's
// split_head.keep_whole, split.keep_whole) show the same pixels, so as detections they would count one
// person twice (one detection, one false positive) or give the tracker two people where there is one.
//
// The rule, greedy by score (highest first, ties in candidate order): a candidate is a duplicate when a
// higher-scoring candidate that is no duplicate comes from the same object and exactly one of the two is
// a piece. Pieces of one object never suppress each other (they are the people it was cut into), and
// candidates of different objects (other layers, other objects of the layer) never do.
//
// Invariant (why one pass serves every threshold): a candidate is suppressed only by higher-scoring ones,
// so the duplicates among the candidates scoring >= t are exactly the duplicates of the whole list that
// score >= t. The detections at threshold t are the candidates scoring >= t that are no duplicates, and
// the exact detection curve (exact_curve.hpp) stays one pass.
#include <vector>

#include "rdsf/candidates/candidate.hpp"

namespace rdsf {

/// What the rule needs of a candidate: its object (unique in the frame, -1: related to no other) and
/// whether it is a piece.
struct CandidateKin {
  int object = -1;
  bool part = false;
};

inline CandidateKin kin_of(const Candidate& candidate) { return {candidate.object, candidate.part}; }

/// Per candidate, 1 when it is a duplicate (`kin` and `scores` have one entry per candidate).
std::vector<char> duplicate_candidates(const std::vector<CandidateKin>& kin, const std::vector<double>& scores);

}  // namespace rdsf
