#pragma once
// Step 2 of the detector core: the upright objects of each depth layer that are tall and wide enough in
// real centimetres, as candidates with their boxes and 64x128 crops.
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/candidates/candidate_params.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/segmentation/depth_layers.hpp"

namespace rdsf {

/// Finds the candidates of every layer of `segmentation` (computed on `frame`). Crops are `crop_size`
/// (64x128 for RDSF). Candidates are ordered by layer (nearest first), then left to right.
std::vector<Candidate> find_candidates(const DepthFrame& frame, const Segmentation& segmentation,
                                       const CandidateParams& params, cv::Size crop_size = {64, 128});

/// Cuts `window` (may leave the image) out of `labels`/`depth_mm`/`bgr`, keeping only pixels of `layer`,
/// and resizes it to `crop_size` by nearest neighbour. Fills candidate.depth_crop and colour_crop.
void cut_crops(const DepthFrame& frame, const cv::Mat1b& labels, int layer, const cv::Rect& window,
               cv::Size crop_size, Candidate& candidate);

/// Intersection over union of two boxes (0 when either is empty).
double iou(const cv::Rect& a, const cv::Rect& b);

}  // namespace rdsf
