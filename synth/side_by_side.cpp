// rdsf-side-by-side: pictures for docs/synthetic.md. Each row shows depth images side by side as colour
// maps (near = warm, far = cool, 0-7 m, black = no reading), each with its ground-truth boxes when a
// boxes.csv lies beside it (white; the synthetic ones labelled with their visible fraction).
//   rdsf-side-by-side OUT.jpg COLUMNS IMAGE.depth.png...   (OUT.png works too; JPEG quality 80)
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/analysis/overlay.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace {

cv::Mat3b tile(const std::string& path) {
  const cv::Mat1w depth = rdsf::read_depth_png(path);
  cv::Mat3b picture = rdsf::colourise_depth(depth, 7000);
  const std::filesystem::path file(path);
  const std::filesystem::path boxes = file.parent_path() / "boxes.csv";
  if (std::filesystem::exists(boxes)) {
    std::string name = file.filename().string();
    name = name.substr(0, name.size() - std::string(".depth.png").size());
    const rdsf::GroundTruth truth = rdsf::read_ground_truth(boxes.string());
    for (const rdsf::TruthBox& t : truth.in(name)) {
      cv::rectangle(picture, t.box, cv::Scalar(255, 255, 255), 2);
      if (t.visible_fraction < 1.0) {
        char text[16];
        std::snprintf(text, sizeof text, "%.2f", t.visible_fraction);
        cv::putText(picture, text, t.box.tl() + cv::Point(3, 22), cv::FONT_HERSHEY_SIMPLEX, 0.7,
                    cv::Scalar(255, 255, 255), 2);
      }
    }
  }
  cv::Mat3b small;
  cv::resize(picture, small, cv::Size(320, 240), 0, 0, cv::INTER_AREA);
  return small;
}

}  // namespace

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-side-by-side", [&] {
    if (argc < 4) throw rdsf::cli::UsageError("usage: rdsf-side-by-side OUT.png COLUMNS IMAGE.depth.png...");
    const int columns = std::stoi(argv[2]);
    if (columns < 1 || columns > 8) throw rdsf::cli::UsageError("COLUMNS must be 1..8");
    std::vector<cv::Mat3b> tiles;
    for (int i = 3; i < argc; ++i) tiles.push_back(tile(argv[i]));
    while (tiles.size() % static_cast<std::size_t>(columns) != 0) tiles.emplace_back(240, 320, cv::Vec3b(255, 255, 255));
    std::vector<cv::Mat> rows;
    for (std::size_t r = 0; r < tiles.size(); r += static_cast<std::size_t>(columns)) {
      cv::Mat row;
      cv::hconcat(std::vector<cv::Mat>(tiles.begin() + static_cast<std::ptrdiff_t>(r),
                                       tiles.begin() + static_cast<std::ptrdiff_t>(r) + columns), row);
      rows.push_back(row);
    }
    cv::Mat picture;
    cv::vconcat(rows, picture);
    const std::vector<int> small_jpeg = {cv::IMWRITE_JPEG_QUALITY, 80};  // ignored for PNG
    if (!cv::imwrite(argv[1], picture, small_jpeg)) rdsf::fail(argv[1], "cannot write the picture");
    return 0;
  });
}
