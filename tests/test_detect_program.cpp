// rdsf-detect as a user meets it: --help, the CSV, the pictures, and one-line errors with exit codes.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/frame/depth_png.hpp"
#include "rdsf/version.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

// Every run here is model-free: the candidates as the core finds them, not the default model's people.
std::string detect() { return test::quote(test::program("rdsf-detect")) + " --candidates-only"; }

int count_lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// A folder with one hand-built frame: a person-sized block before a wall.
void write_scene(const test::TempDir& dir) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  write_png_atomically(dir / "scene.depth.png", frame.depth_mm);
}

}  // namespace

TEST(DetectProgram, HelpShowsEveryDefault) {
  const test::RunResult r = test::run(detect() + " --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* text : {"--source", "--out", "--save-dir", "--config", "--depth-threshold arg (=150)",
                           "--candidate-threshold arg (=700)", "--row-step arg (=10)", "--k arg (=6)",
                           "--far-height arg (=90)", "--fx arg (=525)", "--threshold-lkh arg (=0.6)"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
  }
}

TEST(DetectProgram, WritesCsvAndPictures) {
  test::TempDir dir;
  write_scene(dir);
  const test::RunResult r = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --out " +
                                      test::quote(dir / "out.csv") + " --save-dir " + test::quote(dir / "pics"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = test::file_text(dir / "out.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "frame,candidate,x,y,w,h,depth_mm,score");
  // The fitted box: the slab's extent (300, 40 wide) widened about its centre to 0.3 of its height.
  EXPECT_NE(csv.find("scene,0,266,100,108,360,2000,\n"), std::string::npos) << csv;
  // Header and the person: the two wall pieces either side, 480 px tall at 6 m (5.5 m at their own depth),
  // are taller than any person (--max-height, 250 cm by default); --max-height 0 keeps them.
  EXPECT_EQ(count_lines(csv), 1 + 1) << csv;
  const cv::Mat picture = cv::imread(dir / "pics/scene.detections.png");
  ASSERT_FALSE(picture.empty());
  EXPECT_EQ(picture.size(), cv::Size(640, 480));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv.partial"));
  const test::RunResult all = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --out " +
                                        test::quote(dir / "all.csv") + " --max-height 0");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_EQ(count_lines(test::file_text(dir / "all.csv")), 1 + 3);
}

// Depth that does not look like millimetres (TUM RGB-D's 5000 units a metre: the scene five times too far)
// gets one warning naming the frame, the median and camera.yml's depth_unit_mm; the run goes on. The scene
// in millimetres, and the same five-times values with a camera.yml stating depth_unit_mm 0.2, get none.
TEST(DetectProgram, DepthThatIsNotMillimetresIsWarnedAboutOnce) {
  test::TempDir dir;
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  const cv::Mat1w tum = frame.depth_mm * 5;
  write_png_atomically(dir / "a.depth.png", tum);
  write_png_atomically(dir / "b.depth.png", tum);
  const std::string warning = "rdsf-detect: warning: frame a: the median reading is 20000 mm, beyond a "
                              "Kinect-class camera's range: if the depth is not in millimetres, state its unit "
                              "in a camera.yml beside the frames (depth_unit_mm: 0.2";
  const test::RunResult r = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --out " +
                                      test::quote(dir / "out.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(warning), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning: frame b"), std::string::npos) << "warned twice: " << r.err;

  std::ofstream(dir / "camera.yml") << "%YAML:1.0\n---\nformat: rdsf-camera\nformat_version: 1\nwidth_px: 640\n"
                                       "height_px: 480\nfx_px: 525\nfy_px: 525\ncx_px: 319.5\ncy_px: 239.5\n"
                                       "depth_unit_mm: 0.2\n";
  const test::RunResult stated = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --out " +
                                           test::quote(dir / "stated.csv"));
  ASSERT_EQ(stated.exit_code, 0) << stated.err;
  EXPECT_EQ(stated.err.find("warning"), std::string::npos) << stated.err;

  test::TempDir mm;
  write_scene(mm);
  const test::RunResult plain = test::run(detect() + " --source " + test::quote(mm.path().string()) + " --out " +
                                          test::quote(mm / "out.csv"));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.err.find("warning"), std::string::npos) << plain.err;
}

