#include "rdsf/evaluation/adaptation_results.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/curve_plot.hpp"

namespace rdsf {
namespace {

constexpr double kLargest = 1e9;

// The whole field as a finite number in [0, max]; false otherwise (empty, trailing text, nan, inf).
bool number(const std::string& field, double max, double& value) {
  if (field.empty() || field.size() > 64 || std::isspace(static_cast<unsigned char>(field[0]))) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtod(field.c_str(), &end);
  return errno == 0 && end == field.c_str() + field.size() && std::isfinite(value) && value >= 0 && value <= max;
}

bool whole(const std::string& field, long& value) {
  double v = 0;
  if (!number(field, kLargest, v) || v != std::floor(v)) return false;
  value = static_cast<long>(v);
  return true;
}

}  // namespace

const std::string& adaptation_results_header() {
  static const std::string header = "room\tmode\tbudget\tanswers\tpropagated\tpropagated_wrong\ttar\ttrain_s";
  return header;
}

std::vector<AdaptationResult> parse_adaptation_results(const std::string& text, const std::string& path) {
  std::vector<AdaptationResult> results;
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != adaptation_results_header()) {
    fail(path, "line 1: not the header of the adaptation benchmark's results (room, mode, budget, answers, "
               "propagated, propagated_wrong, tar, train_s)");
  }
  for (int number_of_line = 2; std::getline(in, line); ++number_of_line) {
    const std::string where = "line " + std::to_string(number_of_line) + ": ";
    std::vector<std::string> f;
    std::size_t start = 0;
    for (std::size_t tab; (tab = line.find('\t', start)) != std::string::npos; start = tab + 1) {
      f.push_back(line.substr(start, tab - start));
    }
    f.push_back(line.substr(start));
    if (f.size() != 8) fail(path, where + std::to_string(f.size()) + " fields, not 8");
    AdaptationResult r;
    r.room = f[0];
    r.mode = f[1];
    if (r.mode.empty() || r.mode.find_first_of("\r\n") != std::string::npos) fail(path, where + "no mode");
    if (!whole(f[2], r.budget)) fail(path, where + "budget is not a whole number from 0 to 1e9");
    if (!number(f[3], kLargest, r.answers)) fail(path, where + "answers is not a number from 0 to 1e9");
    if (!whole(f[4], r.propagated) || !whole(f[5], r.propagated_wrong)) {
      fail(path, where + "propagated or propagated_wrong is not a whole number from 0 to 1e9");
    }
    if (!number(f[6], 1.0, r.tar)) fail(path, where + "tar is not a number from 0 to 1");
    if (!number(f[7], kLargest, r.train_s)) fail(path, where + "train_s is not a number of seconds from 0 to 1e9");
    results.push_back(r);
  }
  return results;
}

std::vector<AdaptationResult> read_adaptation_results(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_adaptation_results(text.str(), path);
}

cv::Mat3b draw_adaptation_chart(const std::vector<AdaptationResult>& results) {
  struct Sum {
    double answers = 0, tar = 0;
    int rooms = 0;
  };
  std::map<std::string, std::map<long, Sum>> modes;  // mode -> budget -> sums over the rooms
  for (const AdaptationResult& r : results) {
    Sum& s = modes[r.mode][r.budget];
    s.answers += r.answers;
    s.tar += r.tar;
    ++s.rooms;
  }
  PlotAxes axes;
  axes.title = "Answers spent against TAR at FPPF <= 0.1, mean over rooms";
  axes.x_label = "answers (the truth as the person)";
  axes.y_label = "TAR at FPPF <= 0.1";
  axes.x_max = 1;
  axes.y_min = 0;
  std::vector<PlotCurve> curves;
  for (const auto& [mode, budgets] : modes) {
    PlotCurve c;
    c.label = mode;
    for (const auto& [budget, s] : budgets) {
      c.points.emplace_back(s.answers / s.rooms, s.tar / s.rooms);
      axes.x_max = std::max(axes.x_max, s.answers / s.rooms * 1.1);
    }
    if (c.points.size() == 1) c.operating_point = c.points.front();  // a single point is marked
    curves.push_back(c);
  }
  return draw_plot(axes, curves);
}

}  // namespace rdsf
