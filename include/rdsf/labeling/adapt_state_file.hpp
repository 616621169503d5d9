#pragma once
// rdsf-adapt's state file, OUT/adapt-state.tsv (adapt/adapt_state.hpp keeps it): one "KEY<TAB>VALUE" line
// per key, sorted by key, each line ending in '\n'. A key is not empty and holds no tab; neither key nor value
// holds '\n' or '\r'. The last line of a key wins. The file is always rewritten whole (core/atomic_file), so
// a torn line is damage, not an interrupted write.
#include <map>
#include <string>

namespace rdsf {

using AdaptStateValues = std::map<std::string, std::string>;

/// Parses the text of `path`; throws Error "PATH: line N: ..." on a line that is not KEY<TAB>VALUE.
AdaptStateValues parse_adapt_state(const std::string& text, const std::string& path);

/// Reads `path` (an absent file is empty: a first run); throws Error naming it when it cannot be read or
/// does not parse.
AdaptStateValues read_adapt_state(const std::string& path);

/// The file's text for `values`; throws Error naming `path` when a key or value cannot be written (the rule
/// above), so that what is written always reads back the same.
std::string adapt_state_text(const AdaptStateValues& values, const std::string& path);

}  // namespace rdsf
