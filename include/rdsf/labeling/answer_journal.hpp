#pragma once
// The labeler's record of every answer, so that a killed or resumed labeler never shows an answered
// candidate again: an append-only TSV (flushed and synced per answer) in the sample set's folder,
//   labeler-answers.tsv: time, source, frame, x, y, w, h, answer, sample_id, by
// answer: y (person), n (not a person), s (skipped), u (undoes the latest answer in force for that candidate);
// sample_id: the sample the answer stored (-1: none); by: "human", "truth" (assisted mode) or the model
// that answered, "model NAME/vN H=<score> P=<probability>" (model answers).
// A torn last line (killed mid-write) is ignored when the journal is read.
#include <cstdint>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

/// The identity of a candidate across runs: where it came from and its strict box.
struct CandidateKey {
  std::string source, frame;
  cv::Rect box;
  bool operator<(const CandidateKey& o) const;
  bool operator==(const CandidateKey& o) const { return !(*this < o) && !(o < *this); }
};

struct JournalEntry {
  CandidateKey key;
  char answer = 's';  ///< 'y', 'n', 's'
  std::int64_t sample_id = -1;
  std::string by = "human";
};

class AnswerJournal {
 public:
  /// Opens (creating) the journal at `path` and replays it. Throws Error naming the file and line on a bad
  /// row other than a torn last one.
  explicit AnswerJournal(const std::string& path);

  bool answered(const CandidateKey& key) const { return answered_.count(key) > 0; }
  /// The answer in force for `key` ('y', 'n', 's'), '\0' when none.
  char answer_of(const CandidateKey& key) const;
  /// Appends an answer (flushed and synced before returning).
  void record(const JournalEntry& entry);
  /// Appends an undo of `undone`'s answer (the most recent one in force for its candidate).
  void record_undo(const JournalEntry& undone);
  std::size_t answers_in_force() const { return in_force_.size(); }
  /// The answers in force (replayed and recorded, undone ones removed), oldest first.
  const std::vector<JournalEntry>& in_force() const { return in_force_; }
  /// Finishes undos cut short: an answer in force whose sample is no longer in the set (`in_set` says which
  /// ids are) was undone there (the retraction is written first) but its journal line was lost to a failed
  /// write or a power cut; its undo is appended now. Returns how many.
  std::size_t finish_interrupted_undos(const std::function<bool(std::int64_t)>& in_set);
  const std::string& path() const { return path_; }

 private:
  void append_line(const std::string& line);
  bool forget(const CandidateKey& key);
  std::string path_;
  std::vector<JournalEntry> in_force_;  ///< replayed answers, oldest first
  std::multiset<CandidateKey> answered_;
};

}  // namespace rdsf
