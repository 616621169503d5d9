// A model's stated detection options (pipeline/stated_options.hpp): the options a user gives keep their
// values, the model's fill the rest, --thesis takes none; the pipeline runs the model with them; rdsf-detect
// writes the same rows for a model stating an option as for the option given, refuses two models that would
// need other candidates, and says what the model states; rdsf-mine --model mines their candidates; sets
// record the options their candidates were found with and rdsf-train states what they all record; rdsf-train
// refuses bad --detection-options.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rdsf/classifier/model_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set_manifest.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"
#include "rdsf/pipeline/stated_options.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string shipped(const std::string& name) { return std::string(RDSF_SOURCE_DIR) + "/models/people/" + name; }

BoostedModel stating(const AnalyserParams& params) {
  BoostedModel model = BoostedModel::load(shipped("v2.yml"));
  model.set_detection_options(stated_options(params));
  return model;
}

// `frames` frames of a small synthetic room (seed 7) in `dir`/room.
bool render_room(const test::TempDir& dir, int frames) {
  return test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(dir / "room") + " --force --frames " +
                   std::to_string(frames) + " --people 1..2 --clip-frames " + std::to_string(frames) + " --seed 7")
             .exit_code == 0;
}

// people/v2 stating --hole-gap 20 --k 8, written as `dir`/stating.yml; its path.
std::string write_stating_model(const test::TempDir& dir) {
  AnalyserParams params;
  params.candidates.hole_gap_cm = 20;
  params.candidates.k = 8;
  const std::string path = dir / "stating.yml";
  std::ofstream out(path);
  out << model_file_text(stating(params));
  return path;
}

// rdsf-detect on `dir`/room, writing to the path that follows.
std::string detect_command(const test::TempDir& dir) {
  return test::quote(test::program("rdsf-detect")) + " --source " + test::quote(dir / "room") + " --threads 2 --force --out ";
}

// The rows rdsf-detect writes to `dir`/`name` with `options` (it must succeed).
std::string detect_rows(const test::TempDir& dir, const std::string& name, const std::string& options) {
  const test::RunResult r = test::run(detect_command(dir) + test::quote(dir / name) + " " + options);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return test::file_text(dir / name);
}

}  // namespace

TEST(StatedOptions, TextIsReadAsTheRowsType) {
  EXPECT_EQ(parameter_value_of_text("1", ParameterValue(false), "x"), ParameterValue(true));
  EXPECT_EQ(parameter_value_of_text("0", ParameterValue(true), "x"), ParameterValue(false));
  EXPECT_EQ(parameter_value_of_text("7", ParameterValue(0), "x"), ParameterValue(7));
  EXPECT_EQ(parameter_value_of_text("0.3", ParameterValue(0.0), "x"), ParameterValue(0.3));
  EXPECT_EQ(parameter_value_of_text("1500", ParameterValue(0.0), "x"), ParameterValue(1500.0));
  EXPECT_EQ(parameter_value_of_text("fitted", ParameterValue(std::string()), "x"), ParameterValue(std::string("fitted")));
  EXPECT_NE(test::error_message([] { parameter_value_of_text("2", ParameterValue(false), "relaxed"); })
                .find("relaxed must be 0 or 1"),
            std::string::npos);
  EXPECT_NE(test::error_message([] { parameter_value_of_text("1.5", ParameterValue(0), "k"); })
                .find("k must be an integer, not '1.5'"),
            std::string::npos);
  EXPECT_THROW(parameter_value_of_text("", ParameterValue(0.0), "x"), Error);
  EXPECT_THROW(parameter_value_of_text("1e999", ParameterValue(0.0), "x"), Error);
  EXPECT_THROW(parameter_value_of_text("inf", ParameterValue(0.0), "x"), Error);
  EXPECT_THROW(parameter_value_of_text("nan", ParameterValue(0.0), "x"), Error);
  EXPECT_THROW(parameter_value_of_text("3x", ParameterValue(0), "x"), Error);
}

// Every analyser option is stated, at its value; the departures are what differs from the defaults.
TEST(StatedOptions, AModelStatesEveryOptionAndItsDeparturesAreNamed) {
  AnalyserParams params;
  const RecordedParameters defaults = stated_options(params);
  EXPECT_EQ(defaults.size(), analyser_parameters().size());
  EXPECT_TRUE(departures_from_defaults(defaults).empty());
  params.candidates.hole_gap_cm = 20;
  params.candidates.k = 8;
  params.reported_box = BoxKind::strict;
  EXPECT_EQ(option_words(departures_from_defaults(stated_options(params))), "--k 8 --hole-gap 20 --box strict");
}

