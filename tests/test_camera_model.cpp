#include <gtest/gtest.h>

#include <cmath>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/camera_model.hpp"

using rdsf::CameraModel;

TEST(CameraModel, KinectDefaultsConvertPixelsToCentimetres) {
  const CameraModel camera = CameraModel::kinect_v1();
  EXPECT_EQ(camera.width_px, 640);
  EXPECT_EQ(camera.height_px, 480);
  // 525 pixels at 1 m span exactly 1 m.
  EXPECT_DOUBLE_EQ(camera.height_cm(525, 1000), 100.0);
  EXPECT_DOUBLE_EQ(camera.width_cm(52.5, 2000), 20.0);
}

TEST(CameraModel, EmpiricalCalibrationGivesEquivalentFocalLengths) {
  // A 244 cm x 183 cm surface fills the 640x480 image at 2 m.
  const CameraModel camera = CameraModel::from_empirical({244.0, 183.0, 2000.0});
  EXPECT_NEAR(camera.fx_px, 640 * 2000.0 / 2440.0, 1e-9);
  EXPECT_NEAR(camera.fy_px, 480 * 2000.0 / 1830.0, 1e-9);
  // The whole image width at the calibration distance is the surface width.
  EXPECT_NEAR(camera.width_cm(640, 2000), 244.0, 1e-9);
  EXPECT_NEAR(camera.height_cm(480, 4000), 366.0, 1e-9);
}

TEST(CameraModel, EmpiricalCalibrationRejectsNonPositiveValues) {
  EXPECT_THROW(CameraModel::from_empirical({0.0, 183.0, 2000.0}), rdsf::Error);
  EXPECT_THROW(CameraModel::from_empirical({244.0, 183.0, -1.0}), rdsf::Error);
}

TEST(CameraModel, FieldOfViewGivesACentredPinhole) {
  // 90 degrees across 640 px: the half width, 320 px, is the focal length.
  const CameraModel square = CameraModel::from_field_of_view(640, 400, 90.0);
  EXPECT_NEAR(square.fx_px, 320.0, 1e-9);
  EXPECT_EQ(square.fy_px, square.fx_px) << "no vertical angle: square pixels";
  EXPECT_EQ(square.cx_px, 319.5);
  EXPECT_EQ(square.cy_px, 199.5);
  const CameraModel both = CameraModel::from_field_of_view(848, 480, 87.0, 58.0);
  EXPECT_NEAR(both.fx_px, 424.0 / std::tan(43.5 * M_PI / 180.0), 1e-9);
  EXPECT_NEAR(both.fy_px, 240.0 / std::tan(29.0 * M_PI / 180.0), 1e-9);
  // The whole width at depth d spans 2 d tan(hfov / 2).
  EXPECT_NEAR(square.width_cm(640, 1000), 200.0, 1e-9);
}

TEST(CameraModel, ScalingKeepsRealSizes) {
  const CameraModel half = CameraModel::kinect_v1().scaled_to(320, 240);
  EXPECT_DOUBLE_EQ(half.fx_px, 262.5);
  EXPECT_DOUBLE_EQ(half.cx_px, 159.5);
  // Half the pixels at half the focal length: the same real size.
  EXPECT_DOUBLE_EQ(half.height_cm(100, 3000), CameraModel::kinect_v1().height_cm(200, 3000));
}
