#pragma once
// The candidates a background model adds (segmentation/background_model.hpp): the objects each depth layer
// has among the pixels in front of the room, shaped by find_candidates() like any layer's, appended BESIDE
// the layers' own candidates (never replacing them: a free-standing person keeps the candidate they had).
// A person within half a metre of a wall shares its layer; in front of the room they stand alone, so
// their box reaches the floor instead of the waist, or exists at all where they joined the wall.
//
// Each added candidate has Candidate::foreground set, its crops hold only the foreground pixels of its layer
// (cut from the foreground segmentation's labels), and against the layers' candidates of the same layer:
//   strict boxes' IoU and fitted boxes' IoU both >= kDuplicateIou
//                          the same object found twice: not added (a candidate whose strict box is the
//                          same but whose fitted box differs is kept: the layer's object reached over the
//                          wall or a neighbour beside the person, which the foreground leaves out);
//   else, the candidate of the largest strict-box IoU, when >= kPieceIou
//                          its object's piece (Candidate::object its, part = true), so that of the two, as
//                          detections, only the higher-scoring one counts (duplicate_candidates.hpp: a
//                          whole object and a piece of it);
//   else                   an object of its own (Candidate::object after every layer object's; pieces of
//                          one foreground object share one).
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/candidates/candidate_params.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/segmentation/depth_layers.hpp"

namespace rdsf {

constexpr double kDuplicateIou = 0.7;
constexpr double kPieceIou = 0.3;

/// Appends to `candidates` (the layers' own, from find_candidates() on the frame's segmentation) the
/// candidates of `in_front` (segmentation/background_model.hpp's in_front_of() of that segmentation) by
/// the rule above. Returns how many were added.
std::size_t add_foreground_candidates(const DepthFrame& frame, const Segmentation& in_front,
                                      const CandidateParams& params, cv::Size crop_size, CropColour colour,
                                      std::vector<Candidate>& candidates);

}  // namespace rdsf
