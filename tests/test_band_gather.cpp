// gather_band() (band_gather.hpp), the fitted extent's band counts, on hand-built label and depth maps:
// the SSE2 kernel and the scalar loop against counts worked out by hand, at the image's right border
// (the 16 lanes read from cols - 16) and on an image narrower than 16 columns (scalar only).
#include <gtest/gtest.h>

#include "rdsf/candidates/band_gather.hpp"

namespace rdsf {
namespace {

// A 10 x 20 map: layer 2 in column 3 at rows 2, 4, 5, 6 (depths 1000, 1100, 1200, 1300) and in column 19
// at rows 1, 3, 7 (depths 2000, 2100, 2200); label 1 (another layer) in column 4 at every row.
struct Maps {
  cv::Mat1b labels = cv::Mat1b::zeros(10, 20);
  cv::Mat1w depth = cv::Mat1w::zeros(10, 20);
  Maps() {
    const int rows3[] = {2, 4, 5, 6}, rows19[] = {1, 3, 7};
    for (int i = 0; i < 4; ++i) labels(rows3[i], 3) = 2, depth(rows3[i], 3) = static_cast<std::uint16_t>(1000 + 100 * i);
    for (int i = 0; i < 3; ++i) labels(rows19[i], 19) = 2, depth(rows19[i], 19) = static_cast<std::uint16_t>(2000 + 100 * i);
    for (int y = 0; y < 10; ++y) labels(y, 4) = 1, depth(y, 4) = 900;
  }
};

void expect_column(const BandColumn& b, int count, int first_row, std::int64_t depth_sum, const char* what) {
  EXPECT_EQ(b.count, count) << what;
  EXPECT_EQ(b.first_row, first_row) << what;
  EXPECT_EQ(b.depth_sum, depth_sum) << what;
}

TEST(BandGather, CountsFirstRowAndDepthSumEveryOtherRow) {
  const Maps m;
  ASSERT_TRUE(band_16_lanes(m.labels.cols, 2, 3, 2, 8));
  for (const bool scalar : {false, true}) {
    BandColumn out[3];
    // Columns 2..4, rows 2, 4, 6, 8: column 3 holds rows 2, 4, 6 (row 5 is skipped).
    (scalar ? gather_band_scalar : gather_band)(m.labels, m.depth, 2, 2, 3, 2, 8, out);
    const char* what = scalar ? "scalar" : "gather_band";
    expect_column(out[0], 0, -1, 0, what);
    expect_column(out[1], 3, 2, 1000 + 1100 + 1300, what);
    expect_column(out[2], 0, -1, 0, what);  // label 1 is another layer
    // From row 1 (odd rows): only row 5 of column 3.
    (scalar ? gather_band_scalar : gather_band)(m.labels, m.depth, 2, 3, 1, 1, 9, out);
    expect_column(out[0], 1, 5, 1200, what);
  }
}

TEST(BandGather, RightBorderColumnsReadFromTheLastSixteen) {
  const Maps m;
  for (const bool scalar : {false, true}) {
    BandColumn out[2];
    // Columns 18, 19 (the 16 lanes then start at column 4), rows 1, 3, 5, 7, 9.
    (scalar ? gather_band_scalar : gather_band)(m.labels, m.depth, 2, 18, 2, 1, 9, out);
    const char* what = scalar ? "scalar" : "gather_band";
    expect_column(out[0], 0, -1, 0, what);
    expect_column(out[1], 3, 1, 2000 + 2100 + 2200, what);
  }
}

TEST(BandGather, NarrowImageAndWideLabelsUseTheScalarLoop) {
  EXPECT_FALSE(band_16_lanes(15, 2, 3, 0, 8));       // image narrower than 16
  EXPECT_FALSE(band_16_lanes(640, 256, 3, 0, 8));    // label not a byte
  EXPECT_FALSE(band_16_lanes(640, 2, 17, 0, 8));     // more than 16 columns
  EXPECT_FALSE(band_16_lanes(640, 2, 3, 0, 65536));  // row index beyond 16 bits
  const Maps m;
  const cv::Mat1b labels = m.labels.colRange(0, 8).clone();
  const cv::Mat1w depth = m.depth.colRange(0, 8).clone();
  BandColumn out[8];
  gather_band(labels, depth, 2, 0, 8, 0, 9, out);
  expect_column(out[3], 3, 2, 1000 + 1100 + 1300, "narrow");
  expect_column(out[4], 0, -1, 0, "narrow");
}

// A walk's first gather takes kBandChunk + 1 columns (scalar: more than the 16 lanes).
TEST(BandGather, SeventeenColumnsAtOnce) {
  const Maps m;
  EXPECT_FALSE(band_16_lanes(m.labels.cols, 2, kBandChunk + 1, 0, 9));
  BandColumn out[kBandChunk + 1];
  gather_band(m.labels, m.depth, 2, 3, kBandChunk + 1, 1, 9, out);
  expect_column(out[0], 1, 5, 1200, "17 columns");
  expect_column(out[16], 3, 1, 2000 + 2100 + 2200, "17 columns");
}

}  // namespace
}  // namespace rdsf
