#include "cli/cli.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <iostream>

#include <opencv2/core.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/version.hpp"

namespace rdsf::cli {

namespace {

// Printed at the end of every --help (docs/options.md states the convention).
const char* const kNamingNote =
    "Option names are kebab-case with British spelling. The thesis's snake_case names are aliases (--row_step\n"
    "is --row-step, also in --config files), and so is --color for --colour.";

// --thesis: every departure option not given explicitly takes the thesis's value (the rows of
// analyser_parameters() and decision_parameters() that declare one). Applied to the parsed values before
// po::notify stores them, so explicit options still win.
void apply_thesis_preset(po::variables_map& values) {
  const auto it = values.find("thesis");
  if (it == values.end() || !it->second.as<bool>()) return;
  // In place: the entry keeps its link to its notifier, which po::notify then calls with this value.
  const auto preset = [&values](const std::string& name, const std::optional<ParameterValue>& thesis) {
    const auto option = values.find(name);
    if (!thesis || option == values.end() || !option->second.defaulted()) return;
    option->second.value() = std::visit([](const auto& v) { return boost::any(v); }, *thesis);
  };
  for (const Parameter<AnalyserParams>& row : analyser_parameters()) preset(row.name, row.thesis);
  for (const Parameter<PipelineParams>& row : decision_parameters()) preset(row.name, row.thesis);
}

// Spellings accepted besides the canonical ones (which are kebab-case and British).
const std::pair<const char*, const char*> kSpellingAliases[] = {{"color", "colour"}};

// Rewrites every "--name" / "--name=value" token to its canonical name; stops at a bare "--".
std::vector<std::string> canonical_arguments(int argc, char** argv) {
  std::vector<std::string> arguments;
  bool options_end = false;
  for (int i = 1; i < argc; ++i) {
    std::string token = argv[i];
    if (token == "--") options_end = true;
    if (!options_end && token.size() > 2 && token.compare(0, 2, "--") == 0) {
      const std::size_t end = std::min(token.find('='), token.size());
      token = "--" + canonical_option_name(token.substr(2, end - 2)) + token.substr(end);
    }
    arguments.push_back(std::move(token));
  }
  return arguments;
}

// The text of an INI file with every "name = value" key rewritten to its canonical name.
std::string canonical_config(std::istream& in) {
  std::string text;
  for (std::string line; std::getline(in, line);) {
    const std::size_t start = line.find_first_not_of(" \t");
    const std::size_t equals = line.find('=');
    if (start != std::string::npos && equals != std::string::npos && line[start] != '#' && line[start] != ';' &&
        line[start] != '[') {
      std::size_t end = equals;
      while (end > start && (line[end - 1] == ' ' || line[end - 1] == '\t')) --end;
      line = line.substr(0, start) + canonical_option_name(line.substr(start, end - start)) + line.substr(end);
    }
    text += line + "\n";
  }
  return text;
}

}  // namespace

std::string shortest_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string canonical_option_name(const std::string& name) {
  std::string canonical = name;
  std::replace(canonical.begin(), canonical.end(), '_', '-');
  for (const auto& [alias, target] : kSpellingAliases) {
    if (canonical == alias) return target;
  }
  return canonical;
}

bool parse(int argc, char** argv, const ProgramInfo& info, const po::options_description& options,
           po::variables_map& values, const po::positional_options_description* positional) {
  po::options_description general("General");
  general.add_options()("help,h", "show this help with every default and exit")(
      "version", "show the workbench's version (and whether it reads OpenNI2) and exit")(
      "config", po::value<std::string>(), "read options from an INI file (name = value); the command line wins");
  po::options_description all;
  all.add(general).add(options);
  try {
    po::command_line_parser parser(canonical_arguments(argc, argv));
    parser.options(all);
    if (positional != nullptr) parser.positional(*positional);
    po::store(parser.run(), values);
    if (values.count("help")) {
      std::cout << "Usage: " << info.name << " " << info.usage << "\n\n" << info.summary << "\n\n" << all << "\n"
                << kNamingNote << "\n";
      return false;
    }
    if (values.count("version")) {
      std::cout << info.name << " " << version() << (has_openni() ? "" : " (built without OpenNI2)") << "\n";
      return false;
    }
    if (values.count("config")) {
      const std::string path = values["config"].as<std::string>();
      std::ifstream in(path);
      if (!in) throw UsageError(path + ": config file cannot be opened");
      std::istringstream canonical(canonical_config(in));
      try {
        po::store(po::parse_config_file(canonical, options), values);
      } catch (const po::error& e) {
        throw UsageError(path + ": " + e.what());
      }
    }
    apply_thesis_preset(values);
    po::notify(values);
  } catch (const po::error& e) {
    throw UsageError(std::string(e.what()) + " (see " + info.name + " --help)");
  }
  return true;
}

po::options_description analyser_options(AnalyserParams& p, bool feature_spec) {
  const ParameterTable<AnalyserParams>& rows = analyser_parameters();
  const std::size_t segmentation_rows = segmentation_parameters().size();
  po::options_description segmentation("Segmentation (depth layers)");
  add_table_options(segmentation, ParameterTable<AnalyserParams>(rows.begin(), rows.begin() + segmentation_rows), p);
  po::options_description candidates("Candidates (shape)");
  add_table_options(candidates, ParameterTable<AnalyserParams>(rows.begin() + segmentation_rows, rows.end()), p);
  candidates.add_options()("thesis", po::bool_switch(),
                           "the thesis's exact behaviour: every departure off, and no detection option a model states "
                           "taken (options given explicitly still win)");
  po::options_description all;
  all.add(segmentation).add(candidates);
  if (feature_spec) all.add(feature_spec_options(p.features));
  return all;
}

GivenOptions given_analyser_options(const po::variables_map& values) {
  GivenOptions given;
  for (const Parameter<AnalyserParams>& row : analyser_parameters()) {
    const auto it = values.find(row.name);
    if (it != values.end() && !it->second.defaulted()) given.keys.push_back(parameter_key(row.name));
  }
  const auto thesis = values.find("thesis");
  given.take_stated = thesis == values.end() || !thesis->second.as<bool>();
  return given;
}

std::vector<std::string> analyser_arguments(const RecordedParameters& options) {
  std::vector<std::string> out;
  for (const auto& [key, text] : options) {
    const std::string name = canonical_option_name(key);
    const Parameter<AnalyserParams>* row = find_parameter(analyser_parameters(), name);
    if (row != nullptr && row->is_switch) {
      out.push_back("--" + name + "=" + text);
      continue;
    }
    out.insert(out.end(), {"--" + name, text});
  }
  return out;
}

po::options_description background_options(std::string& dir, BackgroundParams& params) {
  po::options_description group("Background model of the room (static camera only; off by default)");
  group.add_options()("background", po::value(&dir),
                      "a background model learned by rdsf-background (a folder): whatever stands in front of the room "
                      "is also a candidate, beside the depth layers' candidates");
  add_table_options(group, background_parameters(), params);
  return group;
}

void apply_background(const std::string& dir, AnalyserParams& analyser) {
  if (dir.empty()) return;
  analyser.background = std::make_shared<const BackgroundModel>(read_background(dir));
}

po::options_description feature_spec_options(FeatureSpec& spec) {
  po::options_description features("Features");
  features.add_options()(
      "feature-spec",
      po::value<std::string>()->default_value(spec.option_text())->notifier([&spec](const std::string& text) {
        try {
          spec = FeatureSpec::parse(text);
        } catch (const Error& e) {
          throw UsageError(std::string("--feature-spec: ") + e.what());
        }
      }),
      "RDSF regions: rdsf (the thesis's 128 cells of 8x8 px, 8128 features) or rdsf-rect (the paper's squares of "
      "8-64 px at an 8 px stride, 120,786 features), optionally with parameters, e.g. "
      "rdsf-rect:min=8,max=32,stride=8 (keys: rdsf cell; rdsf-rect min, max, step, stride; both bin, clamp in mm)");
  return features;
}

void add_decision_options(po::options_description& group, PipelineParams& p) {
  const ParameterTable<PipelineParams>& rows = decision_parameters();
  add_table_options(group, rows_between(rows, "threshold", "threshold"), p);
  group.add_options()("score-threshold", po::value<double>()->notifier([&p](double h) { p.score_threshold = h; }),
                      "instead of --threshold: a person when H(x) >= this (the thesis's threshold_classifier)");
  add_table_options(group, rows_between(rows, "mirror-average", "suppress-duplicates"), p);
}

po::options_description tracking_options(TrackingParams& t) {
  po::options_description o("Tracking");
  add_table_options(o, tracking_parameters(), t);
  return o;
}

std::vector<double> parse_thresholds(const std::string& text) {
  if (text.empty()) return {40, 20, 10, 0, -5, -10, -15, -20, -25, -30, -40, -60};
  std::vector<double> values;
  auto number = [&](const std::string& part) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size() || !std::isfinite(v)) {
      throw UsageError("--thresholds: '" + part + "' is not a number (give 40,20,0 or from:to:step)");
    }
    return v;
  };
  if (text.find(':') != std::string::npos) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
    if (parts.size() != 3) throw UsageError("--thresholds: a range is from:to:step, got '" + text + "'");
    const double from = number(parts[0]), to = number(parts[1]), step = std::abs(number(parts[2]));
    if (step <= 0 || std::abs(to - from) / step > 10000) throw UsageError("--thresholds: bad step in '" + text + "'");
    const double direction = to >= from ? 1.0 : -1.0;
    for (double v = from; direction * (to - v) >= -1e-9; v += direction * step) values.push_back(v);
    return values;
  }
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) values.push_back(number(part));
  return values;
}

