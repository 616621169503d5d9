#include "rdsf/classifier/platt_calibration.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/core/error.hpp"

namespace rdsf {

double ScoreCalibration::probability(double score) const {
  const double t = a * score + b;
  // Written so that neither branch overflows.
  if (t >= 0) return 1.0 / (1.0 + std::exp(-t));
  const double e = std::exp(t);
  return e / (1.0 + e);
}

double ScoreCalibration::score_at(double p) const {
  if (!(p > 0.0 && p < 1.0)) throw Error("a probability threshold must be inside (0, 1), got " + std::to_string(p));
  return (std::log(p / (1.0 - p)) - b) / a;
}

ScoreCalibration fit_platt(const std::vector<double>& scores, const std::vector<int>& labels) {
  if (scores.size() != labels.size()) throw Error("calibration: scores and labels differ in number");
  const auto pos = static_cast<std::size_t>(std::count(labels.begin(), labels.end(), 1));
  const std::size_t neg = labels.size() - pos;
  if (pos == 0 || neg == 0) throw Error("calibration needs scores of both classes");
  const double hi = (static_cast<double>(pos) + 1.0) / (static_cast<double>(pos) + 2.0);
  const double lo = 1.0 / (static_cast<double>(neg) + 2.0);
  std::vector<double> t(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) t[i] = labels[i] == 1 ? hi : lo;

  // Minimise F(A, B) = sum_i t_i f_i + log(1 + exp(-f_i)), f_i = A s_i + B (P_i = 1 / (1 + exp(-f_i))).
  auto objective = [&](double A, double B) {
    double f = 0.0;
    for (std::size_t i = 0; i < scores.size(); ++i) {
      const double fi = A * scores[i] + B;
      // -(t log p + (1 - t) log(1 - p)) with p = sigmoid(fi), in a stable form.
      f += (fi >= 0 ? (1.0 - t[i]) * fi + std::log1p(std::exp(-fi)) : -t[i] * fi + std::log1p(std::exp(fi)));
    }
    return f;
  };
  double A = 0.0, B = std::log((static_cast<double>(pos) + 1.0) / (static_cast<double>(neg) + 1.0));
  double F = objective(A, B);
  const double sigma = 1e-12;  // keeps the Hessian positive definite
  for (int iteration = 0; iteration < 100; ++iteration) {
    double h11 = sigma, h22 = sigma, h21 = 0.0, g1 = 0.0, g2 = 0.0;
    for (std::size_t i = 0; i < scores.size(); ++i) {
      const double fi = A * scores[i] + B;
      const double p = fi >= 0 ? 1.0 / (1.0 + std::exp(-fi)) : std::exp(fi) / (1.0 + std::exp(fi));
      const double d1 = p - t[i];  // dF/df_i
      const double d2 = p * (1.0 - p);
      h11 += scores[i] * scores[i] * d2;
      h22 += d2;
      h21 += scores[i] * d2;
      g1 += scores[i] * d1;
      g2 += d1;
    }
    if (std::abs(g1) < 1e-9 && std::abs(g2) < 1e-9) break;
    const double det = h11 * h22 - h21 * h21;
    const double dA = -(h22 * g1 - h21 * g2) / det, dB = -(-h21 * g1 + h11 * g2) / det;
    const double gd = g1 * dA + g2 * dB;
    double step = 1.0;
    bool moved = false;
    while (step >= 1e-10) {
      const double nA = A + step * dA, nB = B + step * dB;
      const double nF = objective(nA, nB);
      if (nF < F + 1e-4 * step * gd) {
        A = nA;
        B = nB;
        F = nF;
        moved = true;
        break;
      }
      step /= 2.0;
    }
    if (!moved) break;
  }
  ScoreCalibration c;
  c.method = "platt";
  c.a = A;
  c.b = B;
  c.positives = pos;
  c.negatives = neg;
  return c;
}

}  // namespace rdsf
