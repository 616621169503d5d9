// A model trained on candidates of one synthetic recording scores the people of another (held-out seed)
// above everything else: AUC >= 0.95. Candidates come from the frame analyser; a candidate is a person when
// its strict box overlaps a ground-truth person box (intersection over union >= 0.5), not a person when it
// overlaps none by more than 0.2 (the ambiguous ones in between are left out).
#include <gtest/gtest.h>

#include <cstdio>

#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace rdsf {
namespace {

double iou(const cv::Rect& a, const cv::Rect& b) {
  const double inter = (a & b).area();
  const double uni = a.area() + b.area() - inter;
  return uni > 0 ? inter / uni : 0.0;
}

struct Labelled {
  cv::Mat1f rows;
  std::vector<int> labels;
};

Labelled candidates_of(std::uint64_t seed, int frames) {
  synth::SynthParams params = synth::people_scene(frames, 1, 3, seed);
  params.clip_frames = 10;  // many rooms and people, few frames each
  synth::SynthSequence sequence(params);
  const FrameAnalyser analyser;
  Labelled out;
  for (int i = 0; i < frames; ++i) {
    const synth::SynthFrame f = sequence.frame(i);
    const FrameAnalysis analysis = analyser.analyse(f.depth_frame(params.camera()), true);
    for (std::size_t c = 0; c < analysis.candidates.size(); ++c) {
      double best = 0.0;
      for (const synth::PersonTruth& p : f.people) best = std::max(best, iou(analysis.candidates[c].strict_box, p.box));
      if (best > 0.2 && best < 0.5) continue;
      out.rows.push_back(analysis.features.row(static_cast<int>(c)));
      out.labels.push_back(best >= 0.5 ? 1 : 0);
    }
  }
  return out;
}

TEST(ClassifierOnSynthetic, HeldOutSequenceAucAtLeast095) {
  const Labelled train = candidates_of(11, 400), test = candidates_of(12, 150);
  const auto count = [](const std::vector<int>& l, int v) { return std::count(l.begin(), l.end(), v); };
  std::printf("train: %ld people, %ld others; held-out: %ld people, %ld others\n", count(train.labels, 1),
              count(train.labels, 0), count(test.labels, 1), count(test.labels, 0));
  ASSERT_GE(count(train.labels, 1), 30);
  ASSERT_GE(count(train.labels, 0), 30);
  ASSERT_GE(count(test.labels, 1), 15);
  ASSERT_GE(count(test.labels, 0), 15);
  BoostTrainingParams params;
  params.rounds = 60;
  params.bins.count = 16;
  const BoostedModel model = train_boosted_model(train.rows, train.labels, params);
  const double auc = roc_auc(model.score(test.rows), test.labels);
  std::printf("held-out AUC %.4f (validation AUC %.4f)\n", auc, model.training().validation.summary.auc);
  EXPECT_GE(auc, 0.95);
}

}  // namespace
}  // namespace rdsf