namespace {

// Options of the camera model (Kinect v1 defaults, or the thesis's empirical calibration).
po::options_description camera_options(CameraModel& camera, EmpiricalCalibration& calibration) {
  po::options_description o("Camera model (default: Kinect v1, depth registered to colour)");
  o.add_options()
      ("fx", po::value(&camera.fx_px)->default_value(camera.fx_px), "focal length x (px) at 640x480")
      ("fy", po::value(&camera.fy_px)->default_value(camera.fy_px), "focal length y (px) at 640x480")
      ("cx", po::value(&camera.cx_px)->default_value(camera.cx_px), "principal point x (px)")
      ("cy", po::value(&camera.cy_px)->default_value(camera.cy_px), "principal point y (px)")
      ("calibration-width", po::value(&calibration.surface_width_cm),
       "thesis calibration: width (cm) of a surface that fills the image ...")
      ("calibration-height", po::value(&calibration.surface_height_cm), "... its height (cm) ...")
      ("calibration-distance", po::value(&calibration.distance_mm), "... at this distance (mm); overrides fx/fy");
  return o;
}

// Applies a given empirical calibration to `camera` (after parse()).
void apply_calibration(CameraModel& camera, const EmpiricalCalibration& calibration) {
  const bool any = calibration.surface_width_cm != 0 || calibration.surface_height_cm != 0 ||
                   calibration.distance_mm != 0;
  if (!any) return;
  try {
    camera = CameraModel::from_empirical(calibration, camera.width_px, camera.height_px);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

// Options of frame sources beyond --source (a bag's topics), bound to `options`.
po::options_description frame_source_options(FrameSourceOptions& options) {
  po::options_description o("Frame source: ROS 1 bags (--source FILE.bag)");
  o.add_options()
      ("depth-topic", po::value(&options.depth_topic),
       "the depth image topic (16UC1, mono16 or 32FC1, or a compressedDepth topic); default: the bag's only depth "
       "image topic")
      ("colour-topic", po::value(&options.colour_topic),
       "the colour image topic (rgb8, bgr8, or a jpeg/png compressed topic) or 'none'; default: the bag's only "
       "colour topic of the depth's size")
      ("colour-gap-ms", po::value(&options.colour_gap_ms)->default_value(options.colour_gap_ms),
       "the largest stamp gap of a depth frame and the colour frame paired with it (ms)");
  return o;
}

// Completes `options` after parse(): the camera model and whether the user gave it (--fx, --fy, --cx, --cy
// or the calibration options not left at their defaults), so that it wins over a source's own model.
void apply_camera(const po::variables_map& values, const CameraModel& camera, FrameSourceOptions& options) {
  options.camera = camera;
  options.camera_given = false;
  for (const char* name : {"fx", "fy", "cx", "cy", "calibration-width", "calibration-height", "calibration-distance"}) {
    const auto it = values.find(name);
    if (it != values.end() && !it->second.defaulted()) options.camera_given = true;
  }
}

}  // namespace

bool parse(int argc, char** argv, const ProgramInfo& info, const po::options_description& options,
           po::variables_map& values, CameraOptions& camera) {
  if (!parse(argc, argv, info, options, values)) return false;
  camera.apply(values);
  return true;
}

CameraOptions::CameraOptions(po::options_description& options, CameraModel& camera, FrameSourceOptions* frames)
    : camera_(camera), frames_(frames) {
  options.add(camera_options(camera_, calibration_));
  if (frames_ != nullptr) options.add(frame_source_options(*frames_));
}

void CameraOptions::apply(const po::variables_map& values) {
  apply_calibration(camera_, calibration_);
  if (frames_ == nullptr) return;
  apply_camera(values, camera_, *frames_);
  if (!(frames_->colour_gap_ms >= 0)) throw UsageError("--colour-gap-ms must be 0 or more");
}

int run(const std::string& program_name, const std::function<int()>& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    std::cerr << program_name << ": usage error: " << e.what() << "\n";
    return 2;
  } catch (const AlreadyExists& e) {
    std::cerr << program_name << ": error: " << e.what() << " (pass --force to replace it)\n";
    return 1;
  } catch (const Error& e) {
    std::cerr << program_name << ": error: " << e.what() << "\n";
    return 1;
  } catch (const cv::Exception& e) {
    std::cerr << program_name << ": error: OpenCV: " << e.err << " (" << e.func << ")\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << program_name << ": error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace rdsf::cli
