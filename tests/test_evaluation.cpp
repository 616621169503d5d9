#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/clear_mot.hpp"
#include "rdsf/evaluation/curve_plot.hpp"
#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/frame_source.hpp"

using namespace rdsf;

TEST(GroundTruth, ParsesRealAndSyntheticLayouts) {
  const GroundTruth real = parse_ground_truth("frame,person,x,y,w,h\na,1,10,20,30,40\na,2,1,2,3,4\nb,1,5,5,5,5\n", "t");
  EXPECT_EQ(real.people(), 3u);
  EXPECT_EQ(real.in("a")[1].box, cv::Rect(1, 2, 3, 4));
  EXPECT_EQ(real.in("a")[1].track, 2);  // track defaults to person
  EXPECT_TRUE(real.in("zzz").empty());
  const GroundTruth synth =
      parse_ground_truth("frame,person,x,y,w,h,visible_fraction,track\r\n000001,1,1,2,3,4,0.75,9\r\n", "s");
  EXPECT_EQ(synth.in("000001")[0].track, 9);
  EXPECT_DOUBLE_EQ(synth.in("000001")[0].visible_fraction, 0.75);
}

TEST(GroundTruth, BadLinesAreNamed) {
  auto message = [](const std::string& text) {
    try {
      parse_ground_truth(text, "boxes.csv");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(""), "boxes.csv: empty file (expected a header frame,person,x,y,w,h)");
  EXPECT_EQ(message("frame,x,y,w,h\n"), "boxes.csv: line 1: header has no 'person' column");
  EXPECT_EQ(message("frame,person,x,y,w,h\na,1,2,3,4,5\na,1,2,3\n"), "boxes.csv: line 3: 4 fields, the header has 6");
  EXPECT_EQ(message("frame,person,x,y,w,h\na,1,2,x3,4,5\n"), "boxes.csv: line 2: y is not a whole number: 'x3'");
  EXPECT_EQ(message("frame,person,x,y,w,h\na,1,2,3,0,5\n"), "boxes.csv: line 2: box has no area");
  EXPECT_EQ(message("frame,person,x,y,w,h,visible_fraction\na,1,2,3,4,5,1.5\n"),
            "boxes.csv: line 2: visible_fraction is not a number in [0, 1]: '1.5'");
}

// The truth's frame names against a source's: none in common is an Error naming the file and both namings;
// some not in the source are counted; an empty truth or an unknown source says nothing.
TEST(GroundTruth, FramesNamedAgainstTheSourcesNames) {
  const GroundTruth truth = parse_ground_truth("frame,person,x,y,w,h\na,1,10,20,30,40\nb,1,5,5,5,5\n", "t");
  EXPECT_EQ(truth_frames_not_in(truth, "boxes.csv", {"a", "b", "c"}, "room"), 0u);
  EXPECT_EQ(truth_frames_not_in(truth, "boxes.csv", {"b", "c"}, "room"), 1u);
  EXPECT_EQ(truth_frames_not_in(truth, "boxes.csv", {}, "room"), 0u);
  EXPECT_EQ(truth_frames_not_in(GroundTruth{}, "boxes.csv", {"0"}, "room"), 0u);
  try {
    truth_frames_not_in(truth, "boxes.csv", index_frame_names(3), "take.bag");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "boxes.csv: names none of the 3 frames of take.bag (it names e.g. 'a', the "
                                     "source's first frame is '0'; a bag's or a recording's frames are named by "
                                     "their index 0, 1, ...)");
  }
}

TEST(GroundTruth, OverlapWithCountedAndIgnoredPeopleApart) {
  std::vector<TruthBox> people(3);
  people[0].box = {0, 0, 100, 100};
  people[1].box = {0, 0, 100, 50};  // the box looked at below: IoU 1
  people[2].box = {0, 0, 100, 100};
  people[2].ignored = true;
  const TruthOverlap half = truth_overlap({0, 0, 100, 50}, {people[0], people[2]});
  EXPECT_DOUBLE_EQ(half.counted, 0.5);
  EXPECT_DOUBLE_EQ(half.ignored, 0.5);
  EXPECT_DOUBLE_EQ(truth_overlap({0, 0, 100, 50}, people).counted, 1.0);  // the best of the counted ones
  const TruthOverlap apart = truth_overlap({300, 300, 10, 10}, people);
  EXPECT_EQ(apart.counted, 0);
  EXPECT_EQ(apart.ignored, 0);
  EXPECT_EQ(truth_overlap({0, 0, 10, 10}, {}).counted, 0);
}

