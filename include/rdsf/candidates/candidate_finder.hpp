#pragma once
// Step 2 of the frame analyser: the upright objects of each depth layer that are tall and wide enough in
// real centimetres, as candidates with their boxes and 64x128 crops.
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/candidates/candidate_params.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/segmentation/depth_layers.hpp"

namespace rdsf {

/// Whether candidates get their colour crop when they are found. `later`: colour_crop stays empty, and
/// cut_colour_crop() cuts it for the candidates that need one (the pipeline: its detections, whose colour
/// histograms tracking reads); the pixels are the same either way.
enum class CropColour { cut, later };

/// Finds the candidates of every layer of `segmentation` (computed on `frame`). Crops are `crop_size`
/// (64x128 for RDSF). Candidates are ordered by layer (nearest first), then left to right.
std::vector<Candidate> find_candidates(const DepthFrame& frame, const Segmentation& segmentation,
                                       const CandidateParams& params, cv::Size crop_size = {64, 128},
                                       CropColour colour = CropColour::cut);

/// Cuts `window` (may leave the image) out of `labels`/`depth_mm`/`bgr`, keeping only pixels of `layer`,
/// and resizes it to `crop_size` by nearest neighbour. Fills candidate.depth_crop, and colour_crop when the
/// frame has colour and `colour` is `cut` (else colour_crop is emptied).
void cut_crops(const DepthFrame& frame, const cv::Mat1b& labels, int layer, const cv::Rect& window,
               cv::Size crop_size, Candidate& candidate, CropColour colour = CropColour::cut);

/// The colour crop cut_crops() would have cut for `candidate` (its layer and window_unclipped, the size
/// of its depth crop), from the frame and the labels it was found in; empty when the frame has no colour.
void cut_colour_crop(const DepthFrame& frame, const cv::Mat1b& labels, Candidate& candidate);

/// Intersection over union of two boxes (0 when either is empty).
double iou(const cv::Rect& a, const cv::Rect& b);

}  // namespace rdsf
