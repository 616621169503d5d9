// Labels of the detection pictures stay readable: a box at the right border moves its label left so that
// the whole text is in the image, a box at the top puts it below the image's top edge, and a label that
// would cover another moves down a line.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "rdsf/analysis/overlay.hpp"

namespace {

TEST(Overlay, LabelStaysInsideTheImage) {
  const cv::Size image(640, 480), text(150, 10);
  // An ordinary box: the label starts at its left edge, above it.
  const cv::Point inside = rdsf::label_origin(cv::Rect(100, 200, 80, 200), text, image, 6);
  EXPECT_EQ(inside, cv::Point(102, 194));
  // A box at the right border: the label ends 4 px before the image's right edge.
  const cv::Point right = rdsf::label_origin(cv::Rect(590, 200, 50, 200), text, image, 6);
  EXPECT_EQ(right.x + text.width, image.width - 4);
  EXPECT_LT(right.x, 590);
  // A box at the top: the baseline is far enough down for the text.
  const cv::Point top = rdsf::label_origin(cv::Rect(100, 0, 80, 200), text, image, 6);
  EXPECT_EQ(top.y, text.height + 4);
  // A text wider than the image starts at x = 2.
  EXPECT_EQ(rdsf::label_origin(cv::Rect(300, 200, 50, 50), cv::Size(700, 10), image, 6).x, 2);
}

// Two boxes side by side at the same height with labels longer than the first box: the second label moves
// one line down, clear of the first; a third box elsewhere keeps label_origin()'s place; with every line
// taken down to the image's bottom, a label stays where label_origin() puts it.
TEST(Overlay, LabelsDoNotCoverEachOther) {
  const cv::Size image(640, 480), text(200, 10);
  const int baseline = 4;
  rdsf::LabelPlacer labels(image);
  const cv::Rect a(100, 200, 80, 200), b(190, 200, 80, 200);
  const cv::Point first = labels.place(a, text, baseline, 6);
  EXPECT_EQ(first, rdsf::label_origin(a, text, image, 6));
  const cv::Point second = labels.place(b, text, baseline, 6);
  const cv::Rect one = rdsf::LabelPlacer::area(first, text, baseline), two = rdsf::LabelPlacer::area(second, text, baseline);
  EXPECT_EQ((one & two).area(), 0) << one << " " << two;
  EXPECT_EQ(second.x, rdsf::label_origin(b, text, image, 6).x);
  EXPECT_EQ(second.y, first.y + text.height + baseline + 5);
  EXPECT_EQ(labels.place(cv::Rect(500, 100, 60, 60), text, baseline, 6), rdsf::label_origin(cv::Rect(500, 100, 60, 60), text, image, 6));
  // A short image: no free line below, so the label keeps its first place.
  rdsf::LabelPlacer tight(cv::Size(640, 40));
  const cv::Rect low(100, 30, 80, 10);
  const cv::Point p1 = tight.place(low, text, baseline, 6), p2 = tight.place(low, text, baseline, 6);
  EXPECT_EQ(p1, p2);
}

// Drawn: a candidate at the right border gets its whole label in the picture (the label's yellow pixels
// reach no further right than the image minus its margin, and some are left of the box).
TEST(Overlay, CandidateAtTheRightBorderHasItsLabelInThePicture) {
  rdsf::DepthFrame frame;
  frame.depth_mm = cv::Mat1w(480, 640, static_cast<std::uint16_t>(3000));
  rdsf::Segmentation segmentation;
  segmentation.labels = cv::Mat1b(480, 640, static_cast<std::uint8_t>(0));
  rdsf::Candidate candidate;
  candidate.fitted_box = candidate.strict_box = cv::Rect(600, 150, 40, 300);
  candidate.window = candidate.strict_box;
  candidate.layer_depth_mm = 2500;
  const std::vector<double> scores = {-12.5};
  const cv::Mat3b picture = rdsf::render_candidates(frame, segmentation, {candidate}, &scores);
  // The label row band above the box: yellow text pixels (B low, G and R high).
  int leftmost = picture.cols, rightmost = -1;
  for (int y = 125; y <= 146; ++y) {  // above the box's top edge (y = 150)
    for (int x = 0; x < picture.cols; ++x) {
      const cv::Vec3b p = picture(y, x);
      if (p[0] < 80 && p[1] > 200 && p[2] > 200) {
        leftmost = std::min(leftmost, x);
        rightmost = std::max(rightmost, x);
      }
    }
  }
  ASSERT_GE(rightmost, 0) << "no label drawn";
  EXPECT_LT(leftmost, 600) << "the label was not moved left of the box";
  EXPECT_LE(rightmost, picture.cols - 2);
}

}  // namespace