// Given options keep their values, the model fills the rest, --thesis (take_stated false) or no model leaves
// the parameters as they are.
TEST(StatedOptions, GivenOptionsKeepTheirValuesAndTheModelFillsTheRest) {
  AnalyserParams model_params;
  model_params.candidates.hole_gap_cm = 20;
  model_params.candidates.k = 8;
  const BoostedModel model = stating(model_params);
  AnalyserParams user;
  user.candidates.k = 4;
  GivenOptions given;
  given.keys = {"k"};
  const AnalyserParams run = given.for_model(user, &model);
  EXPECT_EQ(run.candidates.k, 4);
  EXPECT_EQ(run.candidates.hole_gap_cm, 20.0);
  EXPECT_EQ(GivenOptions{}.for_model(user, &model).candidates.k, 8);  // nothing given: the model's every value
  GivenOptions thesis;
  thesis.take_stated = false;
  EXPECT_EQ(thesis.for_model(user, &model).candidates.hole_gap_cm, 0.0);
  EXPECT_EQ(given.for_model(user, nullptr).candidates.hole_gap_cm, 0.0);
  const BoostedModel none = BoostedModel::load(shipped("v2.yml"));  // states nothing: the user's values
  EXPECT_EQ(stated_options(GivenOptions{}.for_model(user, &none)), stated_options(user));
}

// The pipeline runs the model with its stated options: a model stating a minimum width no object has finds
// no candidate; the option given, or no model, finds them; params() says what ran.
TEST(StatedOptions, ThePipelineRunsTheModelWithThem) {
  DepthFrame frame = test::wall_frame(4500);
  test::paint(frame, {300, 100, 40, 360}, 2000);  // a body
  AnalyserParams wide;
  wide.candidates.min_width_cm = 300;
  const BoostedModel model = stating(wide);
  PipelineParams params;
  const PeoplePipeline stated(params, &model);
  EXPECT_EQ(stated.params().analyser.candidates.min_width_cm, 300.0);
  EXPECT_TRUE(stated.analyse(frame).analysis.candidates.empty());
  params.analyser_given.keys = {"min_width"};
  const PeoplePipeline given(params, &model);
  EXPECT_EQ(given.params().analyser.candidates.min_width_cm, AnalyserParams{}.candidates.min_width_cm);
  EXPECT_FALSE(given.analyse(frame).analysis.candidates.empty());
  EXPECT_FALSE(PeoplePipeline(PipelineParams{}, nullptr).analyse(frame).analysis.candidates.empty());
}

// rdsf-detect with a model that states --hole-gap 20 --k 8 writes the rows of the same model with those
// options given; an option given (on the command line or in --config) wins; --thesis takes none; two models
// that would need other candidates are refused unless the option that differs is given.
TEST(StatedOptions, DetectProgramTakesThemUnlessGiven) {
  const test::TempDir dir("rdsf-stated");
  ASSERT_TRUE(render_room(dir, 20));
  const std::string model = write_stating_model(dir);
  const std::string detect = detect_command(dir);
  const auto rows = [&](const std::string& name, const std::string& options) { return detect_rows(dir, name, options); };
  const std::string v2 = test::quote(shipped("v2.yml")), s = test::quote(model);
  const std::string by_model = rows("a.csv", "--model " + s);
  EXPECT_FALSE(by_model.empty());
  EXPECT_EQ(by_model, rows("b.csv", "--model " + v2 + " --hole-gap 20 --k 8"));
  EXPECT_NE(by_model, rows("c.csv", "--model " + v2));  // the options change the candidates here
  EXPECT_EQ(rows("d.csv", "--model " + s + " --k 6"), rows("e.csv", "--model " + v2 + " --hole-gap 20"));
  EXPECT_EQ(rows("f.csv", "--model " + s + " --thesis"), rows("g.csv", "--model " + v2 + " --thesis"));
  {  // an option in a --config file is given too
    std::ofstream config(dir / "k.ini");
    config << "k = 6\n";
  }
  EXPECT_EQ(rows("k.csv", "--model " + s + " --config " + test::quote(dir / "k.ini")), rows("l.csv", "--model " + v2 + " --hole-gap 20"));
  const test::RunResult said = test::run(detect + test::quote(dir / "h.csv") + " --model " + s);
  EXPECT_NE(said.err.find("states its detection options (--k 8 --hole-gap 20): taken for the options not given"),
            std::string::npos)
      << said.err;
  const test::RunResult two = test::run(detect + test::quote(dir / "i.csv") + " --model " + s + " --model " + v2);
  EXPECT_EQ(two.exit_code, 2) << two.err;
  EXPECT_NE(two.err.find("run with other detection options (k 8 / 6)"), std::string::npos) << two.err;
  EXPECT_EQ(test::run(detect + test::quote(dir / "j.csv") + " --model " + s + " --model " + v2 + " --k 8 --hole-gap 20")
                .exit_code,
            0);
}

