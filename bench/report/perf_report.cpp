// rdsf-perf-report: the performance report (issue 9). In one process and on the same data: the whole
// system stage by stage against the thesis, native training per round against OpenCV's cv::ml::Boost,
// mining and labelling throughput, and memory peaks. Prints the ratios and writes a Markdown table.
#include <filesystem>
#include <iostream>

#include "cli/cli.hpp"
#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/frame/png_folder_source.hpp"
#include "peer_training.hpp"
#include "perf_run.hpp"
#include "speed_limits.hpp"

namespace {

// The real frames whose PNG reading is timed ("auto": ../shared/realdata/people beside the source tree when
// present, else "none"); refuses an --out that exists without --force and a folder without frames, before
// anything is measured.
std::string checked_real_frames(const rdsf::perf::PerfOptions& o, std::string real_frames) {
  if (!o.force && std::filesystem::exists(o.out)) {  // refused before measuring anything
    throw rdsf::Error(o.out + ": already exists (use --force to replace it)");
  }
  if (real_frames == "auto") {
    const auto beside = std::filesystem::path(RDSF_SOURCE_DIR).parent_path() / "shared/realdata/people";
    real_frames = std::filesystem::is_directory(beside) ? beside.string() : "none";
  }
  if (real_frames != "none") {  // refused before measuring anything, too
    if (!std::filesystem::is_directory(real_frames)) {
      throw rdsf::Error(real_frames + ": no such folder (--real-frames; none skips the real frames)");
    }
    rdsf::PngFolderSource(real_frames, rdsf::CameraModel::kinect_v1());  // throws when it holds no frames
  }
  return real_frames;
}

// The report's three parts (the whole system, the machine's limits, the trainers side by side), measured in
// this order, written to o.out and summarised on stdout.
int run_report(const rdsf::perf::PerfOptions& o, const std::string& real_frames, double peer_budget_s) {
  const rdsf::perf::PerfResults results = rdsf::perf::run_perf_report(o);
  // Issue 17: the machine's limits beside the figures, and the trainers side by side.
  rdsf::perf::SpeedLimitOptions limit_options;
  limit_options.quick = o.quick;
  limit_options.threads = o.threads;
  limit_options.real_frames_dir = real_frames == "none" ? std::string() : real_frames;
  const rdsf::perf::SpeedLimits limits = rdsf::perf::measure_speed_limits(limit_options);
  rdsf::perf::PeerOptions peer;
  peer.quick = o.quick;
  peer.threads = o.threads;
  peer.positives = o.positives;
  peer.negatives = o.negatives;
  peer.budget_s = peer_budget_s >= 0 ? peer_budget_s : (o.quick ? 1.0 : 20.0);
  peer.opencv_ran = results.opencv_ran;
  peer.opencv_rounds = results.opencv_b;
  peer.opencv_s_per_round = results.opencv_s_per_round;
  peer.opencv_auc = results.opencv_auc_at_b;
  const bool peers_ran = peer.budget_s > 0;
  const rdsf::perf::PeerResults peers = peers_ran ? rdsf::perf::measure_peers(peer) : rdsf::perf::PeerResults{};
  rdsf::AtomicTextFile out(o.out, o.force);
  out.stream() << rdsf::perf::perf_markdown(results) << rdsf::perf::speed_limits_markdown(limits)
               << (peers_ran ? rdsf::perf::peers_markdown(peers) : std::string());
  out.commit();
  std::cout << rdsf::perf::perf_summary(results) << rdsf::perf::speed_limits_summary(limits)
            << (peers_ran ? rdsf::perf::peers_summary(peers) : std::string()) << "report: " << o.out << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-perf-report", [&] {
    namespace po = rdsf::cli::po;
    rdsf::perf::PerfOptions o;
    double peer_budget_s = -1;
    // Real frames whose PNG reading is timed: "auto" is ../shared/realdata/people beside the source tree
    // when present (else none).
    std::string real_frames = "auto";
    po::options_description options("rdsf-perf-report");
    options.add_options()
        ("out", po::value(&o.out)->default_value(o.out), "Markdown report to write")
        ("force", po::bool_switch(&o.force), "replace an existing --out file")
        ("quick", po::bool_switch(&o.quick), "small sizes: a smoke run in well under a minute")
        ("work", po::value(&o.work_dir), "empty scratch folder for PNG frames and sample sets (default: a temporary one, removed)")
        ("threads", po::value(&o.threads)->default_value(o.threads), "threads of the parallel measurements")
        ("frames", po::value(&o.frames), "frames with people for the whole system (default 240, quick 24)")
        ("train-frames", po::value(&o.train_frames), "frames whose candidates train the pipeline's model (300, quick 40)")
        ("model-rounds", po::value(&o.model_rounds), "rounds of the pipeline's model (100, quick 20)")
        ("empty-frames", po::value(&o.empty_frames), "people-free frames mined (150, quick 16)")
        ("answers", po::value(&o.answers), "answers timed in the labelling session (300, quick 30)")
        ("positives", po::value(&o.positives), "training comparison: positive rows (5628 = hugeTree, quick 200)")
        ("negatives", po::value(&o.negatives), "training comparison: negative rows (22454 = hugeTree, quick 800)")
        ("native-rounds", po::value(&o.native_rounds), "native rounds timed (20, quick 5)")
        ("opencv-rounds", po::value(&o.opencv_rounds), "OpenCV timed at A and B rounds: A,B (1,3, quick 1,2; 0,0 skips)")
        ("peer-budget", po::value(&peer_budget_s), "seconds of training per trainer side by side (20, quick 1; 0 skips)")
        ("real-frames", po::value(&real_frames)->default_value(real_frames),
         "folder of real NAME.depth.png + NAME.rgb.png frames whose PNG reading is timed too; auto: "
         "../shared/realdata/people beside the source tree when present; none skips");
    po::variables_map values;
    const rdsf::cli::ProgramInfo info{
        "rdsf-perf-report", "[--out FILE.md] [--force] [--quick]",
        "Measures the whole system (segmentation, candidates, RDSF, classifier, tracking) on synthetic 640x480\n"
        "frames against the thesis's timing, native training against OpenCV's cv::ml::Boost per round at\n"
        "hugeTree size, mining and labelling throughput and memory peaks; prints the ratios and writes a\n"
        "Markdown report. A full run takes about 5-10 minutes on 2 cores."};
    if (!rdsf::cli::parse(argc, argv, info, options, values)) return 0;
    o.resolve();
    return run_report(o, checked_real_frames(o, real_frames), peer_budget_s);
  });
}
