#pragma once
// Wall-clock milliseconds of each stage of the system for one frame (the thesis's timing chapter, without
// "showing"), or summed over frames with +=. The frame analyser fills the first three; PeoplePipeline adds
// the classifier and tracking. total_ms() = the sum of the five.
#include <chrono>

namespace rdsf {

struct StageTimes {
  double segmentation_ms = 0;
  double candidates_ms = 0;     ///< candidate initialisation and filtering (column scan, boxes, crops)
  double features_ms = 0;       ///< RDSF of every candidate (or of the features the model reads)
  double classifier_ms = 0;
  double tracking_ms = 0;       ///< colour histograms (and the detections' colour crops) and matching
  double total_ms() const { return segmentation_ms + candidates_ms + features_ms + classifier_ms + tracking_ms; }
  StageTimes& operator+=(const StageTimes& o);
};

/// Milliseconds from `start` to now on the steady clock.
double milliseconds_since(std::chrono::steady_clock::time_point start);

}  // namespace rdsf
