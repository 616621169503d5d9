#pragma once
// The parser entry points that the fuzz targets (fuzz/fuzz_<name>.cpp) and the regression test
// (tests/test_fuzz_regressions.cpp) feed bytes to, one function per parser that reads user files.
//
// Each function gives the bytes to the parser exactly as a user's file would reach it (text parsers get the
// text, file-based readers get a temporary file holding the bytes) and may throw only rdsf::Error: any other
// exception, a crash, a sanitizer report or a hang is a bug. Where a parse succeeds, the result is written
// back in its own format and read again, which must succeed too (a file the workbench wrote must always be
// readable); a failure there throws std::logic_error, which the fuzzer and the test report as a bug.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <filesystem>

#include "rdsf/classifier/model_file.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/dataset/recipe.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_check.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set_manifest.hpp"
#include "rdsf/dataset/sample_tsv.hpp"
#include "rdsf/dataset/thesis_text.hpp"
#include "rdsf/evaluation/adaptation_results.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/camera_file.hpp"
#include "rdsf/frame/compressed_image.hpp"
#include "rdsf/labeling/adapt_state_file.hpp"
#include "rdsf/labeling/answer_journal.hpp"
#include "rdsf/version.hpp"
#if RDSF_WITH_ROSBAG
#include "rdsf/frame/bag_source.hpp"
#endif

namespace rdsf::fuzz {

/// The parsers, by the name used for fuzz/corpus/<name>/ and fuzz/regressions/<name>/.
inline const std::vector<std::string>& parser_names() {
  static const std::vector<std::string> names = {"ground_truth", "sample_tsv",  "manifest",   "thesis_text",
                                                 "model_file",   "answer_journal", "depth_crop", "model_writer",
                                                 "recipe", "camera_yml", "adapt_state", "adaptation_results",
                                                 "compressed_image"
#if RDSF_WITH_ROSBAG
                                                 , "bag"
#endif
  };
  return names;
}

/// A private folder for the temporary files of this process (removed at exit).
class ScratchFolder {
 public:
  ScratchFolder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/rdsf-fuzz-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (::mkdtemp(buffer.data()) == nullptr) throw std::runtime_error("cannot create " + pattern);
    path_ = buffer.data();
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::string& folder() const { return path_; }
  /// The folder's one input file.
  std::string input_path() const { return path_ + "/input"; }
  /// Writes `bytes` to the input file and returns its path.
  std::string write(const std::string& bytes) const {
    const std::string file = input_path();
    std::remove((file + ".tmp").c_str());
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write " + file);
    return file;
  }

