#include "adapt/adapt_chart.hpp"

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/curve_plot.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace rdsf {

void write_adaptation_chart(const std::string& results_tsv, const std::string& png) {
  std::ifstream in(results_tsv);
  if (!in) fail(results_tsv, "cannot be read");
  struct Sum {
    double answers = 0, tar = 0;
    int rooms = 0;
  };
  std::map<std::string, std::map<long, Sum>> modes;  // mode -> budget -> sums over the rooms
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    if (++number == 1) continue;  // header
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, '\t');) f.push_back(x);
    try {
      if (f.size() != 8) throw std::invalid_argument("fields");
      Sum& s = modes[f[1]][std::stol(f[2])];
      s.answers += std::stod(f[3]);
      s.tar += std::stod(f[6]);
      ++s.rooms;
    } catch (const std::exception&) {
      fail(results_tsv, "line " + std::to_string(number) + ": not room, mode, budget, answers, propagated, "
                        "propagated_wrong, tar, train_s");
    }
  }
  PlotAxes axes;
  axes.title = "Answers spent against TAR at FPPF <= 0.1, mean over rooms";
  axes.x_label = "answers (the truth as the person)";
  axes.y_label = "TAR at FPPF <= 0.1";
  axes.x_max = 1;
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
  axes.y_min = 0;
  write_png_atomically(png, draw_plot(axes, curves));
}

}  // namespace rdsf
