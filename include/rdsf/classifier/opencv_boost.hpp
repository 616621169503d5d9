#pragma once
// The OpenCV backend: cv::ml::Boost, REAL boosting with depth-1 trees (stumps), as the thesis trained its
// models. After training, the trees are read back as Stump weak classifiers, so a BoostedModel scores an
// OpenCV-trained model without cv::ml; the cv::ml model itself is kept as YAML (node "opencv_model") to
// be embedded in the model file. Scores equal predict(x, DTrees::PREDICT_SUM) (RAW_OUTPUT alone would
// return the class: OpenCV issue 8257).
//
// Only this file and the trainer need opencv_ml; BoostedModel does not.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/weak_classifier.hpp"

namespace rdsf {

struct OpenCvBoostParams {
  int rounds = 100;           ///< weak count
  double weight_trim = 0.0;   ///< fraction of weight trimmed per round (OpenCV weightTrimRate = 1 - this; 0 = off)
};

struct OpenCvBoostResult {
  std::vector<WeakClassifier> stumps;  ///< one per tree, in training order
  std::string yaml;                    ///< FileStorage YAML with the cv::ml::Boost under "opencv_model"
};

/// Trains on `rows` (one sample per row) with `labels` (1 person, 0 not). One call, no per-round progress.
OpenCvBoostResult train_opencv_boost(const cv::Mat1f& rows, const std::vector<int>& labels,
                                     const OpenCvBoostParams& params);

/// Scores `rows` with the embedded cv::ml::Boost itself (predict with PREDICT_SUM): the reference that the
/// stumps reproduce. Throws Error when `yaml` holds no OpenCV model.
std::vector<double> opencv_boost_scores(const std::string& yaml, const cv::Mat1f& rows);

}  // namespace rdsf
