#include "rdsf/dataset/sample_groups.hpp"

#include <algorithm>
#include <filesystem>
#include <map>

#include "rdsf/core/error.hpp"

namespace rdsf {

std::string recording_of(const std::string& source) {
  namespace fs = std::filesystem;
  fs::path p = fs::path(source).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  const std::string name = p.filename().string();
  return name.empty() ? source : name;
}

GroupBy parse_group_by(const std::string& text) {
  if (text == "recording-block") return GroupBy::recording_block;
  if (text == "block") return GroupBy::block;
  if (text == "recording") return GroupBy::recording;
  throw Error("grouping '" + text + "' is not known (recording-block, block or recording)");
}

namespace {

// The frame's number when its name is one (at most 18 digits), else -1.
long long frame_number(const std::string& name) {
  if (name.empty() || name.size() > 18) return -1;
  long long n = 0;
  for (char c : name) {
    if (c < '0' || c > '9') return -1;
    n = n * 10 + (c - '0');
  }
  return n;
}

}  // namespace

SampleGroups sample_groups(const std::vector<SampleOrigin>& origins, int group_frames, GroupBy by) {
  if (group_frames < 1) throw Error("group frames must be at least 1 (" + std::to_string(group_frames) + " given)");
  std::map<std::string, std::vector<std::string>> frames;  // recording -> distinct frame names, sorted
  std::vector<std::string> recordings;
  recordings.reserve(origins.size());
  for (const SampleOrigin& o : origins) {
    recordings.push_back(recording_of(o.source));
    frames[recordings.back()].push_back(o.frame);
  }
  for (auto& entry : frames) {
    std::vector<std::string>& names = entry.second;
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
  }
  std::vector<std::string> keys;
  keys.reserve(origins.size());
  for (std::size_t i = 0; i < origins.size(); ++i) {
    if (by == GroupBy::recording) {
      keys.push_back(recordings[i]);
      continue;
    }
    const std::vector<std::string>& names = frames[recordings[i]];
    long long position = frame_number(origins[i].frame);
    if (position < 0) {
      position = std::lower_bound(names.begin(), names.end(), origins[i].frame) - names.begin();
    }
    const std::string block = "#" + std::to_string(position / group_frames);
    keys.push_back(by == GroupBy::block ? block : recordings[i] + block);
  }
  SampleGroups out;
  out.names = keys;
  std::sort(out.names.begin(), out.names.end());
  out.names.erase(std::unique(out.names.begin(), out.names.end()), out.names.end());
  for (const std::string& k : keys) {
    out.group.push_back(static_cast<std::size_t>(std::lower_bound(out.names.begin(), out.names.end(), k) - out.names.begin()));
  }
  return out;
}

}  // namespace rdsf