// The camera options (cli::CameraOptions) reach the frame analyser: a calibration that makes the Kinect v1's
// model (a 640 x 480 cm surface filling the image at 5.25 m: fx = fy = 525) changes nothing, one that doubles
// the focal length (320 x 240 cm) makes the same candidates as --fx 1050 --fy 1050 and not the default's (the
// 40 px block at 2 m is then 7.6 cm wide, below min_width_cm); an incomplete calibration is a usage error.
TEST(DetectProgram, CameraOptionsReachTheAnalyser) {
  test::TempDir dir;
  write_scene(dir);
  const auto csv_with = [&](const std::string& name, const std::string& options) {
    const test::RunResult r = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --out " +
                                        test::quote(dir / name) + " --max-height 0 " + options);
    EXPECT_EQ(r.exit_code, 0) << options << "\n" << r.err;
    return test::file_text(dir / name);
  };
  const std::string plain = csv_with("plain.csv", "");
  EXPECT_EQ(count_lines(plain), 1 + 3) << plain;
  EXPECT_EQ(csv_with("kinect.csv", "--calibration-width 640 --calibration-height 480 --calibration-distance 5250"), plain);
  const std::string doubled =
      csv_with("doubled.csv", "--calibration-width 320 --calibration-height 240 --calibration-distance 5250");
  EXPECT_NE(doubled, plain);
  EXPECT_EQ(csv_with("fx.csv", "--fx 1050 --fy 1050"), doubled);
  const test::RunResult r = test::run(detect() + " --source " + test::quote(dir.path().string()) +
                                      " --calibration-width 320");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("usage error: empirical calibration"), std::string::npos) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  // The frame source options are checked with them: a negative colour pairing gap is a usage error.
  const test::RunResult gap = test::run(detect() + " --source " + test::quote(dir.path().string()) +
                                        " --colour-gap-ms -1");
  EXPECT_EQ(gap.exit_code, 2);
  EXPECT_NE(gap.err.find("usage error: --colour-gap-ms must be 0 or more"), std::string::npos) << gap.err;
  EXPECT_EQ(count_lines(gap.err), 1) << gap.err;
}