// A switch a model states on (--relaxed) can be given off: `--relaxed 0` or `--relaxed=0` on the command line or `relaxed = 0`
// in --config wins, `--relaxed` alone is on; a program running others passes it as `--relaxed=0` (rdsf-adapt).
TEST(StatedOptions, ASwitchTheModelStatesOnCanBeGivenOff) {
  const test::TempDir dir("rdsf-stated");
  ASSERT_TRUE(render_room(dir, 20));
  AnalyserParams relaxed;
  relaxed.candidates.mode = HeightMode::relaxed;
  const std::string model = dir / "relaxed.yml";
  {
    std::ofstream out(model);
    out << model_file_text(stating(relaxed));
  }
  const auto rows = [&](const std::string& name, const std::string& options) { return detect_rows(dir, name, options); };
  const std::string v2 = test::quote(shipped("v2.yml")), s = test::quote(model);
  const std::string detect = detect_command(dir);
  const std::string strict = rows("strict.csv", "--model " + v2);
  const std::string stated = rows("stated.csv", "--model " + s);
  EXPECT_NE(stated, strict);  // relaxed changes the candidates here
  EXPECT_EQ(stated, rows("on.csv", "--model " + v2 + " --relaxed"));
  EXPECT_EQ(stated, rows("on1.csv", "--model " + v2 + " --relaxed=1"));
  EXPECT_EQ(rows("off.csv", "--model " + s + " --relaxed=0"), strict);
  EXPECT_EQ(rows("off0.csv", "--relaxed 0 --model " + s), strict);
  {
    std::ofstream config(dir / "strict.ini");
    config << "relaxed = 0\n";
  }
  EXPECT_EQ(rows("config.csv", "--model " + s + " --config " + test::quote(dir / "strict.ini")), strict);
  const test::RunResult bad = test::run(detect + test::quote(dir / "bad.csv") + " --model " + s + " --relaxed=2");
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("relaxed"), std::string::npos) << bad.err;
}

// rdsf-mine --model (hard negatives) mines the candidates of the model's stated options: the same boxes and
// crops as the options given, and it says so.
TEST(StatedOptions, MineProgramTakesThemFromItsModel) {
  const test::TempDir dir("rdsf-stated");
  ASSERT_TRUE(render_room(dir, 10));
  const std::string model = write_stating_model(dir);
  const std::string mine = test::quote(test::program("rdsf-mine")) + " --source " + test::quote(dir / "room") +
                           " --min-score -1000 --threads 2 --out ";
  const auto mined = [&](const std::string& set, const std::string& options) {
    const test::RunResult r = test::run(mine + test::quote(dir / set) + " " + options);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::string rows;  // frame, boxes, layer depth and crop hash of each sample
    std::istringstream in(test::file_text(dir / (set + "/samples.tsv")));
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> f;
      std::istringstream cells(line);
      for (std::string cell; std::getline(cells, cell, '\t');) f.push_back(cell);
      if (f.size() < 20) continue;
      for (std::size_t i = 4; i < 14; ++i) rows += f[i] + ",";
      rows += f[19] + "\n";
    }
    return std::make_pair(rows, r.err);
  };
  const auto [by_model, said] = mined("a", "--model " + test::quote(model));
  EXPECT_NE(by_model.find("000000"), std::string::npos);
  EXPECT_EQ(by_model, mined("b", "--model " + test::quote(shipped("v2.yml")) + " --hole-gap 20 --k 8").first);
  EXPECT_NE(by_model, mined("c", "--model " + test::quote(shipped("v2.yml"))).first);
  EXPECT_NE(said.find("rdsf-mine: model people v2 states its detection options (--k 8 --hole-gap 20)"),
            std::string::npos)
      << said;
}

