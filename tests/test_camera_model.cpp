#include <gtest/gtest.h>

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

TEST(CameraModel, ScalingKeepsRealSizes) {
  const CameraModel half = CameraModel::kinect_v1().scaled_to(320, 240);
  EXPECT_DOUBLE_EQ(half.fx_px, 262.5);
  EXPECT_DOUBLE_EQ(half.cx_px, 159.5);
  // Half the pixels at half the focal length: the same real size.
  EXPECT_DOUBLE_EQ(half.height_cm(100, 3000), CameraModel::kinect_v1().height_cm(200, 3000));
}