// No model named: the shipped default model scores the candidates and people are tracked.
TEST(DetectProgram, WithoutAModelTheDefaultModelRuns) {
  test::TempDir dir;
  write_scene(dir);
  const std::string program = test::quote(test::program("rdsf-detect"));
  const test::RunResult r = test::run(program + " --source " + test::quote(dir.path().string()) + " --out " +
                                      test::quote(dir / "out.csv") + " --models-dir " + test::quote(dir / "none"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("model people v4"), std::string::npos) << r.err;
  // ... which runs with the option it states (people/v4: what stands in front of its surroundings).
  EXPECT_NE(r.err.find("model people v4 states its detection options (--local-front 70): taken for the options not "
                       "given"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("people at P >= 0.27 (its operating point), none taller than 250 cm"), std::string::npos)
      << r.err;
  const std::string csv = test::file_text(dir / "out.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')).find("frame,candidate,x,y,w,h,depth_mm,score,"), 0u) << csv;
  EXPECT_EQ(count_lines(csv), 1 + 1);  // the person; the wall pieces are too tall (--max-height)
  const test::RunResult both = test::run(program + " --source x --out y.csv --candidates-only --model people");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("exclude each other"), std::string::npos) << both.err;
}

TEST(DetectProgram, BoxOptionAndThesisPreset) {
  test::TempDir dir;
  write_scene(dir);
  const std::string base = detect() + " --source " + test::quote(dir.path().string()) + " --force --out ";
  ASSERT_EQ(test::run(base + test::quote(dir / "strict.csv") + " --box strict").exit_code, 0);
  EXPECT_NE(test::file_text(dir / "strict.csv").find("scene,0,230,100,180,360,2000,\n"), std::string::npos);
  ASSERT_EQ(test::run(base + test::quote(dir / "thesis.csv") + " --thesis").exit_code, 0);
  EXPECT_NE(test::file_text(dir / "thesis.csv").find("scene,0,230,100,180,360,2000,\n"), std::string::npos);
  // An explicit option wins over the preset.
  ASSERT_EQ(test::run(base + test::quote(dir / "mixed.csv") + " --thesis --box fitted").exit_code, 0);
  EXPECT_NE(test::file_text(dir / "mixed.csv").find("scene,0,300,100,40,360,2000,\n"), std::string::npos);  // no widening
  ASSERT_EQ(test::run(base + test::quote(dir / "extent.csv") + " --fit-min-width-ratio 0").exit_code, 0);
  EXPECT_NE(test::file_text(dir / "extent.csv").find("scene,0,300,100,40,360,2000,\n"), std::string::npos);
  EXPECT_EQ(test::run(base + test::quote(dir / "bad.csv") + " --box tight").exit_code, 2);
}

// Scores are the mean of the crop's and its mirror's H(x) by default; --mirror-average 0 scores the crop
// alone, and so does --thesis unless --mirror-average is given.
TEST(DetectProgram, MirrorAveragingIsTheDefaultAndTheThesisPresetTurnsItOff) {
  test::TempDir dir;
  DepthFrame frame = test::wall_frame(4500);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  test::paint(frame, {340, 180, 25, 12}, 2000);  // an arm held out on one side: the crop is not its own mirror
  write_png_atomically(dir / "scene.depth.png", frame.depth_mm);
  const std::string base = test::quote(test::program("rdsf-detect")) + " --source " +
                           test::quote(dir.path().string()) + " --model people --models-dir " +
                           test::quote(dir / "none") + " --force --out ";
  const auto scores = [&](const std::string& name, const std::string& options) {
    const test::RunResult r = test::run(base + test::quote(dir / name) + options);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::string out;  // column 8 (score) of every row
    std::istringstream csv(test::file_text(dir / name));
    std::string line;
    std::getline(csv, line);
    while (std::getline(csv, line)) {
      std::istringstream row(line);
      std::string field;
      for (int i = 0; i < 8 && std::getline(row, field, ','); ++i) {
      }
      out += field + ";";
    }
    return out;
  };
  const std::string averaged = scores("default.csv", ""), one = scores("one.csv", " --mirror-average 0");
  ASSERT_FALSE(averaged.empty());
  EXPECT_NE(averaged, one);
  EXPECT_EQ(averaged, scores("explicit.csv", " --mirror-average 1"));
  const std::string thesis = scores("thesis.csv", " --thesis");
  EXPECT_EQ(thesis, scores("thesis-one.csv", " --thesis --mirror-average 0"));
  EXPECT_NE(thesis, scores("thesis-mirror.csv", " --thesis --mirror-average 1"));
}

TEST(DetectProgram, TruthWithoutAModelCountsThePeopleWithACandidate) {
  test::TempDir dir;
  write_scene(dir);
  std::ofstream(dir / "boxes.csv") << "frame,person,x,y,w,h\nscene,1,300,100,40,360\n";
  // The scene's person is a slab of 0.11 of its height: counted by its extent (no widened fitted box).
  const test::RunResult r = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --truth " +
                                      test::quote(dir / "boxes.csv") + " --fit-min-width-ratio 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 of 1 people have a candidate (fitted box IoU >= 0.5), 0 without; strict box: 0"),
            std::string::npos)
      << r.err;
}

