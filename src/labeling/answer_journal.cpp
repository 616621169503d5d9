#include "rdsf/labeling/answer_journal.hpp"

#include <cstdio>
#include <filesystem>
#include <iterator>
#include <sstream>
#include <tuple>

#include "rdsf/core/append_only_log.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/utc_time.hpp"

namespace rdsf {
namespace {

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::stringstream in(line);
  while (std::getline(in, field, '\t')) fields.push_back(field);
  if (!line.empty() && line.back() == '\t') fields.emplace_back();
  return fields;
}

bool parse_long(const std::string& text, long long& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtoll(text.c_str(), &end, 10);
  return *end == '\0';
}

const char* kHeader = "time\tsource\tframe\tx\ty\tw\th\tanswer\tsample_id\tby";

}  // namespace

bool CandidateKey::operator<(const CandidateKey& o) const {
  return std::tie(source, frame, box.x, box.y, box.width, box.height) <
         std::tie(o.source, o.frame, o.box.x, o.box.y, o.box.width, o.box.height);
}

AnswerJournal::AnswerJournal(const std::string& path) : path_(path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    append_line_synced(path_, kHeader);
    return;
  }
  const LogLines read = read_log_lines(path);
  for (std::size_t i = 0; i < read.lines.size(); ++i) {
    const std::string& line = read.lines[i];
    const std::string where = "line " + std::to_string(i + 1);
    if (i == 0) {
      if (line != kHeader) fail(path, "line 1: not a labeler answer journal");
      continue;
    }
    const std::vector<std::string> f = split_tabs(line);
    long long x = 0, y = 0, w = 0, h = 0, id = 0;
    if (f.size() != 10 || f[7].size() != 1 || !parse_long(f[3], x) || !parse_long(f[4], y) ||
        !parse_long(f[5], w) || !parse_long(f[6], h) || !parse_long(f[8], id)) {
      fail(path, where + ": malformed answer row");
    }
    const char answer = f[7][0];
    const CandidateKey key{f[1], f[2], cv::Rect(static_cast<int>(x), static_cast<int>(y), static_cast<int>(w),
                                                static_cast<int>(h))};
    if (answer == 'u') {
      if (!forget(key)) fail(path, where + ": undo of a candidate never answered");
      continue;
    }
    if (answer != 'y' && answer != 'n' && answer != 's') fail(path, where + ": unknown answer '" + f[7] + "'");
    answered_.insert(key);
    in_force_.push_back({key, answer, id, f[9]});
  }
  // A line torn by a kill was never acknowledged: cut it off so the next answer starts a line of its own.
  if (read.torn_tail) {
    cut_torn_tail(path, read.complete_bytes);
    if (read.lines.empty()) append_line_synced(path_, kHeader);
  }
}

char AnswerJournal::answer_of(const CandidateKey& key) const {
  if (!answered(key)) return '\0';
  for (auto it = in_force_.rbegin(); it != in_force_.rend(); ++it) {
    if (it->key == key) return it->answer;
  }
  return '\0';
}

void AnswerJournal::append_line(const std::string& line) { append_line_synced(path_, line); }

void AnswerJournal::record(const JournalEntry& e) {
  const cv::Rect& b = e.key.box;
  append_line(utc_now_iso8601() + "\t" + e.key.source + "\t" + e.key.frame + "\t" + std::to_string(b.x) + "\t" +
              std::to_string(b.y) + "\t" + std::to_string(b.width) + "\t" + std::to_string(b.height) + "\t" +
              std::string(1, e.answer) + "\t" + std::to_string(e.sample_id) + "\t" + e.by);
  answered_.insert(e.key);
  in_force_.push_back(e);
}

bool AnswerJournal::forget(const CandidateKey& key) {
  for (auto it = in_force_.rbegin(); it != in_force_.rend(); ++it) {
    if (it->key == key) {
      in_force_.erase(std::next(it).base());
      answered_.erase(answered_.find(key));
      return true;
    }
  }
  return false;
}

std::size_t AnswerJournal::finish_interrupted_undos(const std::function<bool(std::int64_t)>& in_set) {
  std::vector<JournalEntry> undone;
  for (const JournalEntry& e : in_force_) {
    if (e.sample_id >= 0 && !in_set(e.sample_id)) undone.push_back(e);
  }
  for (auto it = undone.rbegin(); it != undone.rend(); ++it) record_undo(*it);
  return undone.size();
}

void AnswerJournal::record_undo(const JournalEntry& undone) {
  if (!answered(undone.key)) throw Error(path_ + ": undo of a candidate that has no answer");
  const cv::Rect& b = undone.key.box;
  append_line(utc_now_iso8601() + "\t" + undone.key.source + "\t" + undone.key.frame + "\t" + std::to_string(b.x) +
              "\t" + std::to_string(b.y) + "\t" + std::to_string(b.width) + "\t" + std::to_string(b.height) +
              "\tu\t" + std::to_string(undone.sample_id) + "\t" + undone.by);
  forget(undone.key);
}

}  // namespace rdsf
