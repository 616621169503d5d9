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

// --thesis: every departure option not given explicitly takes the thesis's value (thesis_params()).
// Applied to the parsed values before po::notify stores them, so explicit options still win.
void apply_thesis_preset(po::variables_map& values) {
  const auto it = values.find("thesis");
  if (it == values.end() || !it->second.as<bool>()) return;
  const AnalyserParams thesis = thesis_params();
  const CandidateParams& c = thesis.candidates;
  auto set = [&values](const char* name, const boost::any& value) {
    const auto option = values.find(name);
    // In place: the entry keeps its link to the bound variable, which po::notify then stores.
    if (option != values.end() && option->second.defaulted()) option->second.value() = value;
  };
  set("left-border-jump", thesis.segmentation.left_border_jump);
  set("occlusion-gap", c.occlusion_gap_cm);
  set("floor-tolerance", c.floor_tolerance_mm);
  set("height-at-column-depth", c.height_at_column_depth);
  set("fit-reach", c.fit_reach_cm);
  set("fit-depth-step", c.fit_depth_step_mm);
  set("fit-occlusion-gap", c.fit_occlusion_gap_cm);
  set("fit-min-width-ratio", c.fit_min_width_ratio);
  set("join-pieces", c.join_pieces);
  set("max-object-width", c.max_object_width_cm);
  set("min-fitted-width", c.min_fitted_width_cm);
  set("narrow-fitted-width", c.narrow_fitted_width_cm);
  set("split-depth-jump", c.split_depth_jump_mm);
  set("split-valley", c.split_valley_cm);
  set("split-step", c.split_step_cm);
  set("split-head-drop", c.split_head_drop_cm);
  set("fit-across-head-cut", c.fit_across_head_cut);
  set("split-keep-whole", c.split_keep_whole);
  set("box", std::string("strict"));
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

po::options_description analyser_options(AnalyserParams& p) {
  po::options_description segmentation("Segmentation (depth layers)");
  auto& s = p.segmentation;
  segmentation.add_options()
      ("row-step", po::value(&s.row_step)->default_value(s.row_step), "scan every N-th row for depth jumps")
      ("depth-threshold", po::value(&s.depth_threshold_mm)->default_value(s.depth_threshold_mm),
       "a depth jump larger than this (mm) starts a depth candidate")
      ("n", po::value(&s.n)->default_value(s.n), "pixels after the jump that must stay within --range-threshold")
      ("range-threshold", po::value(&s.range_threshold_mm)->default_value(s.range_threshold_mm),
       "tolerance (mm) of the n pixels after a jump")
      ("candidate-threshold", po::value(&s.candidate_threshold_mm)->default_value(s.candidate_threshold_mm),
       "sorted depth candidates are averaged in runs spanning at most this (mm)")
      ("kmeans-iterations", po::value(&s.max_iterations)->default_value(s.max_iterations),
       "upper bound of k-means iterations")
      ("left-border-jump", po::value(&s.left_border_jump)->default_value(s.left_border_jump),
       "the left image border counts as a depth jump; 0 = thesis");
  po::options_description candidates("Candidates (shape)");
  auto& c = p.candidates;
  candidates.add_options()
      ("k", po::value(&c.k)->default_value(c.k), "gap tolerance (pixels) inside a column's run")
      ("relaxed", po::bool_switch()->notifier([&c](bool on) { if (on) c.mode = HeightMode::relaxed; }),
       "relaxed threshold_height: near_height everywhere (default strict)")
      ("near-height", po::value(&c.near_height_cm)->default_value(c.near_height_cm),
       "threshold_height (cm) for near layers and in relaxed mode")
      ("far-height", po::value(&c.far_height_cm)->default_value(c.far_height_cm),
       "threshold_height (cm) for far layers in strict mode")
      ("near-far-boundary", po::value(&c.near_far_boundary_mm)->default_value(c.near_far_boundary_mm),
       "layers nearer than this (mm) are near")
      ("column-gap", po::value(&c.column_gap)->default_value(c.column_gap),
       "gap tolerance (columns) when joining columns into an object")
      ("min-width", po::value(&c.min_width_cm)->default_value(c.min_width_cm),
       "minimum real width (cm) of a candidate")
      ("occlusion-gap", po::value(&c.occlusion_gap_cm)->default_value(c.occlusion_gap_cm),
       "a column's run goes on across nearer things up to this height (cm); 0 = thesis")
      ("floor-tolerance", po::value(&c.floor_tolerance_mm)->default_value(c.floor_tolerance_mm),
       "cut bottom rows nearer than the object's median depth by more than this (mm): floor; 0 = thesis")
      ("window-scale", po::value(&c.window_scale)->default_value(c.window_scale),
       "window = strict box enlarged by this factor")
      ("box", po::value<std::string>()->default_value(p.reported_box == BoxKind::strict ? "strict" : "fitted")
                  ->notifier([&p](const std::string& box) {
                    if (box != "fitted" && box != "strict") throw UsageError("--box: fitted or strict, got '" + box + "'");
                    p.reported_box = box == "strict" ? BoxKind::strict : BoxKind::fitted;
                  }),
       "the box detections report and assisted labelling matches (CSV, pictures, tracking, evaluation): fitted "
       "(the object's extent) or strict (the thesis's height x height/2)")
      ("height-at-column-depth", po::value(&c.height_at_column_depth)->default_value(c.height_at_column_depth),
       "a column failing threshold_height at the layer's mean depth is measured at its own; 0 = thesis")
      ("column-depth-layers-below", po::value(&c.column_depth_layers_below_mm)->default_value(c.column_depth_layers_below_mm),
       "... in layers nearer than this (mm) only")
      ("fit-reach", po::value(&c.fit_reach_cm)->default_value(c.fit_reach_cm),
       "fitted box: reach (cm) over attached pieces (arms) each side; 0 = passing columns only")
      ("fit-depth-step", po::value(&c.fit_depth_step_mm)->default_value(c.fit_depth_step_mm),
       "fitted box: a piece's mean depth within this (mm) of its neighbour's; 0 = any")
      ("fit-occlusion-gap", po::value(&c.fit_occlusion_gap_cm)->default_value(c.fit_occlusion_gap_cm),
       "fitted box: ... also across this much (cm) of nearer things in front (an arm behind a nearer person); 0 = off")
      ("fit-min-width-ratio",
       po::value(&c.fit_min_width_ratio)->default_value(c.fit_min_width_ratio, shortest_text(c.fit_min_width_ratio)),
       "fitted box: at least this fraction of its height wide, widened about its centre (limbs swung out of the "
       "layer); 0 = the layer's extent alone")
      ("join-pieces", po::value(&c.join_pieces)->default_value(c.join_pieces),
       "objects whose fitted extents touch are one when no wider than --max-person-width; 0 = thesis")
      ("join-narrow-layers-below", po::value(&c.join_narrow_layers_below_mm)->default_value(c.join_narrow_layers_below_mm),
       "pieces each narrower than --min-width join only in layers nearer than this (mm)")
      ("join-narrow-passing", po::value(&c.join_narrow_passing)->default_value(c.join_narrow_passing),
       "... and only when their passing columns alone are together at least --narrow-passing-width wide")
      ("narrow-fitted-width", po::value(&c.narrow_fitted_width_cm)->default_value(c.narrow_fitted_width_cm),
       "objects narrower than --min-width are candidates when their fitted box is this wide (cm), they are person-"
       "tall, near and have a background above their top (20 turns it on); 0 = off, the thesis")
      ("narrow-passing-width", po::value(&c.narrow_passing_width_cm)->default_value(c.narrow_passing_width_cm),
       "... and their passing columns at least this wide (cm)")
      ("narrow-layers-below", po::value(&c.narrow_layers_below_mm)->default_value(c.narrow_layers_below_mm),
       "... in layers nearer than this (mm)")
      ("narrow-min-height", po::value(&c.narrow_min_height_cm)->default_value(c.narrow_min_height_cm),
       "... at least this tall (cm)")
      ("narrow-clear-above", po::value(&c.narrow_clear_above_cm)->default_value(c.narrow_clear_above_cm),
       "... with other layers over half of this band (cm) above their top")
      ("min-fitted-width", po::value(&c.min_fitted_width_cm)->default_value(c.min_fitted_width_cm),
       "objects whose fitted box is narrower than this (cm) are not candidates (border objects exempt); 0 = thesis")
      ("max-object-width", po::value(&c.max_object_width_cm)->default_value(c.max_object_width_cm),
       "objects wider than this (cm) are walls, not candidates; 0 = thesis (no limit)")
      ("max-person-width", po::value(&c.max_person_width_cm)->default_value(c.max_person_width_cm),
       "the widest person (cm): wider objects are tried for splitting by depth jumps, valleys and steps, narrower pieces joined")
      ("split-depth-jump", po::value(&c.split_depth_jump_mm)->default_value(c.split_depth_jump_mm),
       "split a wide object where its column depth jumps by more than this (mm); 0 = off")
      ("split-valley", po::value(&c.split_valley_cm)->default_value(c.split_valley_cm),
       "... or at a valley of its height profile this deep (cm); 0 = off")
      ("split-step", po::value(&c.split_step_cm)->default_value(c.split_step_cm),
       "... or at a step of its height profile this high (cm); 0 = off")
      ("split-head-drop", po::value(&c.split_head_drop_cm)->default_value(c.split_head_drop_cm),
       "split an object of any width between two heads (tops of its height profile with shoulders at least this "
       "far below, cm: people overlapping at one depth); 0 = off, the thesis")
      ("split-head-width", po::value(&c.split_head_width_cm)->default_value(c.split_head_width_cm),
       "... a head's top (within 5 cm of its height) at most this wide (cm)")
      ("split-head-min-width", po::value(&c.split_head_min_width_cm)->default_value(c.split_head_min_width_cm),
       "... and at least this wide (cm; a raised hand is narrower)")
      ("split-head-layers-below", po::value(&c.split_head_layers_below_mm)->default_value(c.split_head_layers_below_mm),
       "... in layers nearer than this (mm)")
      ("split-head-keep-whole", po::value(&c.split_head_keep_whole)->default_value(c.split_head_keep_whole),
       "an object split between heads stays a candidate besides its pieces")
      ("fit-across-head-cut", po::value(&c.fit_across_head_cut)->default_value(c.fit_across_head_cut),
       "... the pieces' fitted boxes reach across the cut over an arm held out to the other's passing columns; "
       "0 = each side of the cut only")
      ("min-part-width", po::value(&c.min_part_width_cm)->default_value(c.min_part_width_cm),
       "the narrowest piece a split leaves (cm)")
      ("split-keep-whole", po::value(&c.split_keep_whole)->default_value(c.split_keep_whole),
       "a split object stays a candidate besides its pieces")
      ("thesis", po::bool_switch(),
       "the thesis's exact behaviour: every departure off (options given explicitly still win)");
  po::options_description all;
  all.add(segmentation).add(candidates).add(feature_spec_options(p.features));
  return all;
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

po::options_description tracking_options(TrackingParams& t) {
  po::options_description o("Tracking");
  o.add_options()
      ("threshold-lkh", po::value(&t.threshold_lkh)->default_value(t.threshold_lkh, shortest_text(t.threshold_lkh)),
       "a detection matches a person when lkh = Bhattacharyya distance + d_cm/98 - 1/49 <= this")
      ("max-missed-frames", po::value(&t.max_missed_frames)->default_value(t.max_missed_frames),
       "a person unmatched for more frames is not matched again (0: never forgotten)")
      ("histogram-bins", po::value(&t.histogram_bins)->default_value(t.histogram_bins),
       "colour histogram bins per channel");
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

po::options_description frame_source_options(FrameSourceOptions& options) {
  po::options_description o("Frame source: ROS 1 bags (--source FILE.bag)");
  o.add_options()
      ("depth-topic", po::value(&options.depth_topic),
       "the depth image topic (16UC1, mono16 or 32FC1); default: the bag's only depth image topic")
      ("colour-topic", po::value(&options.colour_topic),
       "the colour image topic (rgb8, bgr8) or 'none'; default: the bag's only colour topic of the depth's size");
  return o;
}

void apply_camera(const po::variables_map& values, const CameraModel& camera, FrameSourceOptions& options) {
  options.camera = camera;
  options.camera_given = false;
  for (const char* name : {"fx", "fy", "cx", "cy", "calibration-width", "calibration-height", "calibration-distance"}) {
    const auto it = values.find(name);
    if (it != values.end() && !it->second.defaulted()) options.camera_given = true;
  }
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
