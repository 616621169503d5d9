#pragma once
// rdsf-adapt's state file, OUT/adapt-state.tsv ("KEY<TAB>VALUE" lines, parsed by
// rdsf/labeling/adapt_state_file.hpp), rewritten whole (temporary name, synced, renamed: core/atomic_file)
// after every step, so that a killed run resumes at the first step not
// marked done ("done.STEP" = yes) and a rerun with another room or model name into the same folder is
// refused instead of mixing two rooms.
#include <map>
#include <string>

namespace rdsf {

class AdaptState {
 public:
  /// Reads OUT/adapt-state.tsv when it exists (creating OUT when not). Throws Error naming the file on a
  /// malformed line.
  explicit AdaptState(const std::string& out_dir);
  /// The value of `key`, or "" when unset.
  std::string get(const std::string& key) const;
  /// Sets `key` and writes the file (durably) before returning.
  void set(const std::string& key, const std::string& value);
  bool done(const std::string& step) const { return get("done." + step) == "yes"; }
  void mark_done(const std::string& step) { set("done." + step, "yes"); }
  /// Records `value` for `key` on the first run; on a rerun throws Error when it was another one.
  void pin(const std::string& key, const std::string& value);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::map<std::string, std::string> values_;
};

}  // namespace rdsf
