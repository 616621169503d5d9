#pragma once
// What rdsf-train makes of its samples before boosting: validation groups and the positives' augmentation.
// Each parameter is declared once, as a row of training_data_parameters() (core/parameter_table.hpp), from
// which rdsf-train's options, their checks, --help and the --thesis preset are made; the recipe does not
// set them. The model file records group_frames, group_by and the augmentation as applied
// (CropAugmentation::describe(), with the recipe's seed).
#include <string>

#include "rdsf/core/parameter_table.hpp"

namespace rdsf {

struct TrainingDataParams {
  /// Validation groups: a recording's frames in blocks of this many (dataset/sample_groups.hpp); 0 = no
  /// groups, the validation split is by sample (near-identical crops on both sides).
  int group_frames = 30;
  std::string group_by = "recording-block";  ///< recording-block, block or recording (parse_group_by)
  /// Positives augmented at training time: "off", or a comma list of mirror, shift, scale, occlusion
  /// (parse_augmentation; mirror chosen by the quality report). The thesis: off.
  std::string augment = "mirror";
  int augment_copies = 0;  ///< random variants per positive (shift / scale / occlusion), besides the mirror
};

/// The rows of TrainingDataParams, in --help's order.
const ParameterTable<TrainingDataParams>& training_data_parameters();

}  // namespace rdsf