// A truth that names none of the source's frames (a folder's file stems against a bag's indices) would score
// every frame as one without people: refused before the run with one line naming both namings. One naming
// some frames the source does not have is said, and the run goes on.
TEST(DetectProgram, TruthNamingNoFrameReadIsRefusedAndFramesNotReadAreSaid) {
  test::TempDir dir;
  write_scene(dir);
  std::ofstream(dir / "other.csv") << "frame,person,x,y,w,h\n0,1,300,100,40,360\n";
  const test::RunResult none = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --truth " +
                                         test::quote(dir / "other.csv"));
  EXPECT_EQ(none.exit_code, 1);
  EXPECT_NE(none.err.find("rdsf-detect: error: " + (dir / "other.csv") + ": names none of the 1 frames of " +
                          dir.path().string() + " (it names e.g. '0', the source's first frame is 'scene'"),
            std::string::npos) << none.err;
  EXPECT_EQ(count_lines(none.err), 2) << "read before refusing: " << none.err;  // the truth's line and the error

  std::ofstream(dir / "more.csv") << "frame,person,x,y,w,h\nscene,1,300,100,40,360\nabsent,1,300,100,40,360\n";
  const test::RunResult some = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --truth " +
                                         test::quote(dir / "more.csv"));
  ASSERT_EQ(some.exit_code, 0) << some.err;
  EXPECT_NE(some.err.find(dir / "more.csv" + ": 1 of its 2 frames are not in " + dir.path().string() + " (not counted)"),
            std::string::npos)
      << some.err;
}

TEST(DetectProgram, PeopleWithoutACandidateAreCountedByTheNearestCandidatesShape) {
  test::TempDir dir;
  write_scene(dir);
  // The scene's person, a box where nothing is (none) and one half as wide as the candidate (wide).
  std::ofstream(dir / "boxes.csv") << "frame,person,x,y,w,h\nscene,1,300,100,40,360\nscene,2,20,20,40,100\n"
                                      "scene,3,300,100,19,360\n";
  // The scene's person is a slab of 0.11 of its height: counted by its extent (no widened fitted box).
  const test::RunResult r = test::run(detect() + " --source " + test::quote(dir.path().string()) + " --truth " +
                                      test::quote(dir / "boxes.csv") + " --fit-min-width-ratio 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 of 3 people have a candidate (fitted box IoU >= 0.5), 2 without"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("without a candidate, by the nearest candidate's fitted box: 1 none, 1 wide"), std::string::npos)
      << r.err;
}

TEST(DetectProgram, ConfigFileAndCommandLineOverride) {
  test::TempDir dir;
  write_scene(dir);
  std::ofstream(dir / "detect.ini") << "# raise the width needed so that the person (15 cm) is dropped\nmin_width = 20\n";
  const std::string base = detect() + " --source " + test::quote(dir.path().string()) + " --config " +
                           test::quote(dir / "detect.ini") + " --force --out " + test::quote(dir / "out.csv");
  ASSERT_EQ(test::run(base).exit_code, 0);
  EXPECT_EQ(test::file_text(dir / "out.csv").find(",2000,"), std::string::npos);
  ASSERT_EQ(test::run(base + " --min_width 10").exit_code, 0);  // the command line wins
  EXPECT_NE(test::file_text(dir / "out.csv").find(",2000,"), std::string::npos);
}

// Kebab-case names are canonical; the thesis's snake_case names and --color are aliases, on the command
// line and in --config files (docs/options.md); --color is tested with rdsf-record (test_openni_*).
TEST(DetectProgram, SnakeCaseNamesAreAliases) {
  test::TempDir dir;
  write_scene(dir);
  std::ofstream(dir / "detect.ini") << "min-width = 20\n";
  const std::string base = detect() + " --source " + test::quote(dir.path().string()) + " --force --out " +
                           test::quote(dir / "out.csv");
  for (const std::string& options :
       std::vector<std::string>{" --min-width 20", " --min_width=20", " --config " + test::quote(dir / "detect.ini")}) {
    ASSERT_EQ(test::run(base + options).exit_code, 0) << options;
    EXPECT_EQ(test::file_text(dir / "out.csv").find(",2000,"), std::string::npos) << options;  // the person is dropped
  }
  const test::RunResult unknown = test::run(base + " --min_widht 20");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("min-widht"), std::string::npos) << unknown.err;
}

