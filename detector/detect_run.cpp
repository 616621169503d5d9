#include "detector/detect_run.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include <opencv2/highgui.hpp>

#include "cli/progress.hpp"
#include "core/error.hpp"
#include "detector/detection_csv.hpp"
#include "detector/overlay.hpp"
#include "frame/depth_png.hpp"
#include "frame/frame_source.hpp"
#include "gui/display.hpp"

namespace rdsf {

int run_detect(const DetectOptions& o) {
  if (o.out_csv.empty() && o.save_dir.empty() && !o.show) {
    throw Error("nothing to do: give --out FILE.csv, --save-dir DIR or --show");
  }
  if (o.show) gui::require_display("rdsf-detect --show", "drop --show or use --save-dir to get pictures");
  const DetectorCore core(o.detector);
  auto source = open_frame_source(o.source, o.camera);
  std::unique_ptr<DetectionCsv> csv;
  if (!o.out_csv.empty()) csv = std::make_unique<DetectionCsv>(o.out_csv, o.force);
  if (!o.save_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.save_dir, ec);
    if (ec) fail(o.save_dir, "cannot create folder: " + ec.message());
  }
  std::cerr << "rdsf-detect: " << source->description() << "\n";

  cli::Progress progress(std::cerr, "frames", source->frame_count());
  DepthFrame frame;
  std::int64_t frames = 0, candidates = 0;
  StageTimes total;
  while (source->next(frame)) {
    const FrameAnalysis analysis = core.analyse(frame, /*with_features=*/false);
    total.segmentation_ms += analysis.times.segmentation_ms;
    total.candidates_ms += analysis.times.candidates_ms;
    if (csv) csv->write_frame(frame.name, analysis.candidates);
    if (!o.save_dir.empty() || o.show) {
      const cv::Mat3b picture = render_candidates(frame, analysis.segmentation, analysis.candidates);
      if (!o.save_dir.empty()) {
        write_png_atomically((std::filesystem::path(o.save_dir) / (frame.name + ".candidates.png")).string(),
                             picture);
      }
      if (o.show) {
        cv::imshow("rdsf-detect", picture);
        const int key = cv::waitKey(1);
        if (key == 'q' || key == 27) break;
      }
    }
    ++frames;
    candidates += static_cast<std::int64_t>(analysis.candidates.size());
    progress.update(frames, "candidates " + std::to_string(candidates));
  }
  progress.finish(frames, "candidates " + std::to_string(candidates));
  if (csv) csv->commit();
  if (frames > 0) {
    std::fprintf(stderr,
                 "rdsf-detect: %lld frames, %.2f candidates per frame; per frame: segmentation %.2f ms, "
                 "candidates %.2f ms\n",
                 static_cast<long long>(frames), static_cast<double>(candidates) / static_cast<double>(frames),
                 total.segmentation_ms / static_cast<double>(frames),
                 total.candidates_ms / static_cast<double>(frames));
  }
  if (!o.out_csv.empty()) std::cerr << "rdsf-detect: wrote " << o.out_csv << "\n";
  if (!o.save_dir.empty()) std::cerr << "rdsf-detect: pictures in " << o.save_dir << "\n";
  return 0;
}

}  // namespace rdsf
