#pragma once
// A sample set: a folder holding labelled person / not-person samples so that none is ever lost, each can
// be looked at and traced to where it came from, and features can be recomputed when the feature spec
// changes. The exact format is in datasets/README.md:
//   manifest.yml                 format, version, feature spec (hash), camera model, creation time
//   samples.tsv                  append-only index, one row per sample (SampleRecord)
//   crops/NNNNNNNN.depth.png     the 16-bit depth crop (window sized, 64x128), per sample with a crop
//   crops/NNNNNNNN.rgb.png       the colour crop, when the frame had colour
//   vectors.<spec hash>.f32      feature vectors of samples without crop (thesis text imports)
//   retracted.tsv                samples taken back (the labeler's undo); readers leave them out
//   lock                         present while a writer (SampleSetWriter) has the set open
// SampleSet reads a set (no lock: a set being appended to can be read; rows appended later are not seen).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/dataset/sample_record.hpp"
#include "rdsf/dataset/sample_set_manifest.hpp"
#include "rdsf/features/feature_spec.hpp"
#include "rdsf/features/feature_subset.hpp"
#include "rdsf/features/rdsf_extractor.hpp"

namespace rdsf {

class SampleSet {
 public:
  /// Reads the manifest and the index; throws rdsf::Error naming the file (and line) on any fault. A row
  /// torn by a killed writer at the end of the index is ignored (torn_tail() says so).
  static SampleSet open_read(const std::string& dir);

  const std::vector<SampleRecord>& records() const { return records_; }
  const std::string& dir() const { return dir_; }
  FeatureSpec feature_spec() const { return manifest_.feature_spec; }
  const SampleSetManifest& manifest() const { return manifest_; }
  /// Stable hash (16 hex digits) of manifest.yml's bytes.
  std::string manifest_hash() const { return manifest_hash_; }
  std::size_t count(int label) const;
  /// True when the index ended in a torn row (ignored).
  bool torn_tail() const { return torn_tail_; }
  /// Samples left out because they were retracted (retracted.tsv).
  std::size_t retracted_count() const { return retracted_; }

  /// Paths of a record's crops (the colour path is returned even when the record has no colour crop).
  std::string depth_crop_path(std::size_t index) const;
  std::string colour_crop_path(std::size_t index) const;
  /// The record's depth crop; throws Error naming the file when it is missing, not 16-bit, or not the size
  /// of the feature spec's window, or when the record has no crop.
  cv::Mat1w depth_crop(std::size_t index) const;
  /// The record's colour crop; empty when it has none.
  cv::Mat3b colour_crop(std::size_t index) const;

  /// Feature rows (indices.size() x dimension, CV_32F) for the given record indices (all when empty),
  /// computed from the crops on `threads` threads (0: one per core), or read from the stored vectors of
  /// samples without crop (which exist only for the spec they were imported with: other specs throw).
  cv::Mat1f features(const RdsfExtractor& extractor, const std::vector<std::size_t>& indices = {},
                     int threads = 0) const;
  /// The same for only some features of a spec (subset.size() columns, in subset.features() order): crops
  /// compute just those; stored vectors are read whole and the columns picked.
  cv::Mat1f features(const FeatureSubset& subset, const std::vector<std::size_t>& indices = {},
                     int threads = 0) const;

 private:
  /// Rows of `columns` values per chosen sample: from_crop for samples with a crop; stored vectors of
  /// `spec` otherwise (all of them, or the columns `pick` when given).
  cv::Mat1f rows_of(const FeatureSpec& spec, int columns, const std::function<void(const cv::Mat1w&, float*)>& from_crop,
                    const std::vector<int>* pick, const std::vector<std::size_t>& indices, int threads) const;
  std::string dir_;
  SampleSetManifest manifest_;
  std::string manifest_hash_;
  std::vector<SampleRecord> records_;
  bool torn_tail_ = false;
  std::size_t retracted_ = 0;
};

}  // namespace rdsf