 private:
  std::string path_;
};

inline const ScratchFolder& scratch() {
  static const ScratchFolder folder;
  return folder;
}

inline void require(bool condition, const std::string& what) {
  if (!condition) throw std::logic_error(what);
}

/// boxes.csv (evaluation/ground_truth.hpp).
inline void parse_ground_truth_bytes(const std::string& bytes) {
  const GroundTruth truth = parse_ground_truth(bytes, "fuzz/boxes.csv");
  std::size_t people = 0;
  for (const auto& [frame, boxes] : truth.frames) {
    require(!frame.empty(), "ground truth: empty frame name accepted");
    for (const TruthBox& box : boxes) {
      require(box.box.width > 0 && box.box.height > 0, "ground truth: box without area accepted");
      require(box.visible_fraction >= 0.0 && box.visible_fraction <= 1.0, "ground truth: fraction out of [0, 1]");
    }
    people += boxes.size();
  }
  require(people == truth.people(), "ground truth: people() disagrees with the frames");
}

/// samples.tsv of a sample set (dataset/sample_tsv.hpp); file-based reader.
inline void parse_sample_tsv_bytes(const std::string& bytes) {
  const SampleTsvContents contents = read_sample_tsv(scratch().write(bytes));
  require(contents.complete_bytes <= bytes.size(), "samples.tsv: complete_bytes beyond the end of the file");
  for (const SampleRecord& record : contents.records) {
    const std::string row = format_sample_row(record);
    const SampleRecord again = parse_sample_row(row, "fuzz/samples.tsv (written back)");
    require(format_sample_row(again) == row, "samples.tsv: a row does not survive writing and reading back");
  }
}

/// manifest.yml of a sample set (dataset/sample_set_manifest.hpp).
inline void parse_manifest_bytes(const std::string& bytes) {
  const SampleSetManifest manifest = SampleSetManifest::parse(bytes, "fuzz/manifest.yml");
  try {
    // Text fields holding control characters may come back changed (OpenCV's YAML escapes are not
    // symmetric); the feature spec and camera must come back exactly.
    const SampleSetManifest again = SampleSetManifest::parse(manifest.to_text(), "fuzz/manifest.yml (written back)");
    require(again.feature_spec == manifest.feature_spec && again.camera == manifest.camera,
            "manifest: the feature spec or camera changes when written back");
  } catch (const Error& e) {
    throw std::logic_error(std::string("manifest: written back, it no longer reads: ") + e.what());
  }
}

/// The thesis text import format (dataset/thesis_text.hpp), checked for a small dimension so that the
/// fuzzer can reach complete lines; file-based reader.
inline constexpr int kThesisFuzzDimension = 4;
inline void parse_thesis_text_bytes(const std::string& bytes) {
  const std::int64_t lines = check_thesis_text(scratch().write(bytes), kThesisFuzzDimension);
  require(lines > 0, "thesis text: a file of no samples accepted");
}

/// A model file (classifier/model_file.hpp), checked against the default feature spec; file-based reader.
inline void parse_model_file_bytes(const std::string& bytes) {
  const BoostedModel model = read_model_file(scratch().write(bytes));
  std::vector<float> features(static_cast<std::size_t>(model.feature_spec().dimension()), 0.5f);
  (void)model.score(features.data());
  const std::string text = model_file_text(model);
  try {
    const BoostedModel again = read_model_file(scratch().write(text));
    require(again.weak_classifiers().size() == model.weak_classifiers().size(),
            "model file: the weak classifiers change when written back");
  } catch (const Error& e) {
    throw std::logic_error(std::string("model file: written back, it no longer reads: ") + e.what());
  }
}

/// The labeler's answer journal (labeling/answer_journal.hpp); file-based (it may repair a torn last line).
inline void parse_answer_journal_bytes(const std::string& bytes) {
  const AnswerJournal journal(scratch().write(bytes));
  require(journal.answers_in_force() <= bytes.size(), "answer journal: more answers than bytes");
}

/// A crop file of a sample set (dataset/sample_set.hpp, dataset/sample_set_check.hpp): the bytes replace the
/// depth crop of the one sample of a set made for the purpose. Reading it and checking the set may only
/// refuse it with an rdsf::Error naming the file; a crop the reader accepts must pass the check too.
inline void parse_depth_crop_bytes(const std::string& bytes) {
  const std::string set = scratch().folder() + "/set";
  std::error_code ec;
  if (!std::filesystem::exists(set + "/manifest.yml", ec)) {
    SampleSetWriter writer = SampleSetWriter::open_or_create(set, FeatureSpec{}, CameraModel::kinect_v1(), "fuzz");
    SampleRecord record;
    record.label = 1;
    record.origin = "fuzz";
    record.source = "fuzz";
    record.frame = "0";
    writer.append(record, cv::Mat1w(128, 64, static_cast<std::uint16_t>(2500)));
  }
  const std::string crop = set + "/crops/00000001.depth.png";
  std::ofstream(crop, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const std::vector<SetProblem> problems = check_sample_set(set);
  const SampleSet read = SampleSet::open_read(set);
  (void)read.depth_crop(0);  // throws Error for a bad crop
  require(problems.empty(), "depth crop: read fine but --check reports " + (problems.empty() ? "" : problems[0].what));
}

/// The model writer (classifier/model_registry.hpp): a model read from the bytes is saved as a new version
/// through core/durable_io and read back, which must give the same text.
inline void parse_model_writer_bytes(const std::string& bytes) {
  BoostedModel model = read_model_file(scratch().write(bytes));
  const std::string models = scratch().folder() + "/models";
  std::error_code ec;
  std::filesystem::remove_all(models, ec);
  const std::string path = save_new_model_version(model, "fuzz", models);
  try {
    const BoostedModel again = read_model_file(path);
    require(model_file_text(again) == model_file_text(model), "model writer: the saved file reads back different");
  } catch (const Error& e) {
    throw std::logic_error(std::string("model writer: the saved model no longer reads: ") + e.what());
  }
}

/// A training recipe (dataset/recipe.hpp): what it reads must be trainable parameters.
inline void parse_recipe_bytes(const std::string& bytes) {
  const Recipe recipe = parse_recipe(bytes, "fuzz/recipe.yml");
  require(recipe.path == "fuzz/recipe.yml", "recipe: the path it came from is lost");
  try {
    validate_training_params(recipe.params);
  } catch (const Error& e) {
    throw std::logic_error(std::string("recipe: accepted parameters that do not validate: ") + e.what());
  }
}

/// camera.yml beside PNG frames (frame/camera_file.hpp): what it accepts is written back and reads the same.
inline void parse_camera_yml_bytes(const std::string& bytes) {
  const CameraFile file = parse_camera_file(bytes, "fuzz/camera.yml");
  require(file.camera.fx_px > 0 && file.camera.fy_px > 0 && file.depth_unit_mm > 0, "camera.yml: bad values accepted");
  try {
    const CameraFile again = parse_camera_file(camera_file_text(file), "fuzz/camera.yml (written back)");
    require(again.camera == file.camera && again.depth_unit_mm == file.depth_unit_mm,
            "camera.yml: the model changes when written back");
  } catch (const Error& e) {
    throw std::logic_error(std::string("camera.yml: written back, it no longer reads: ") + e.what());
  }
}

/// A sensor_msgs/CompressedImage payload of a bag (frame/compressed_image.hpp): the bytes up to the first
/// newline are the message's format, the rest its data; compressedDepth decoded to depth, any other format to
/// colour. A decoded image must be of a sane size.
inline void parse_compressed_image_bytes(const std::string& bytes) {
  const auto newline = bytes.find('\n');
  const std::string format = bytes.substr(0, newline);
  const std::string data = newline == std::string::npos ? std::string() : bytes.substr(newline + 1);
  const auto* begin = reinterpret_cast<const std::uint8_t*>(data.data());
  const cv::Mat image = is_compressed_depth_format(format)
                            ? cv::Mat(decode_compressed_depth("fuzz/compressed_image", format, begin, data.size()))
                            : cv::Mat(decode_compressed_colour("fuzz/compressed_image", format, begin, data.size()));
  require(!image.empty() && image.total() <= (std::size_t{1} << 30), "compressed image: an empty or huge image returned");
}

/// rdsf-adapt's state file, adapt-state.tsv (labeling/adapt_state_file.hpp); file-based reader: what it reads
/// is written back and reads the same.
inline void parse_adapt_state_bytes(const std::string& bytes) {
  const std::string path = scratch().write(bytes);
  const AdaptStateValues values = read_adapt_state(path);
  try {
    const std::string text = adapt_state_text(values, path);
    require(parse_adapt_state(text, path) == values, "adapt-state.tsv: the values change when written back");
  } catch (const Error& e) {
    throw std::logic_error(std::string("adapt-state.tsv: written back, it no longer reads: ") + e.what());
  }
}

/// The adaptation benchmark's results.tsv (evaluation/adaptation_results.hpp), read and drawn as rdsf-adapt
/// --chart draws it.
inline void parse_adaptation_results_bytes(const std::string& bytes) {
  const std::vector<AdaptationResult> results = parse_adaptation_results(bytes, "fuzz/results.tsv");
  for (const AdaptationResult& r : results) {
    require(!r.mode.empty() && r.tar >= 0 && r.tar <= 1 && r.answers >= 0 && r.budget >= 0 && r.train_s >= 0,
            "results.tsv: a value out of its range accepted");
  }
  const cv::Mat3b chart = draw_adaptation_chart(results);
  require(!chart.empty(), "results.tsv: no chart drawn");
}

#if RDSF_WITH_ROSBAG
/// A ROS 1 bag (frame/bag_source.hpp) read to its end: every frame delivered must be of its camera model's
/// size, with colour (when any) of the same size; file-based reader (librosbag reads files).
inline void parse_bag_bytes(const std::string& bytes) {
  BagSource source(scratch().write(bytes), FrameSourceOptions{});
  DepthFrame frame;
  std::int64_t frames = 0;
  while (source.next(frame)) {
    require(frame.depth_mm.cols == frame.camera.width_px && frame.depth_mm.rows == frame.camera.height_px,
            "bag: a frame of another size than its camera model delivered");
    require(frame.bgr.empty() || frame.bgr.size() == frame.depth_mm.size(), "bag: colour of another size delivered");
    ++frames;
  }
  require(frames == source.frame_count().value_or(-1), "bag: fewer frames delivered than counted");
}
#endif

/// Dispatch by parser name (see parser_names()). An rdsf::Error is passed on only when its message is the
/// project's one line naming the file ("fuzz/..." for text parsers, the temporary input for file readers);
/// a message that breaks the rule becomes std::logic_error.
inline void parse_bytes(const std::string& parser, const std::string& bytes) {
  try {
    if (parser == "ground_truth") return parse_ground_truth_bytes(bytes);
    if (parser == "sample_tsv") return parse_sample_tsv_bytes(bytes);
    if (parser == "manifest") return parse_manifest_bytes(bytes);
    if (parser == "thesis_text") return parse_thesis_text_bytes(bytes);
    if (parser == "model_file") return parse_model_file_bytes(bytes);
    if (parser == "answer_journal") return parse_answer_journal_bytes(bytes);
    if (parser == "depth_crop") return parse_depth_crop_bytes(bytes);
    if (parser == "model_writer") return parse_model_writer_bytes(bytes);
    if (parser == "recipe") return parse_recipe_bytes(bytes);
    if (parser == "camera_yml") return parse_camera_yml_bytes(bytes);
    if (parser == "adapt_state") return parse_adapt_state_bytes(bytes);
    if (parser == "adaptation_results") return parse_adaptation_results_bytes(bytes);
    if (parser == "compressed_image") return parse_compressed_image_bytes(bytes);
#if RDSF_WITH_ROSBAG
    if (parser == "bag") return parse_bag_bytes(bytes);
#endif
  } catch (const Error& e) {
    const std::string message = e.what();
    require(message.find('\n') == std::string::npos, parser + ": error message of more than one line: " + message);
    require(message.rfind("fuzz/", 0) == 0 || message.rfind(scratch().folder() + "/", 0) == 0,
            parser + ": error message does not start with the file name: " + message);
    throw;
  }
  throw std::invalid_argument("no parser named '" + parser + "'");
}

/// What a fuzz target does with one input: rdsf::Error is the expected answer to bad input and is
/// swallowed; anything else escapes (libFuzzer reports an uncaught exception as a crash).
inline int fuzz_one(const std::string& parser, const unsigned char* data, std::size_t size) {
  try {
    parse_bytes(parser, std::string(reinterpret_cast<const char*>(data), size));
  } catch (const Error&) {
  }
  return 0;
}

}  // namespace rdsf::fuzz
