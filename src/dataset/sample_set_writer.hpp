#pragma once
// Appends samples to a sample set (format in sample_set.hpp and datasets/README.md), holding the set's
// lock for its lifetime so that a second writer is refused.
//
// Durability: a sample's crop files are written first (temporary name + rename), then its row is appended
// to samples.tsv, flushed and fdatasync'ed before append() returns. A writer killed at any moment leaves a
// readable set that has lost at most the sample in flight. Reopening cuts off a torn last row and removes
// crops and vectors of samples whose row was never written.
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include <opencv2/core.hpp>

#include "dataset/sample_crop.hpp"
#include "dataset/sample_record.hpp"
#include "dataset/sample_set_lock.hpp"
#include "dataset/sample_set_manifest.hpp"

namespace rdsf {

class SampleSetWriter {
 public:
  /// Opens the set in `dir` for appending, creating it (and the folder) when it does not exist yet.
  /// An existing set must have the same feature spec (throws Error naming both hashes otherwise). A folder
  /// that exists but is not a sample set (other files, no manifest.yml) is refused.
  static SampleSetWriter open_or_create(const std::string& dir, const FeatureSpec& spec, const CameraModel& camera,
                                        const std::string& created_by);
  /// Opens an existing set for appending; throws Error when `dir` holds no sample set.
  static SampleSetWriter open_existing(const std::string& dir);

  SampleSetWriter(SampleSetWriter&&) noexcept;
  SampleSetWriter& operator=(SampleSetWriter&&) noexcept;
  ~SampleSetWriter();

  /// Appends a sample with its crops and returns the record as stored: id assigned (the record's id is
  /// ignored), time set when empty, has_crop, has_colour and crop_hash filled in. The depth crop must be
  /// window sized (CV_16UC1); the colour crop (CV_8UC3) is optional.
  SampleRecord append(SampleRecord record, const cv::Mat1w& depth_crop, const cv::Mat3b& colour_crop = {});
  /// The same with crops already encoded (EncodedCrop::encode, e.g. on worker threads). With `sync` false
  /// the row is written (a killed program keeps it) but fdatasync() is left to a later sync(), so that a
  /// batch (the miner: one frame's samples) costs one disk flush.
  SampleRecord append_encoded(SampleRecord record, const EncodedCrop& crop, bool sync = true);
  /// Flushes rows appended with sync = false to disk.
  void sync();
  /// Appends a sample without crop whose feature vector (dimension() floats of the set's feature spec) is
  /// stored instead (has_crop = false).
  SampleRecord append_vector(SampleRecord record, const float* features);

  /// Takes back sample `id` (the labeler's undo): its retraction is appended to retracted.tsv (flushed to
  /// disk) and readers leave it out from then on; its row and crops stay for inspection. Throws Error when
  /// the set holds no such sample (or it was retracted already).
  void retract(std::int64_t id);

  /// True when a sample with the same label and the same place (source, frame, strict box) or the same
  /// depth crop (crop_hash, when set) is already in the set. Used by the miner, merge and import to skip
  /// exact duplicates.
  bool is_duplicate(const SampleRecord& record) const;

  const std::vector<SampleRecord>& records() const;
  const SampleSetManifest& manifest() const;
  const std::string& dir() const;
  int dimension() const;
  /// True when opening cut off a row torn by a killed writer.
  bool recovered_torn_row() const;
  /// True when the lock of a killed writer was taken over; stale_holder() says whose.
  bool took_over_stale_lock() const;
  std::string stale_holder() const;
  /// Releases the lock (also done by the destructor). No append is possible afterwards.
  void close();

 private:
  struct State;
  explicit SampleSetWriter(std::unique_ptr<State> state);
  static SampleSetWriter open_locked(const std::string& dir, SampleSetLock lock);
  SampleRecord prepare(SampleRecord record) const;
  void append_row(const SampleRecord& record, bool sync);
  std::unique_ptr<State> state_;
};

}  // namespace rdsf
