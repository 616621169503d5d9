#include "labeling/answer_journal.hpp"

#include <cstdio>
#include <iterator>
#include <sstream>
#include <tuple>

#include <fcntl.h>
#include <unistd.h>

#include "core/error.hpp"
#include "dataset/sample_record.hpp"

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
  std::ifstream in(path, std::ios::binary);
  if (in) {
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const bool complete_last_line = text.empty() || text.back() == '\n';
    std::stringstream lines(text);
    std::string line;
    int number = 0;
    std::vector<std::string> all;
    while (std::getline(lines, line)) all.push_back(line);
    for (std::size_t i = 0; i < all.size(); ++i) {
      ++number;
      const bool last = i + 1 == all.size();
      if (number == 1) {
        if (all[i] != kHeader) fail(path, "line 1: not a labeler answer journal");
        continue;
      }
      if (last && !complete_last_line) break;  // torn by a kill: the answer was never acknowledged
      const std::vector<std::string> f = split_tabs(all[i]);
      long long x = 0, y = 0, w = 0, h = 0, id = 0;
      if (f.size() != 10 || f[7].size() != 1 || !parse_long(f[3], x) || !parse_long(f[4], y) ||
          !parse_long(f[5], w) || !parse_long(f[6], h) || !parse_long(f[8], id)) {
        fail(path, "line " + std::to_string(number) + ": malformed answer row");
      }
      const char answer = f[7][0];
      const CandidateKey key{f[1], f[2], cv::Rect(static_cast<int>(x), static_cast<int>(y), static_cast<int>(w),
                                                  static_cast<int>(h))};
      if (answer == 'u') {
        if (!forget(key)) fail(path, "line " + std::to_string(number) + ": undo of a candidate never answered");
        continue;
      }
      if (answer != 'y' && answer != 'n' && answer != 's') {
        fail(path, "line " + std::to_string(number) + ": unknown answer '" + f[7] + "'");
      }
      JournalEntry entry{key, answer, id, f[9]};
      answered_.insert(entry.key);
      in_force_.push_back(entry);
    }
    if (!complete_last_line) {
      // Cut the torn line off so that the next append starts on a line of its own.
      std::ofstream rewrite(path + ".tmp", std::ios::binary | std::ios::trunc);
      const std::size_t keep = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
      rewrite << (keep == 0 ? std::string(kHeader) + "\n" : text.substr(0, keep));
      rewrite.close();
      if (std::rename((path + ".tmp").c_str(), path.c_str()) != 0) fail(path, "cannot repair torn last line");
    }
  } else {
    append_line(kHeader);
  }
}

void AnswerJournal::append_line(const std::string& line) {
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) fail(path_, "cannot be opened for appending");
  const std::string text = line + "\n";
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) && ::fdatasync(fd) == 0;
  ::close(fd);
  if (!ok) fail(path_, "write failed (disk full?)");
}

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

void AnswerJournal::record_undo(const JournalEntry& undone) {
  if (!answered(undone.key)) throw Error(path_ + ": undo of a candidate that has no answer");
  const cv::Rect& b = undone.key.box;
  append_line(utc_now_iso8601() + "\t" + undone.key.source + "\t" + undone.key.frame + "\t" + std::to_string(b.x) +
              "\t" + std::to_string(b.y) + "\t" + std::to_string(b.width) + "\t" + std::to_string(b.height) +
              "\tu\t" + std::to_string(undone.sample_id) + "\t" + undone.by);
  forget(undone.key);
}

}  // namespace rdsf