TEST(DetectionMetrics, ThesisFarDefinition) {
  DetectionFigures f;
  f.n_frames = 608;
  f.n_fp = 33;
  f.n_people = 600;
  f.n_det = 540;
  f.n_miss = 60;
  compute_rates(f);
  EXPECT_NEAR(f.far, 0.051482, 5e-7);  // the thesis's tree2 row at threshold 0
  EXPECT_NEAR(f.trr, 1 - 0.051482, 5e-7);
  EXPECT_NEAR(f.tar, 0.9, 1e-12);
  EXPECT_NEAR(f.frr, 0.1, 1e-12);
  EXPECT_NEAR(f.fppf, 33.0 / 608.0, 1e-12);
  EXPECT_NEAR(f.mpf, 60.0 / 608.0, 1e-12);
}

TEST(DetectionMetrics, HandWorkedFrames) {
  const GroundTruth truth = parse_ground_truth(
      "frame,person,x,y,w,h\n"
      "f1,1,0,0,100,200\n"
      "f1,2,300,0,100,200\n"
      "f2,1,0,0,100,200\n",
      "t");
  // f1: a good detection of person 1 (score 5), a duplicate of person 1 (score 3), a detection far from
  // everyone (score 1); person 2 has no candidate at all (segmentation error).
  // f2: person 1 found with score -2. f3: no people, one candidate with score 0.
  const std::vector<FrameCandidates> frames = {
      {"f1", {{cv::Rect(0, 0, 100, 200), 5, {}}, {cv::Rect(10, 0, 100, 200), 3, {}}, {cv::Rect(500, 0, 50, 50), 1, {}}}},
      {"f2", {{cv::Rect(0, 10, 100, 200), -2, {}}}},
      {"f3", {{cv::Rect(0, 0, 10, 10), 0, {}}}}};
  const DetectionFigures at0 = detection_figures(frames, truth, 0);
  EXPECT_EQ(at0.n_frames, 3);
  EXPECT_EQ(at0.n_people, 3);
  EXPECT_EQ(at0.n_det, 1);   // person 1 in f1
  EXPECT_EQ(at0.n_fp, 3);    // the duplicate, the stray one, f3's
  EXPECT_EQ(at0.n_miss, 2);  // person 2 in f1, person 1 in f2 (score below 0)
  EXPECT_NEAR(at0.far, 3.0 / 6.0, 1e-12);
  const DetectionFigures low = detection_figures(frames, truth, -5);
  EXPECT_EQ(low.n_det, 2);
  EXPECT_EQ(low.n_miss, 1);
  EXPECT_EQ(segmentation_errors(frames, truth), 1);
  const DetectionFigures clean = detection_figures(frames, truth, -5, true);
  EXPECT_EQ(clean.n_people, 2);
  EXPECT_EQ(clean.n_miss, 0);
  EXPECT_DOUBLE_EQ(clean.tar, 1.0);
  EXPECT_EQ(thesis_thresholds().size(), 12u);
}

TEST(ClearMot, HandWorkedSequence) {
  // Two people over four frames. Truth tracks 1 and 2; the tracker's ids 7, 8, then a swap, a miss and a
  // false positive. Worked by hand:
  //  frame 1: t1-h7 (IoU 1), t2-h8 (IoU 1)                 -> 2 matches
  //  frame 2: t1-h7 (IoU 0.8), t2-h8 (IoU 1)                -> 2 matches
  //  frame 3: t1-h8 (IoU 1), t2 missed, h9 false positive   -> 1 match, 1 mismatch (t1 was h7), 1 miss, 1 fp
  //  frame 4: t1-h8 (IoU 1), t2-h7 (IoU 1)                  -> 2 matches, 1 mismatch (t2 was h8)
  // matches 7, misses 1, false positives 1, mismatches 2, truth 8; IoU sum 6.8 (0.8 = 80/100 overlap)
  const cv::Rect a(0, 0, 100, 100), b(300, 0, 100, 100);
  const cv::Rect a_shift(0, 0, 80, 100);  // IoU with a: 8000 / 10000 = 0.8
  ClearMot mot;
  mot.add_frame({{a, 1}, {b, 2}}, {{a, 7}, {b, 8}});
  mot.add_frame({{a, 1}, {b, 2}}, {{a_shift, 7}, {b, 8}});
  mot.add_frame({{a, 1}, {b, 2}}, {{a, 8}, {cv::Rect(600, 0, 50, 50), 9}});
  mot.add_frame({{a, 1}, {b, 2}}, {{a, 8}, {b, 7}});
  const MotFigures& f = mot.figures();
  EXPECT_EQ(f.truth, 8);
  EXPECT_EQ(f.matches, 7);
  EXPECT_EQ(f.misses, 1);
  EXPECT_EQ(f.false_positives, 1);
  EXPECT_EQ(f.mismatches, 2);
  EXPECT_NEAR(f.motp(), 100.0 * 6.8 / 7.0, 1e-9);
  EXPECT_NEAR(f.mota(), 1.0 - 4.0 / 8.0, 1e-12);
}

