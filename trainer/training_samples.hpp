#pragma once
// The samples a training run uses: the wanted class taken from each given sample set (positives from the
// --pos sets, negatives from the --neg sets), a seeded subset when fewer are asked for than the sets hold
// (with a clear warning when they hold fewer than asked), and their feature rows.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/training_record.hpp"
#include "rdsf/features/feature_spec.hpp"
#include "rdsf/dataset/crop_augmentation.hpp"
#include "rdsf/dataset/sample_groups.hpp"

namespace rdsf {

struct SampleChoice {
  std::vector<std::string> pos_sets, neg_sets;
  std::size_t positives = 0, negatives = 0;  ///< wanted; 0 = all
  std::uint64_t seed = 1;
  std::string asked_by;  ///< "recipe tree2" or "--positives", for the warning
  std::string role_prefix;  ///< "" for training, "validation-" for a separate validation set
  /// The feature spec the sets must have; empty: the first set's (all must agree).
  std::optional<FeatureSpec> spec;
  /// How the sets' crops must have been cut; unknown: as the first set that records it (all that record
  /// it must agree; sets that do not agree with any).
  CropProvenance crops;
  /// Features to compute (a pool, ascending); empty: feature_pool decides.
  std::vector<int> columns;
  /// 0: every feature when the rows fit in memory_budget_mb, else a seeded pool of as many as fit;
  /// N: a seeded pool of N features (all when the spec has no more).
  std::size_t feature_pool = 0;
  /// Features every pool must hold besides its seeded draw (continued training: the --init model's, whose
  /// scores are computed from the rows); ignored when the rows hold every feature.
  std::vector<int> required_features;
  std::size_t memory_budget_mb = 4096;  ///< for the float rows and their 8-bit bins (5 bytes per value)
  /// Validation groups: recording and block of this many consecutive frames (dataset/sample_groups.hpp);
  /// 0 = no groups (the validation split is by sample).
  int group_frames = 30;
  GroupBy group_by = GroupBy::recording_block;
  CropAugmentation augmentation;  ///< positives only; off by default
  /// Data-parallel training (issue 37): this process is rank `shard` of `shards` and computes the feature
  /// rows of its share only: each class's chosen samples in `shards` contiguous blocks of (nearly) equal
  /// size, in order (rank r holds block r), an augmented copy where its original is. Everything else
  /// (labels, groups, sets) is of every row. 1: one process, every row.
  int shard = 0, shards = 1;
};

struct ChosenSamples {
  FeatureSpec spec;         ///< of the sets
  CropProvenance crops;     ///< how the sets' crops were cut (unknown when none records it)
  /// The analyser options the sets' candidates were found with, when every set records the same; else none.
  RecordedParameters analyser_options;
  std::vector<int> columns; ///< feature of each column when the rows hold a pool; empty: all features
  cv::Mat1f rows;           ///< one feature row per sample, positives first (this rank's rows only)
  std::vector<int> labels;  ///< 1 / 0
  std::vector<SampleSetUse> sets;  ///< per set and role: path, manifest hash, available, used
  std::vector<std::size_t> groups;    ///< per row: group id (dataset/sample_groups.hpp)
  std::vector<SampleOrigin> origins;  ///< per row: its recording and frame, when grouped (group_frames > 0)
  std::vector<bool> augmented;        ///< per row: an augmented copy (after the originals)
  std::vector<int> owner;             ///< per row: the rank holding it (SampleChoice::shards); empty: one process
};


/// Reads the sets, picks the samples and computes (or reads) their features. Warnings go to `log`.
/// Throws Error when a set cannot be read, has another feature spec or crops cut differently (naming both),
/// or a class ends up empty.
ChosenSamples choose_samples(const SampleChoice& choice, std::ostream& log, int threads = 0);


}  // namespace rdsf
