#pragma once
// Guards for the YAML files the workbench reads through cv::FileStorage (sample-set manifests, model
// files), found by fuzzing (fuzz/, scripts/fuzz.sh).
#include <string>

namespace rdsf {

/// `text` on one printable line for an Error message: control characters (a line break in text quoted from
/// the file, in an OpenCV message) become \n, \r or \xNN.
std::string one_line(const std::string& text);

/// OpenCV 4.6's YAML reader never returns on some damaged files: when the top-level collection ends before
/// the end of the text (it starts indented, or text follows the "---" marker on its line) and a line
/// starting with '-' follows (inputs in fuzz/regressions/). The workbench writes "%YAML:1.0", "---" alone on
/// its line, then the top-level entries from column 1 to the end of the file, so any other layout is refused
/// before OpenCV sees the text. Returns the problem ("line N: ...") or "".
std::string yaml_layout_problem(const std::string& text);

}  // namespace rdsf