TEST(ClearMot, KeepsCorrespondenceWhileItHolds) {
  // A hypothesis that overlaps two truths: the previous frame's correspondence is kept, so no mismatch.
  ClearMot mot;
  mot.add_frame({{cv::Rect(0, 0, 100, 100), 1}}, {{cv::Rect(0, 0, 100, 100), 5}});
  mot.add_frame({{cv::Rect(0, 0, 100, 100), 1}},
                {{cv::Rect(30, 0, 100, 100), 5}, {cv::Rect(0, 0, 100, 100), 6}});  // 5 still at IoU 0.54
  EXPECT_EQ(mot.figures().mismatches, 0);
  EXPECT_EQ(mot.figures().false_positives, 1);
}

TEST(CurvePlot, DrawsAxesCurvesAndLegend) {
  PlotAxes axes;
  axes.title = "ROC";
  axes.x_label = "FAR";
  axes.y_label = "TAR";
  const cv::Mat3b empty = draw_plot(axes, {});
  const cv::Mat3b plot = draw_plot(axes, {{"tree", {{0, 0}, {0.1, 0.8}, {1, 1}}, cv::Point2d(0.1, 0.8), "T=0"}});
  ASSERT_EQ(plot.size(), cv::Size(900, 650));
  EXPECT_GT(cv::norm(plot, empty, cv::NORM_L1), 0.0);  // the curve changed pixels
  axes.log_x = axes.log_y = true;
  axes.x_min = axes.y_min = 1e-3;
  const cv::Mat3b log_plot = draw_plot(axes, {{"tree", {{0.0, 0.5}, {0.01, 0.1}, {1, 0.01}}, {}, ""}});
  EXPECT_EQ(log_plot.size(), cv::Size(900, 650));
}

// The legend lands in the corner asked for, away from a curve that rises at the left and runs along the top.
TEST(CurvePlot, LegendInItsCorner) {
  PlotAxes axes;
  const std::vector<PlotCurve> curve = {{"tree", {{0, 0}, {0, 1}, {0.3, 1}}, {}, ""}};
  const cv::Mat3b empty = draw_plot(axes, {});
  const cv::Rect bottom_right(450, 325, 450, 325), top_right(450, 0, 450, 325);
  const auto changed = [&](const cv::Mat3b& plot, const cv::Rect& area) {
    return cv::norm(plot(area), empty(area), cv::NORM_L1);
  };
  axes.legend = PlotAxes::Corner::bottom_right;
  const cv::Mat3b at_bottom = draw_plot(axes, curve);
  EXPECT_GT(changed(at_bottom, bottom_right), 0.0);
  EXPECT_EQ(changed(at_bottom, top_right), 0.0);
  axes.legend = PlotAxes::Corner::top_right;
  const cv::Mat3b at_top = draw_plot(axes, curve);
  EXPECT_EQ(changed(at_top, bottom_right), 0.0);
  EXPECT_GT(changed(at_top, top_right), 0.0);
}

// Operating points that share their label (one probability threshold for every model) are labelled once,
// in the legend, not eight times on top of each other beside the points; different labels stay at the points.
TEST(CurvePlot, SharedOperatingLabelOnceInTheLegend) {
  PlotAxes axes;
  const auto curves = [](const std::string& a, const std::string& b) {
    return std::vector<PlotCurve>{{"one", {{0, 0}, {0.1, 0.7}, {1, 1}}, cv::Point2d(0.1, 0.7), a},
                                  {"two", {{0, 0}, {0.15, 0.75}, {1, 1}}, cv::Point2d(0.15, 0.75), b}};
  };
  const cv::Mat3b unlabelled = draw_plot(axes, curves("", ""));
  const cv::Mat3b shared = draw_plot(axes, curves("P>=0.50", "P>=0.50"));
  const cv::Mat3b different = draw_plot(axes, curves("P>=0.50", "P>=0.30"));
  const cv::Rect legend_half(450, 325, 450, 325), points_half(0, 0, 450, 325);
  const auto changed = [&](const cv::Mat3b& plot, const cv::Rect& area) {
    return cv::norm(plot(area), unlabelled(area), cv::NORM_L1);
  };
  EXPECT_EQ(changed(shared, points_half), 0.0) << "a shared label was drawn at the points";
  EXPECT_GT(changed(shared, legend_half), 0.0) << "a shared label is missing from the legend";
  EXPECT_GT(changed(different, points_half), 0.0) << "different labels belong at their points";
}

