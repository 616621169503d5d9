#include "rdsf/classifier/roc_metrics.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

void check(const std::vector<double>& scores, const std::vector<int>& labels, std::size_t& positives,
           std::size_t& negatives) {
  if (scores.size() != labels.size()) {
    throw Error("ROC: " + std::to_string(scores.size()) + " scores for " + std::to_string(labels.size()) +
                " labels");
  }
  positives = static_cast<std::size_t>(std::count(labels.begin(), labels.end(), 1));
  negatives = labels.size() - positives;
  if (positives == 0 || negatives == 0) throw Error("ROC: both positives and negatives are needed");
}

std::vector<std::size_t> descending_order(const std::vector<double>& scores) {
  std::vector<std::size_t> order(scores.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  return order;
}

}  // namespace

std::vector<RocPoint> roc_curve(const std::vector<double>& scores, const std::vector<int>& labels) {
  std::size_t positives = 0, negatives = 0;
  check(scores, labels, positives, negatives);
  const std::vector<std::size_t> order = descending_order(scores);
  std::vector<RocPoint> curve;
  curve.push_back({0.0, 0.0, scores[order.front()] + 1.0});  // a threshold above every score
  std::size_t tp = 0, fp = 0;
  for (std::size_t k = 0; k < order.size();) {
    const double threshold = scores[order[k]];
    while (k < order.size() && scores[order[k]] == threshold) {
      (labels[order[k]] == 1 ? tp : fp) += 1;
      ++k;
    }
    curve.push_back({static_cast<double>(fp) / static_cast<double>(negatives),
                     static_cast<double>(tp) / static_cast<double>(positives), threshold});
  }
  return curve;
}

double roc_auc(const std::vector<double>& scores, const std::vector<int>& labels) {
  const std::vector<RocPoint> curve = roc_curve(scores, labels);
  double area = 0.0;
  for (std::size_t k = 1; k < curve.size(); ++k) {
    area += (curve[k].far - curve[k - 1].far) * (curve[k].tar + curve[k - 1].tar) * 0.5;
  }
  return area;
}

double tar_at_far(const std::vector<RocPoint>& curve, double max_far) {
  double best = 0.0;
  for (const RocPoint& p : curve) {
    if (p.far <= max_far + 1e-12) best = std::max(best, p.tar);
  }
  return best;
}

RocSummary summarise_curve(const std::vector<RocPoint>& curve) {
  RocSummary s;
  for (std::size_t k = 1; k < curve.size(); ++k) {
    s.auc += (curve[k].far - curve[k - 1].far) * (curve[k].tar + curve[k - 1].tar) * 0.5;
  }
  s.tar_at_far_1 = tar_at_far(curve, 0.01);
  s.tar_at_far_5 = tar_at_far(curve, 0.05);
  return s;
}

RocSummary summarise_roc(const std::vector<double>& scores, const std::vector<int>& labels) {
  RocSummary s = summarise_curve(roc_curve(scores, labels));
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < scores.size(); ++i) wrong += ((scores[i] > 0.0) != (labels[i] == 1)) ? 1 : 0;
  s.error_rate = static_cast<double>(wrong) / static_cast<double>(scores.size());
  return s;
}

std::vector<RocPoint> roc_at_far_levels(const std::vector<RocPoint>& curve) {
  static const double kLevels[] = {0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0};
  std::vector<RocPoint> out;
  for (double level : kLevels) {
    const RocPoint* best = nullptr;
    for (const RocPoint& p : curve) {
      if (p.far <= level + 1e-12 && (best == nullptr || p.tar > best->tar)) best = &p;
    }
    if (best != nullptr && (out.empty() || out.back().far != best->far || out.back().tar != best->tar)) {
      out.push_back(*best);
    }
  }
  return out;
}

}  // namespace rdsf
