#include "pcl_people_run.hpp"

#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include <pcl/console/print.h>
#include <pcl/people/ground_based_people_detection_app.h>
#include <pcl/point_types.h>

#include "rdsf/analysis/detection_csv.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/evaluation/threshold_sweep.hpp"
#include "rdsf/frame/frame_source.hpp"

namespace rdsf::peers {
namespace {

using PointT = pcl::PointXYZRGBA;
using Cloud = pcl::PointCloud<PointT>;

std::vector<DepthFrame> read_frames(const PclPeopleOptions& o) {
  auto source = open_frame_source(o.source, o.camera);
  std::vector<DepthFrame> frames;
  DepthFrame frame;
  while (source->next(frame)) {
    if (!frame.has_colour()) {
      fail(o.source, "frame " + frame.name + " has no colour image (PCL's detector needs NAME.rgb.png)");
    }
    if (!frames.empty() && !(frame.camera == frames.front().camera)) {  // one camera model for PCL's intrinsics
      fail(o.source, "frame " + frame.name + " has the camera model " + frame.camera.describe() + ", the first " +
                         frames.front().camera.describe());
    }
    frames.push_back(std::move(frame));
    frame = DepthFrame();
  }
  if (frames.empty()) fail(o.source, "no frames");
  return frames;
}

/// The recording a frame belongs to: its name up to the first digit.
std::string recording_of(const std::string& name) {
  std::size_t end = 0;
  while (end < name.size() && !std::isdigit(static_cast<unsigned char>(name[end]))) ++end;
  return name.substr(0, end);
}

/// The organised cloud PCL's app expects (metres; no reading = NaN), colour from the registered image.
Cloud::Ptr organised_cloud(const DepthFrame& frame) {
  Cloud::Ptr cloud(new Cloud(frame.width_px(), frame.height_px()));
  cloud->is_dense = false;
  const CameraModel& c = frame.camera;
  for (int v = 0; v < frame.height_px(); ++v) {
    for (int u = 0; u < frame.width_px(); ++u) {
      PointT& p = (*cloud)(u, v);
      const cv::Vec3b bgr = frame.bgr(v, u);
      p.b = bgr[0], p.g = bgr[1], p.r = bgr[2], p.a = 255;
      const float z = frame.depth_mm(v, u) / 1000.0f;
      if (z <= 0) {
        p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      p.x = static_cast<float>((u - c.cx_px) * z / c.fx_px);
      p.y = static_cast<float>((v - c.cy_px) * z / c.fy_px);
      p.z = z;
    }
  }
  return cloud;
}

/// The score of a cluster whose HOG window PCL could not evaluate (below any threshold of the sweep).
constexpr double kNotEvaluated = -10;

struct PclPerson {
  cv::Rect box;
  double depth_mm = 0;
  double confidence = 0;
};

/// The box of a cluster: its points (of the app's no-ground cloud) projected with the camera model, down to
/// the projection of the cluster's foot point on the floor (getTBottom: the points within 2 voxels of the
/// floor were removed with it, and the truth's boxes reach the feet).
cv::Rect projected_box(const Cloud& points, const pcl::PointIndices& indices, const Eigen::Vector3f& bottom,
                       const CameraModel& c) {
  double u0 = 1e9, v0 = 1e9, u1 = -1e9, v1 = -1e9;
  for (int i : indices.indices) {
    const PointT& p = points[static_cast<std::size_t>(i)];
    if (!(p.z > 0)) continue;
    const double u = c.fx_px * p.x / p.z + c.cx_px, v = c.fy_px * p.y / p.z + c.cy_px;
    u0 = std::min(u0, u), v0 = std::min(v0, v), u1 = std::max(u1, u), v1 = std::max(v1, v);
  }
  if (u1 < u0) return {};
  if (bottom.z() > 0) v1 = std::max(v1, c.fy_px * bottom.y() / bottom.z() + c.cy_px);
  const cv::Rect box(cv::Point(static_cast<int>(std::floor(u0)), static_cast<int>(std::floor(v0))),
                     cv::Point(static_cast<int>(std::ceil(u1)) + 1, static_cast<int>(std::ceil(v1)) + 1));
  return box & cv::Rect(0, 0, c.width_px, c.height_px);
}

std::vector<PclPerson> detect(pcl::people::GroundBasedPeopleDetectionApp<PointT>& app, const DepthFrame& frame,
                              Eigen::VectorXf ground) {
  Cloud::Ptr cloud = organised_cloud(frame);
  app.setInputCloud(cloud);
  app.setGround(ground);
  std::vector<pcl::people::PersonCluster<PointT>> clusters;
  if (!app.compute(clusters)) fail(frame.name, "PCL's people detector refused the frame");
  const Cloud::Ptr points = app.getNoGroundCloud();
  std::vector<PclPerson> people;
  for (auto& cluster : clusters) {
    const cv::Rect box = projected_box(*points, cluster.getIndices(), cluster.getTBottom(), frame.camera);
    if (box.area() == 0) continue;
    // PCL gives NaN when the HOG window leaves the image (the app never accepts those): the lowest score.
    const double confidence = std::isnan(cluster.getPersonConfidence()) ? kNotEvaluated : cluster.getPersonConfidence();
    people.push_back({box, cluster.getDistance() * 1000.0, confidence});
  }
  return people;
}

void write_csv(const PclPeopleOptions& o, const std::vector<DepthFrame>& frames,
               const std::vector<std::vector<PclPerson>>& people) {
  DetectionCsv csv(o.out_csv, o.force, true);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    std::vector<Candidate> rows;
    std::vector<CandidateOutcome> outcomes;
    int number = 0;
    for (const PclPerson& p : people[f]) {
      Candidate c;
      c.strict_box = c.extent_box = c.fitted_box = p.box;
      c.layer_depth_mm = p.depth_mm;
      rows.push_back(c);
      outcomes.push_back({p.confidence, p.confidence >= o.min_confidence ? ++number : 0, 0.0});
    }
    csv.write_frame(frames[f].name, rows, outcomes);
  }
  csv.commit();
  std::cerr << "rdsf-pcl-people: wrote " << o.out_csv << "\n";
}

void evaluate(const PclPeopleOptions& o, const std::vector<DepthFrame>& frames,
              const std::vector<std::vector<PclPerson>>& people, double fps) {
  GroundTruth truth = read_ground_truth(o.truth_csv);
  ignore_hardly_visible(truth, o.min_visible);
  std::vector<std::string> names;
  for (const DepthFrame& frame : frames) names.push_back(frame.name);
  truth_frames_not_in(truth, o.truth_csv, names, o.source);  // refuses a truth of none of them (as rdsf-detect)
  const TrackingParams tracking;
  std::vector<EvaluatedFrame> evaluated;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    EvaluatedFrame e{frames[f].name, frames[f].index, frames[f].camera, {}};
    for (const PclPerson& p : people[f]) {
      e.candidates.push_back({p.box, p.depth_mm, p.confidence,
                              ColourHistogram::of(frames[f].bgr(p.box), frames[f].depth_mm(p.box),
                                                  tracking.histogram_bins),
                              CandidateKin{}});
    }
    evaluated.push_back(std::move(e));
  }
  const ScoreCalibration calibration;  // "none": P = 1 / (1 + exp(-2 c))
  std::vector<SweepResult> results{sweep_thresholds(evaluated, truth, default_probability_thresholds(), tracking,
                                                    "PCL ground-based HOG+SVM", calibration,
                                                    calibration.probability(o.min_confidence), o.clip_frames)};
  results.back().fps = fps;
  std::cout << write_evaluation_report(results, o.report_dir);
}

}  // namespace