// A set records the analyser options its candidates were found with; appending or merging candidates found
// with others is refused; rdsf-train has its model state the options every set records alike, and none
// when they differ (then the --init model's), unless --detection-options says otherwise.
TEST(StatedOptions, SetsRecordThemAndTrainingStatesWhatEverySetRecords) {
  const test::TempDir dir("rdsf-stated");
  ASSERT_TRUE(render_room(dir, 30));
  const std::string room = test::quote(dir / "room");
  const auto mine = [&](const std::string& set, const std::string& options) {
    return test::run(test::quote(test::program("rdsf-mine")) + " --source " + room + " --out " + test::quote(dir / set) +
                     " " + options);
  };
  const auto label = [&](const std::string& set, const std::string& options) {
    return test::run(test::quote(test::program("rdsf-label")) + " --source " + room + " --out " +
                     test::quote(dir / set) + " --truth " + test::quote(dir / "room/boxes.csv") +
                     " --answers /dev/null --keep-rejected " + options);
  };
  ASSERT_EQ(mine("neg", "--narrow-fitted-width 20").exit_code, 0);
  ASSERT_EQ(label("pos", "--narrow-fitted-width 20").exit_code, 0);
  const SampleSetManifest manifest = SampleSetManifest::read(dir / "neg/manifest.yml");
  AnalyserParams narrow;
  narrow.candidates.narrow.fitted_width_cm = 20;
  EXPECT_EQ(manifest.analyser_options, stated_options(narrow));
  EXPECT_EQ(SampleSetManifest::parse(manifest.to_text(), "again.yml").analyser_options, manifest.analyser_options);

  const test::RunResult other = mine("neg", "");
  EXPECT_EQ(other.exit_code, 1) << other.err;
  EXPECT_NE(other.err.find("sample set's candidates were found with other options (narrow_fitted_width 20, now 0)"),
            std::string::npos)
      << other.err;
  ASSERT_EQ(mine("plain", "").exit_code, 0);
  const test::RunResult merged =
      test::run(test::quote(test::program("rdsf-mine")) + " --merge " + test::quote(dir / "neg") + " " +
                test::quote(dir / "plain") + " --out " + test::quote(dir / "both"));
  EXPECT_NE(merged.exit_code, 0);
  EXPECT_NE(merged.err.find("other analyser options than the output's; not merged"), std::string::npos) << merged.err;

  const std::string train = test::quote(test::program("rdsf-train")) + " --models-dir " + test::quote(dir / "models") +
                            " --rounds 3 --folds 0 --group-frames 0 --pos " + test::quote(dir / "pos") + " --neg ";
  const auto stated_by = [&](const std::string& name, const std::string& rest) {
    const test::RunResult r = test::run(train + rest + " --name " + name);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return BoostedModel::load(dir / ("models/" + name + "/v1.yml")).detection_options();
  };
  EXPECT_EQ(stated_by("agreed", test::quote(dir / "neg")), stated_options(narrow));
  EXPECT_TRUE(stated_by("differ", test::quote(dir / "plain")).empty());  // the sets record other options
  AnalyserParams hole;
  hole.candidates.hole_gap_cm = 20;
  EXPECT_EQ(stated_by("given", test::quote(dir / "neg") + " --detection-options hole-gap=20"), stated_options(hole));
}

// rdsf-train --detection-options: bad words are usage errors before any sample is read.
TEST(StatedOptions, TrainProgramRefusesBadDetectionOptions) {
  const test::TempDir dir("rdsf-stated");
  const std::string train = test::quote(test::program("rdsf-train")) + " --name x --models-dir " +
                            test::quote(dir / "models") + " --pos " + test::quote(dir / "none") + " --neg " +
                            test::quote(dir / "none") + " --detection-options ";
  for (const auto& [words, message] : std::vector<std::pair<std::string, std::string>>{
           {"hole-gap=-1", "--detection-options: hole-gap must be at least 0"},
           {"frob=1", "--detection-options: 'frob' is not a known option"},
           {"hole-gap", "--detection-options 'hole-gap': give NAME=VALUE (an analyser option) or 'defaults'"},
           {"defaults k=3", "--detection-options 'defaults': give NAME=VALUE"}}) {
    const test::RunResult r = test::run(train + words);
    EXPECT_EQ(r.exit_code, 2) << words << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "models"));
}
