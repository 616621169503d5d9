#include "rdsf/classifier/opencv_boost.hpp"

#include <opencv2/ml.hpp>

#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

std::vector<WeakClassifier> stumps_of(const cv::ml::Boost& boost) {
  const std::vector<int>& roots = boost.getRoots();
  const std::vector<cv::ml::DTrees::Node>& nodes = boost.getNodes();
  const std::vector<cv::ml::DTrees::Split>& splits = boost.getSplits();
  std::vector<WeakClassifier> out;
  for (int root : roots) {
    const cv::ml::DTrees::Node& node = nodes[static_cast<std::size_t>(root)];
    WeakClassifier w;
    w.kind = WeakClassifier::Kind::Stump;
    if (node.split < 0) {  // a tree that never split: a constant
      w.left = w.right = node.value;
      out.push_back(w);
      continue;
    }
    const cv::ml::DTrees::Split& split = splits[static_cast<std::size_t>(node.split)];
    const cv::ml::DTrees::Node& left = nodes[static_cast<std::size_t>(node.left)];
    const cv::ml::DTrees::Node& right = nodes[static_cast<std::size_t>(node.right)];
    if (left.split >= 0 || right.split >= 0) throw Error("OpenCV boost: a tree deeper than a stump");
    w.feature = split.varIdx;
    w.threshold = static_cast<double>(split.c);
    w.left = split.inversed ? right.value : left.value;
    w.right = split.inversed ? left.value : right.value;
    out.push_back(w);
  }
  return out;
}

}  // namespace

OpenCvBoostResult train_opencv_boost(const cv::Mat1f& rows, const std::vector<int>& labels,
                                     const OpenCvBoostParams& params) {
  if (rows.rows != static_cast<int>(labels.size())) throw Error("OpenCV boost: rows and labels differ in count");
  if (params.rounds < 1) throw Error("OpenCV boost: at least one round is needed");
  cv::Mat1i responses(static_cast<int>(labels.size()), 1);
  for (std::size_t i = 0; i < labels.size(); ++i) responses(static_cast<int>(i), 0) = labels[i];
  cv::Ptr<cv::ml::Boost> boost = cv::ml::Boost::create();
  boost->setBoostType(cv::ml::Boost::REAL);
  boost->setWeakCount(params.rounds);
  boost->setMaxDepth(1);
  boost->setWeightTrimRate(params.weight_trim > 0.0 ? 1.0 - params.weight_trim : 0.0);
  boost->setUseSurrogates(false);
  boost->setCVFolds(0);
  boost->setUse1SERule(false);
  boost->setTruncatePrunedTree(false);
  try {
    const cv::Ptr<cv::ml::TrainData> data = cv::ml::TrainData::create(rows, cv::ml::ROW_SAMPLE, responses);
    if (!boost->train(data)) throw Error("OpenCV boost: training failed");
  } catch (const cv::Exception& e) {
    throw Error("OpenCV boost: " + std::string(e.err));
  }
  OpenCvBoostResult result;
  result.stumps = stumps_of(*boost);
  cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  fs.startWriteStruct("opencv_model", cv::FileNode::MAP);
  boost->write(fs);
  fs.endWriteStruct();
  result.yaml = fs.releaseAndGetString();
  return result;
}

std::vector<double> opencv_boost_scores(const std::string& yaml, const cv::Mat1f& rows) {
  cv::Ptr<cv::ml::Boost> boost = cv::ml::Boost::create();
  try {
    cv::FileStorage fs(yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    const cv::FileNode node = fs["opencv_model"];
    if (!node.isMap()) throw Error("OpenCV boost: no 'opencv_model' in the given YAML");
    boost->read(node);
  } catch (const cv::Exception& e) {
    throw Error("OpenCV boost: cannot read the embedded model (" + std::string(e.err) + ")");
  }
  std::vector<double> scores(static_cast<std::size_t>(rows.rows));
  for (int r = 0; r < rows.rows; ++r) {
    scores[static_cast<std::size_t>(r)] = boost->predict(rows.row(r), cv::noArray(), cv::ml::DTrees::PREDICT_SUM);
  }
  return scores;
}

}  // namespace rdsf