TEST(DetectProgram, RefusesToOverwriteWithoutForce) {
  test::TempDir dir;
  write_scene(dir);
  std::ofstream(dir / "out.csv") << "precious\n";
  const test::RunResult r =
      test::run(detect() + " --source " + test::quote(dir.path().string()) + " --out " + test::quote(dir / "out.csv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("already exists"), std::string::npos) << r.err;
  EXPECT_EQ(test::file_text(dir / "out.csv"), "precious\n");
}

// What an OpenNI2 --source is refused with: `with_openni`, or in a build without OpenNI2 one line naming it.
std::string openni_message(const std::string& spec, const std::string& with_openni) {
  return RDSF_WITH_OPENNI ? with_openni : spec + ": this build has no OpenNI2";
}

struct BadInput {
  std::string name;
  std::function<std::string(const test::TempDir&)> make;  // returns the --source argument
  std::string message;
};

// Test names show the case's name, not a dump of its bytes.
void PrintTo(const BadInput& input, std::ostream* out) { *out << input.name; }

class DetectBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(DetectBadInput, OneLineErrorAndNonZeroExit) {
  test::TempDir dir;
  const std::string source = GetParam().make(dir);
  const test::RunResult r =
      test::run(detect() + " --source " + test::quote(source) + " --out " + test::quote(dir / "out.csv"));
  EXPECT_EQ(r.exit_code, 1);
  // The error is the last line, names the input, and says what is wrong.
  const std::string last = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
  EXPECT_EQ(last.rfind("rdsf-detect: error: ", 0), 0u) << r.err;
  EXPECT_NE(last.find(GetParam().message), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("libpng"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));  // never a CSV that looks complete
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, DetectBadInput,
    ::testing::Values(
        BadInput{"missing_path", [](const test::TempDir& d) { return d / "nothing-here"; }, "nothing-here: no such file"},
        BadInput{"eight_bit",
                 [](const test::TempDir& d) {
                   cv::imwrite(d / "f.depth.png", cv::Mat1b(480, 640, std::uint8_t{9}));
                   return d.path().string();
                 },
                 "f.depth.png: 8-bit image given as depth"},
        BadInput{"colour_as_depth",
                 [](const test::TempDir& d) {
                   cv::imwrite(d / "f.depth.png", cv::Mat3b(480, 640, cv::Vec3b(1, 2, 3)));
                   return d.path().string();
                 },
                 "f.depth.png: 3-channel image given as depth"},
        BadInput{"size_mismatch",
                 [](const test::TempDir& d) {
                   cv::imwrite(d / "f.depth.png", cv::Mat1w(480, 640, std::uint16_t{1000}));
                   cv::imwrite(d / "f.rgb.png", cv::Mat3b(240, 320, cv::Vec3b(1, 2, 3)));
                   return d.path().string();
                 },
                 "f.rgb.png: colour image is 320x240 but its depth image is 640x480"},
        BadInput{"corrupt_png",
                 [](const test::TempDir& d) {
                   std::vector<unsigned char> bytes;
                   cv::imencode(".png", cv::Mat1w(480, 640, std::uint16_t{1000}), bytes);
                   bytes[bytes.size() / 2] ^= 0x5a;
                   std::ofstream(d / "f.depth.png", std::ios::binary)
                       .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
                   return d.path().string();
                 },
                 "f.depth.png: corrupt PNG"},
        BadInput{"truncated_png",
                 [](const test::TempDir& d) {
                   std::vector<unsigned char> bytes;
                   cv::imencode(".png", cv::Mat1w(480, 640, std::uint16_t{1000}), bytes);
                   std::ofstream(d / "f.depth.png", std::ios::binary)
                       .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size() / 2));
                   return d.path().string();
                 },
                 "f.depth.png: truncated PNG"},
        BadInput{"not_oni",
                 [](const test::TempDir& d) {
                   std::ofstream(d / "take.oni", std::ios::binary) << std::string(5000, 'z');
                   return d / "take.oni";
                 },
                 openni_message("take.oni", "take.oni: not a readable OpenNI recording")},
        BadInput{"no_device", [](const test::TempDir&) { return std::string("openni"); },
                 openni_message("openni", "no device attached")}),
    [](const ::testing::TestParamInfo<BadInput>& param_info) { return param_info.param.name; });

