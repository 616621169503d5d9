#include "ground_plane.hpp"

#include <cmath>

#include <pcl/ModelCoefficients.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

namespace rdsf::peers {

std::optional<Eigen::Vector4f> fit_ground(const std::vector<const DepthFrame*>& frames, const GroundParams& params) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr points(new pcl::PointCloud<pcl::PointXYZ>);
  for (const DepthFrame* frame : frames) {
    const CameraModel& c = frame->camera;
    for (int v = 0; v < frame->depth_mm.rows; v += params.stride_px) {
      for (int u = 0; u < frame->depth_mm.cols; u += params.stride_px) {
        const double z = frame->depth_mm(v, u) / 1000.0;
        if (z <= 0 || z > params.max_range_m) continue;
        points->push_back(pcl::PointXYZ(static_cast<float>((u - c.cx_px) * z / c.fx_px),
                                        static_cast<float>((v - c.cy_px) * z / c.fy_px), static_cast<float>(z)));
      }
    }
  }
  const std::size_t sampled = points->size();
  std::optional<Eigen::Vector4f> floor;
  pcl::SACSegmentation<pcl::PointXYZ> ransac;
  ransac.setOptimizeCoefficients(true);
  ransac.setModelType(pcl::SACMODEL_PERPENDICULAR_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setAxis(Eigen::Vector3f(0, 1, 0));
  ransac.setEpsAngle(params.max_tilt_deg * M_PI / 180.0);
  ransac.setDistanceThreshold(params.inlier_distance_m);
  ransac.setMaxIterations(500);
  for (int plane = 0; plane < params.max_planes && points->size() > 3; ++plane) {
    pcl::PointIndices::Ptr inliers(new pcl::PointIndices);
    pcl::ModelCoefficients coefficients;
    ransac.setInputCloud(points);
    ransac.segment(*inliers, coefficients);
    if (inliers->indices.size() < params.min_inlier_share * static_cast<double>(sampled)) break;
    Eigen::Vector4f p(coefficients.values[0], coefficients.values[1], coefficients.values[2], coefficients.values[3]);
    p /= p.head<3>().norm();
    if (p[1] > 0) p = -p;  // normal up (towards -y), so d is the camera's height above the plane
    if (p[3] > 0 && (!floor || p[3] > (*floor)[3])) floor = p;
    pcl::ExtractIndices<pcl::PointXYZ> extract;
    extract.setInputCloud(points);
    extract.setIndices(inliers);
    extract.setNegative(true);
    pcl::PointCloud<pcl::PointXYZ>::Ptr rest(new pcl::PointCloud<pcl::PointXYZ>);
    extract.filter(*rest);
    points = rest;
  }
  return floor;
}

}  // namespace rdsf::peers
