#pragma once
// The pinhole model of the depth camera, in pixels, that turns pixel extents at a depth into real
// centimetres. All programs share one default: a Kinect v1 (PrimeSense PS1080) whose depth is registered
// to the colour camera, as OpenNI2 delivers it with registration on.
//
// Default intrinsics (640x480): fx = fy = 525.0 px, cx = 319.5 px, cy = 239.5 px. These are the nominal
// values of the registered Kinect v1 stream used by OpenNI, ROS (openni_launch) and the TUM RGB-D
// benchmark; at 1 m one pixel spans 1000/525 = 1.905 mm.
//
// The thesis calibrated empirically instead: a flat surface of known width and height is placed so that it
// exactly fills the image at a measured distance; then one pixel at depth d spans
// (surface_width / image_width) * (d / distance). from_empirical() turns such a measurement into the
// equivalent focal lengths, so both ways give one model.
#include <string>

namespace rdsf {

/// The thesis's empirical calibration: a surface that exactly fills the image at `distance_mm`.
struct EmpiricalCalibration {
  double surface_width_cm = 0;   ///< real width of the surface that fills the image width
  double surface_height_cm = 0;  ///< real height of the surface that fills the image height
  double distance_mm = 0;        ///< distance from the camera to the surface
};

struct CameraModel {
  int width_px = 640;
  int height_px = 480;
  double fx_px = 525.0;  ///< focal length along x, in pixels
  double fy_px = 525.0;  ///< focal length along y, in pixels
  double cx_px = 319.5;  ///< principal point x, in pixels
  double cy_px = 239.5;  ///< principal point y, in pixels

  /// The default: Kinect v1, depth registered to colour, 640x480.
  static CameraModel kinect_v1() { return {}; }
  /// The model equivalent to an empirical calibration for an image of the given size.
  static CameraModel from_empirical(const EmpiricalCalibration& calibration, int width_px = 640,
                                    int height_px = 480);

  /// Real extent, in centimetres, of `pixels` pixels along x (or y) at depth `depth_mm`.
  double width_cm(double pixels, double depth_mm) const { return pixels * depth_mm / fx_px / 10.0; }
  double height_cm(double pixels, double depth_mm) const { return pixels * depth_mm / fy_px / 10.0; }
  /// The other way: pixels across (fx) or up and down (fy) that `centimetres` span at depth `depth_mm`
  /// (> 0), unrounded: centimetres * 10 * f / depth_mm.
  double columns_px(double centimetres, double depth_mm) const { return centimetres * 10.0 * fx_px / depth_mm; }
  double rows_px(double centimetres, double depth_mm) const { return centimetres * 10.0 * fy_px / depth_mm; }

  /// A centred pinhole of the given fields of view (degrees across the width and the height):
  /// fx = (width_px / 2) / tan(hfov_deg / 2), fy = (height_px / 2) / tan(vfov_deg / 2), principal point at
  /// the centre ((width_px - 1) / 2, (height_px - 1) / 2). vfov_deg <= 0: square pixels, fy = fx.
  static CameraModel from_field_of_view(int width_px, int height_px, double hfov_deg, double vfov_deg = 0);

  /// The same model for an image of another size (intrinsics scale with the image).
  CameraModel scaled_to(int new_width_px, int new_height_px) const;

  /// "640x480 fx=525 fy=525 cx=319.5 cy=239.5"
  std::string describe() const;
  bool operator==(const CameraModel& other) const;
};

}  // namespace rdsf
