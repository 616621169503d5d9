#include "classifier/boosted_model.hpp"

#include "classifier/model_file.hpp"
#include "classifier/model_registry.hpp"
#include "core/error.hpp"

namespace rdsf {

BoostedModel::BoostedModel(FeatureSpec spec, BinScheme bins, std::vector<WeakClassifier> weak)
    : spec_(spec), bins_(bins), weak_(std::move(weak)) {
  bins_.validate();
  for (const WeakClassifier& w : weak_) {
    if (w.feature < 0 || w.feature >= spec_.dimension()) {
      throw Error("boosted model: weak classifier on feature " + std::to_string(w.feature) + " outside 0.." +
                  std::to_string(spec_.dimension() - 1));
    }
    if (w.kind == WeakClassifier::Kind::Lut && w.responses.size() != static_cast<std::size_t>(bins_.count)) {
      throw Error("boosted model: look-up table of " + std::to_string(w.responses.size()) + " responses for " +
                  std::to_string(bins_.count) + " bins");
    }
  }
}

BoostedModel BoostedModel::load(const std::string& path_or_name, const std::string& models_dir) {
  return read_model_file(resolve_model(path_or_name, models_dir));
}

double BoostedModel::score(const float* features) const {
  double sum = 0.0;
  for (const WeakClassifier& w : weak_) sum += w.respond(features[w.feature], bins_);
  return sum;
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