int run_pcl_people(const PclPeopleOptions& o) {
  if (!o.report_dir.empty() && !o.force && std::filesystem::exists(std::filesystem::path(o.report_dir) / "metrics.csv")) {
    throw Error(o.report_dir + ": already holds a report (pass --force to replace it)");
  }
  if (!std::filesystem::is_regular_file(o.svm)) fail(o.svm, "no such file (PCL's HOG+SVM file: peers/pcl_people/data)");
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  pcl::people::PersonClassifier<pcl::RGB> classifier;
  if (!classifier.loadSVMFromFile(o.svm)) fail(o.svm, "not a PCL HOG+SVM file");
  const std::vector<DepthFrame> frames = read_frames(o);

  std::map<std::string, std::vector<const DepthFrame*>> recordings;
  for (const DepthFrame& f : frames) recordings[recording_of(f.name)].push_back(&f);
  std::map<std::string, std::optional<Eigen::Vector4f>> grounds;
  for (const auto& [name, members] : recordings) {
    grounds[name] = fit_ground(members, o.ground);
    const auto& g = grounds[name];
    std::cerr << "rdsf-pcl-people: recording '" << name << "' (" << members.size() << " frames): ";
    if (g) {
      std::cerr << "floor " << (*g)[0] << " " << (*g)[1] << " " << (*g)[2] << " " << (*g)[3] << " (camera "
                << (*g)[3] << " m above it)\n";
    } else {
      std::cerr << "no floor found: no detections in its frames\n";
    }
  }

  pcl::people::GroundBasedPeopleDetectionApp<PointT> app;
  // The frames' own camera model (camera.yml, a bag's CameraInfo, else --fx ... scaled to their size), as
  // their clouds are made with.
  const CameraModel camera = frames.empty() ? o.camera : frames.front().camera;
  Eigen::Matrix3f intrinsics;
  intrinsics << static_cast<float>(camera.fx_px), 0, static_cast<float>(camera.cx_px), 0,
      static_cast<float>(camera.fy_px), static_cast<float>(camera.cy_px), 0, 0, 1;
  app.setVoxelSize(static_cast<float>(o.voxel_size_m));
  app.setIntrinsics(intrinsics);
  app.setClassifier(classifier);
  app.setPersonClusterLimits(static_cast<float>(o.min_height_m), static_cast<float>(o.max_height_m),
                             static_cast<float>(o.min_width_m), static_cast<float>(o.max_width_m));
  std::vector<std::vector<PclPerson>> people;
  std::size_t clusters = 0, above = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const DepthFrame& f : frames) {
    const auto& g = grounds[recording_of(f.name)];
    people.push_back(g ? detect(app, f, Eigen::VectorXf(*g)) : std::vector<PclPerson>{});
    clusters += people.back().size();
    for (const PclPerson& p : people.back()) above += p.confidence >= o.min_confidence ? 1 : 0;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double fps = seconds > 0 ? static_cast<double>(frames.size()) / seconds : 0.0;
  std::cerr << "rdsf-pcl-people: " << frames.size() << " frames, " << clusters << " person clusters, " << above
            << " with confidence >= " << o.min_confidence << "; " << fps << " frames/s (PCL only)\n";
  if (!o.out_csv.empty()) write_csv(o, frames, people);
  if (!o.truth_csv.empty()) evaluate(o, frames, people, fps);
  return 0;
}

}  // namespace rdsf::peers
