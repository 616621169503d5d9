#pragma once
// Appends samples to a sample set (format in sample_set.hpp and datasets/README.md), holding the set's
// lock for its lifetime so that a second writer is refused.
//
// Durability (core/durable_io): a sample's crop files are written under a temporary name, fdatasync'ed,
// renamed and the crops folder fsync'ed; then its row is appended to samples.tsv and fdatasync'ed before
// append() returns: a sample reported as saved survives a killed program and a power cut. A batch
// (append_encoded with sync = false) renames its crops at once and syncs them, the folder and the rows in
// sync(); a batch never holds more than kMaxUnsyncedRows rows (the writer syncs first), so every row a
// power cut can leave without its crop is among the last rows that opening decodes (repair 3). Writes that fail (disk full, I/O error) throw Error naming the file and the cause, and the writer
// refuses further appends until the set is reopened.
//
// Repairs on open (each reported in repairs(), one line each; never a row whose crop is valid):
//   1. a torn last row of samples.tsv or retracted.tsv (no newline: never reported as saved) is cut off;
//   2. temporary files (*.tmp) in crops/, and crops and stored vectors of ids past the last row (a sample
//      whose row was never written) are removed;
//   3. a row whose depth crop is missing or empty, or (for the last 64 rows, decoded) truncated, of the
//      wrong size or type, or not matching its crop_hash, is retracted (retracted.tsv, with the reason in a
//      third column); its row and files stay for inspection. rdsf-samples --check checks every row.
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/dataset/sample_crop.hpp"
#include "rdsf/dataset/sample_record.hpp"
#include "rdsf/dataset/sample_set_lock.hpp"
#include "rdsf/dataset/sample_set_manifest.hpp"

namespace rdsf {

class SampleSetWriter {
 public:
  /// Rows appended with sync = false that may wait for one sync(); the last this many rows of a set are
  /// decoded and hashed when it is opened (repair 3), so a batch is always checked whole.
  static constexpr std::size_t kMaxUnsyncedRows = 64;

  /// Opens the set in `dir` for appending, creating it (and the folder) when it does not exist yet.
  /// An existing set must have the same feature spec (throws Error naming both hashes otherwise) and, when
  /// both are known, crops cut the same way (`crops`: crop_provenance(detector params); unknown for samples
  /// without crops) and candidates found with the same analyser options (`analyser_options`: every option's
  /// (key, text), stated_options(params); empty: not known). A new set records both. A folder that exists
  /// but is not a sample set (other files, no manifest.yml) is refused.
  static SampleSetWriter open_or_create(const std::string& dir, const FeatureSpec& spec, const CameraModel& camera,
                                        const std::string& created_by, const CropProvenance& crops = {},
                                        const RecordedParameters& analyser_options = {});
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
  /// Flushes rows appended with sync = false (and their crops) to disk.
  void sync();
  /// Rows appended with sync = false since the last sync() (at most kMaxUnsyncedRows).
  std::size_t unsynced_rows() const;
  /// Appends a sample without crop whose feature vector (dimension() floats of the set's feature spec) is
  /// stored instead (has_crop = false).
  SampleRecord append_vector(SampleRecord record, const float* features);

  /// Takes back sample `id` (the labeler's undo): its retraction is appended to retracted.tsv (flushed to
  /// disk) and readers leave it out from then on; its row and crops stay for inspection. Throws Error when
  /// the set holds no such sample (or it was retracted already).
  void retract(std::int64_t id, const std::string& reason = "");

  /// True when a sample with the same label and the same place (source, frame, strict box) or the same
  /// depth crop (crop_hash, when set) is already in the set. Used by the miner, merge and import to skip
  /// exact duplicates.
  bool is_duplicate(const SampleRecord& record) const;
  /// The id of the sample in force with the same label and place (source, frame, strict box), or -1. The
  /// labeler uses it for a sample saved whose journal line was lost (a failed write, a power cut).
  std::int64_t id_at_place(const SampleRecord& record) const;

  const std::vector<SampleRecord>& records() const;
  const SampleSetManifest& manifest() const;
  const std::string& dir() const;
  int dimension() const;
  /// True when opening cut off a row torn by a killed writer.
  bool recovered_torn_row() const;
  /// What opening repaired (rules above), one line each, e.g. "sample 7: retracted (crop missing, ...)".
  const std::vector<std::string>& repairs() const;
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
  void write_crop_unsynced(const std::string& path, const std::vector<unsigned char>& bytes);
  void sync_crops();
  std::unique_ptr<State> state_;
};

}  // namespace rdsf