// Eight models (the quality report's levers) get eight different colours.
TEST(CurvePlot, EightCurvesHaveEightColours) {
  PlotAxes axes;
  std::vector<PlotCurve> curves;
  for (int i = 0; i < 8; ++i) {
    const double y = 0.1 + 0.1 * i;
    curves.push_back({"m" + std::to_string(i), {{0.05, y}, {0.4, y}}, {}, ""});
  }
  const cv::Mat3b plot = draw_plot(axes, curves);
  const cv::Mat3b empty = draw_plot(axes, {});
  std::set<std::tuple<int, int, int>> colours;
  for (int i = 0; i < 8; ++i) {
    // The middle of curve i's horizontal line, in the left half (the legend is at the bottom right).
    const cv::Mat3b one = draw_plot(axes, {curves[static_cast<std::size_t>(i)]});
    cv::Mat1b differs;
    cv::compare(cv::Mat(one.reshape(1)), cv::Mat(empty.reshape(1)), differs, cv::CMP_NE);
    cv::Point where(-1, -1);
    for (int y = 0; y < plot.rows && where.x < 0; ++y) {
      for (int x = 100; x < 300; ++x) {
        if (differs(y, 3 * x) || differs(y, 3 * x + 1) || differs(y, 3 * x + 2)) {
          where = {x, y + 1};  // the line is 2 px thick: its second row is solid
          break;
        }
      }
    }
    ASSERT_GE(where.x, 0) << "curve " << i << " not drawn";
    const cv::Vec3b c = plot(where);
    colours.insert({c[0], c[1], c[2]});
  }
  EXPECT_EQ(colours.size(), 8u);
}

TEST(DetectionMetrics, HardlyVisiblePeopleAreDontCare) {
  GroundTruth truth = parse_ground_truth(
      "frame,person,x,y,w,h,visible_fraction,track\n"
      "f1,1,0,0,100,200,0.9,1\n"
      "f1,2,300,0,100,200,0.1,2\n",
      "t");
  EXPECT_EQ(ignore_hardly_visible(truth, 0.5), 1u);
  // Person 2 (10% visible) is detected once and missed nowhere: neither a detection nor a false positive.
  const std::vector<FrameCandidates> frames = {
      {"f1", {{cv::Rect(300, 0, 100, 200), 2, {}}, {cv::Rect(600, 0, 10, 10), 1, {}}}}};
  const DetectionFigures f = detection_figures(frames, truth, 0);
  EXPECT_EQ(f.n_people, 1);
  EXPECT_EQ(f.n_det, 0);
  EXPECT_EQ(f.n_fp, 1);  // only the stray one
  EXPECT_EQ(f.n_miss, 1);
  EXPECT_EQ(segmentation_errors(frames, truth), 1);  // person 1 has no candidate; person 2 does not count
}

// Wilson's interval: the textbook example 81 of 263 gives 0.2553-0.3662 (z = 1.96); an interval never leaves
// [0, 1] and covers the true rate about 95 % of the time on a seeded binomial simulation.
TEST(DetectionMetrics, WilsonIntervalOfARate) {
  const RateInterval a = wilson_interval(81, 263);
  EXPECT_NEAR(a.low, 0.2553, 5e-4);
  EXPECT_NEAR(a.high, 0.3662, 5e-4);
  const RateInterval all = wilson_interval(49, 49);
  EXPECT_DOUBLE_EQ(all.high, 1.0);
  EXPECT_NEAR(all.low, 0.927, 1e-3);
  const RateInterval none = wilson_interval(0, 0);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_EQ(none.high, 1.0);
  std::uint64_t state = 12345;
  const auto uniform = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  int covered = 0;
  const int trials = 4000, n = 49;
  const double rate = 0.8;
  for (int t = 0; t < trials; ++t) {
    int k = 0;
    for (int i = 0; i < n; ++i) k += uniform() < rate;
    const RateInterval r = wilson_interval(k, n);
    covered += r.low <= rate && rate <= r.high;
  }
  EXPECT_GT(covered, 0.93 * trials);
  EXPECT_LT(covered, 0.98 * trials);
}
