#include "rdsf/classifier/boosted_model.hpp"

#include <algorithm>

#include "rdsf/classifier/model_file.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

BoostedModel::BoostedModel(FeatureSpec spec, BinScheme bins, std::vector<WeakClassifier> weak)
    : spec_(spec), bins_(bins), weak_(std::move(weak)) {
  bins_.validate();
  auto check_feature = [&](int feature) {
    if (feature < 0 || feature >= spec_.dimension()) {
      throw Error("boosted model: weak classifier on feature " + std::to_string(feature) + " outside 0.." +
                  std::to_string(spec_.dimension() - 1));
    }
  };
  auto check_table = [&](const std::vector<double>& responses) {
    if (responses.size() != static_cast<std::size_t>(bins_.count)) {
      throw Error("boosted model: look-up table of " + std::to_string(responses.size()) + " responses for " +
                  std::to_string(bins_.count) + " bins");
    }
  };
  for (const WeakClassifier& w : weak_) {
    check_feature(w.feature);
    if (w.kind == WeakClassifier::Kind::Lut) check_table(w.responses);
    if (w.kind == WeakClassifier::Kind::Tree) {
      const std::size_t n = w.nodes.size();
      if (n < 3 || n > 15 || ((n + 1) & n) != 0) {
        throw Error("boosted model: a tree of " + std::to_string(n) + " nodes (a complete tree of depth 2-4 has 3, 7 or 15)");
      }
      for (const LutNode& node : w.nodes) {
        check_feature(node.feature);
        check_table(node.responses);
      }
    }
  }
}

BoostedModel BoostedModel::load(const std::string& path_or_name, const std::string& models_dir) {
  return read_model_file(resolve_model(path_or_name, models_dir));
}

double BoostedModel::score(const float* features, std::size_t rounds) const {
  double sum = 0.0;
  const std::size_t n = std::min(rounds, weak_.size());
  for (std::size_t i = 0; i < n; ++i) sum += weak_[i].respond_row(features, bins_);
  return sum;
}

std::vector<int> BoostedModel::used_features() const {
  std::vector<int> out;
  for (const WeakClassifier& w : weak_) {
    for (int f : w.features_read()) out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<double> BoostedModel::score(const cv::Mat1f& rows) const {
  if (!rows.empty() && rows.cols != spec_.dimension()) {
    throw Error("boosted model " + (path_.empty() ? name_ : path_) + ": rows of " + std::to_string(rows.cols) +
                " features given, the model expects " + std::to_string(spec_.dimension()));
  }
  std::vector<double> out(static_cast<std::size_t>(rows.rows));
  for (int r = 0; r < rows.rows; ++r) out[static_cast<std::size_t>(r)] = score(rows[r]);
  return out;
}

BoostedModel BoostedModel::truncated(std::size_t rounds) const {
  BoostedModel copy = *this;
  if (rounds < copy.weak_.size()) copy.weak_.resize(rounds);
  return copy;
}

void BoostedModel::set_identity(std::string name, int version, std::string path, std::string created) {
  name_ = std::move(name);
  version_ = version;
  path_ = std::move(path);
  created_ = std::move(created);
}

}  // namespace rdsf
