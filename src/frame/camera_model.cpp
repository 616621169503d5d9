#include "rdsf/frame/camera_model.hpp"

#include <cmath>
#include <sstream>

#include "rdsf/core/error.hpp"

namespace rdsf {

CameraModel CameraModel::from_empirical(const EmpiricalCalibration& c, int width_px, int height_px) {
  if (c.surface_width_cm <= 0 || c.surface_height_cm <= 0 || c.distance_mm <= 0) {
    throw Error("empirical calibration: surface width, height and distance must all be positive");
  }
  CameraModel model;
  model.width_px = width_px;
  model.height_px = height_px;
  // A pixel at distance d spans surface_cm*10/width_px mm, so fx = width_px * d / (surface_cm * 10).
  model.fx_px = width_px * c.distance_mm / (c.surface_width_cm * 10.0);
  model.fy_px = height_px * c.distance_mm / (c.surface_height_cm * 10.0);
  model.cx_px = (width_px - 1) / 2.0;
  model.cy_px = (height_px - 1) / 2.0;
  return model;
}

CameraModel CameraModel::from_field_of_view(int width_px, int height_px, double hfov_deg, double vfov_deg) {
  constexpr double kPi = 3.14159265358979323846;
  CameraModel model;
  model.width_px = width_px;
  model.height_px = height_px;
  model.fx_px = 0.5 * width_px / std::tan(0.5 * hfov_deg * kPi / 180.0);
  model.fy_px = vfov_deg > 0 ? 0.5 * height_px / std::tan(0.5 * vfov_deg * kPi / 180.0) : model.fx_px;
  model.cx_px = 0.5 * (width_px - 1);
  model.cy_px = 0.5 * (height_px - 1);
  return model;
}

CameraModel CameraModel::scaled_to(int new_width_px, int new_height_px) const {
  CameraModel model = *this;
  const double sx = static_cast<double>(new_width_px) / width_px;
  const double sy = static_cast<double>(new_height_px) / height_px;
  model.width_px = new_width_px;
  model.height_px = new_height_px;
  model.fx_px *= sx;
  model.fy_px *= sy;
  model.cx_px = (cx_px + 0.5) * sx - 0.5;
  model.cy_px = (cy_px + 0.5) * sy - 0.5;
  return model;
}

std::string CameraModel::describe() const {
  std::ostringstream out;
  out << width_px << "x" << height_px << " fx=" << fx_px << " fy=" << fy_px << " cx=" << cx_px
      << " cy=" << cy_px;
  return out.str();
}

bool CameraModel::operator==(const CameraModel& o) const {
  return width_px == o.width_px && height_px == o.height_px && fx_px == o.fx_px && fy_px == o.fy_px &&
         cx_px == o.cx_px && cy_px == o.cy_px;
}

}  // namespace rdsf