TEST(DetectProgram, UnknownOptionIsAUsageError) {
  const test::RunResult r = test::run(detect() + " --source x --no-such-option");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no-such-option"), std::string::npos) << r.err;
  EXPECT_EQ(count_lines(r.err), 1);
}

TEST(DetectProgram, ShowWithoutDisplayExplainsInsteadOfCrashing) {
  test::TempDir dir;
  write_scene(dir);
  const test::RunResult r = test::run("env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM " + detect() +
                                      " --source " + test::quote(dir.path().string()) + " --show");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
}

// --threads N: frames analysed on N threads, tracked in order: the same CSV byte for byte.
TEST(DetectProgram, ThreadCountDoesNotChangeTheCsv) {
  test::TempDir dir;
  test::write_two_person_frames(dir / "frames");
  const std::string model = std::string(RDSF_SOURCE_DIR) + "/tests/reference_models/rdsf-model-v2-tree.yml";
  const std::string base = test::quote(test::program("rdsf-detect")) + " --source " + test::quote(dir / "frames") +
                           " --model " + test::quote(model) + " --score-threshold -1000 --max-height 0";
  std::string first;
  for (const char* threads : {"1", "2", "3"}) {
    const std::string out = dir / (std::string("t") + threads + ".csv");
    const test::RunResult r = test::run(base + " --threads " + threads + " --out " + test::quote(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(std::string(threads) + " thread(s)"), std::string::npos) << r.err;
    if (first.empty()) first = test::file_text(out);
    EXPECT_EQ(test::file_text(out), first) << threads << " threads";
  }
  EXPECT_EQ(count_lines(first), 1 + 6);  // two frames of three candidates, all of them people
  const test::RunResult one = test::run(base + " --threads 2 --frames 1 --out " + test::quote(dir / "one.csv"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(count_lines(test::file_text(dir / "one.csv")), 1 + 3);
  const test::RunResult bad = test::run(base + " --threads -1 --out " + test::quote(dir / "bad.csv"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--threads must be 0 (one per core) or more"), std::string::npos) << bad.err;
}

// --live: frames pushed as they arrive (a folder paced at --fps), drops and latency percentiles printed.
TEST(DetectProgram, LiveModePrintsDropsAndLatency) {
  test::TempDir dir;
  test::write_two_person_frames(dir / "frames");
  const std::string base = detect() + " --source " + test::quote(dir / "frames");
  const test::RunResult r =
      test::run(base + " --live --threads 2 --fps 100 --max-height 0 --out " + test::quote(dir / "live.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("rdsf-detect: live: 2 frames arrived"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("paced by --fps"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 processed, 0 dropped"), std::string::npos) << r.err;  // one waiting per worker: room for both
  EXPECT_NE(r.err.find("p50 "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("p99 "), std::string::npos) << r.err;
  EXPECT_EQ(count_lines(test::file_text(dir / "live.csv")), 1 + 6);
  const test::RunResult show = test::run(base + " --live --show");
  EXPECT_EQ(show.exit_code, 2);
  EXPECT_NE(show.err.find("--live works with --out and --save-dir"), std::string::npos) << show.err;
}
