#include "rdsf/evaluation/ground_truth.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::stringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

long parse_int(const std::string& text, const std::string& where, const std::string& column) {
  if (text.empty()) fail(where, "empty " + column);
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (*end != '\0' || errno != 0 || value < -1000000 || value > 1000000) {
    fail(where, column + " is not a whole number: '" + text + "'");
  }
  return value;
}

double parse_fraction(const std::string& text, const std::string& where) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value >= 0.0 && value <= 1.0)) {
    fail(where, "visible_fraction is not a number in [0, 1]: '" + text + "'");
  }
  return value;
}

}  // namespace

std::size_t GroundTruth::people() const {
  std::size_t n = 0;
  for (const auto& [frame, boxes] : frames) n += boxes.size();
  return n;
}

const std::vector<TruthBox>& GroundTruth::in(const std::string& frame) const {
  static const std::vector<TruthBox> none;
  const auto it = frames.find(frame);
  return it == frames.end() ? none : it->second;
}

TruthOverlap truth_overlap(const cv::Rect& box, const std::vector<TruthBox>& people) {
  TruthOverlap overlap;
  for (const TruthBox& person : people) {
    double& best = person.ignored ? overlap.ignored : overlap.counted;
    best = std::max(best, iou(box, person.box));
  }
  return overlap;
}

std::size_t truth_frames_not_in(const GroundTruth& truth, const std::string& truth_path,
                                const std::vector<std::string>& names, const std::string& source) {
  if (truth.frames.empty() || names.empty()) return 0;
  const std::set<std::string> named(names.begin(), names.end());
  std::size_t absent = 0;
  for (const auto& [frame, people] : truth.frames) absent += named.count(frame) == 0 ? 1 : 0;
  if (absent == truth.frames.size()) {
    fail(truth_path, "names none of the " + std::to_string(names.size()) + " frames of " + source + " (it names e.g. '" +
                         truth.frames.begin()->first + "', the source's first frame is '" + names.front() +
                         "'; a bag's or a recording's frames are named by their index 0, 1, ...)");
  }
  return absent;
}

std::size_t ignore_hardly_visible(GroundTruth& truth, double min_visible_fraction) {
  std::size_t ignored = 0;
  for (auto& [frame, boxes] : truth.frames) {
    for (TruthBox& box : boxes) {
      box.ignored = box.visible_fraction < min_visible_fraction;
      ignored += box.ignored ? 1 : 0;
    }
  }
  return ignored;
}

GroundTruth parse_ground_truth(const std::string& text, const std::string& name) {
  std::stringstream in(text);
  std::string line;
  if (!std::getline(in, line)) fail(name, "empty file (expected a header frame,person,x,y,w,h)");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> header = split(line);
  std::map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < header.size(); ++i) column[header[i]] = i;
  for (const char* required : {"frame", "person", "x", "y", "w", "h"}) {
    if (!column.count(required)) fail(name, std::string("line 1: header has no '") + required + "' column");
  }
  GroundTruth truth;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::string where = name + ": line " + std::to_string(line_number);
    const std::vector<std::string> fields = split(line);
    if (fields.size() != header.size()) {
      fail(where, std::to_string(fields.size()) + " fields, the header has " + std::to_string(header.size()));
    }
    TruthBox box;
    const std::string& frame = fields[column["frame"]];
    if (frame.empty()) fail(where, "empty frame name");
    box.person = static_cast<int>(parse_int(fields[column["person"]], where, "person"));
    box.box = cv::Rect(static_cast<int>(parse_int(fields[column["x"]], where, "x")),
                       static_cast<int>(parse_int(fields[column["y"]], where, "y")),
                       static_cast<int>(parse_int(fields[column["w"]], where, "w")),
                       static_cast<int>(parse_int(fields[column["h"]], where, "h")));
    if (box.box.width <= 0 || box.box.height <= 0) fail(where, "box has no area");
    box.track = column.count("track") ? static_cast<int>(parse_int(fields[column["track"]], where, "track"))
                                      : box.person;
    if (column.count("visible_fraction")) box.visible_fraction = parse_fraction(fields[column["visible_fraction"]], where);
    truth.frames[frame].push_back(box);
  }
  return truth;
}

GroundTruth read_ground_truth(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened for reading");
  std::stringstream text;
  text << in.rdbuf();
  return parse_ground_truth(text.str(), path);
}

}  // namespace rdsf
