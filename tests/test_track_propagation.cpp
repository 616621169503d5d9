// Track propagation (labeling/track_propagation.hpp) on hand-built sequences: a person walking is labelled
// from one answer both ways; two people crossing stop the track where it is unsure (those are asked); a
// score gate; frames where the track's candidate is missing stepped over (max_gap_frames); undo of the answer through the journal removes every propagated label; the labelling session
// with per_track on a rendered room, and with one answer per place on a room seen by a still camera; the model's
// answers followed along their tracks (from_model) before the first question, which u does not undo.
#include <gtest/gtest.h>

#include "rdsf/candidates/crop_provenance.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/labeling/labeling_session.hpp"
#include "rdsf/labeling/track_propagation.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

// A person 60x120 px at 2.5 m walking right 4 px per frame, and a chair (static, 3 m) far to the right.
std::vector<std::vector<TrackCandidate>> walking(int frames) {
  std::vector<std::vector<TrackCandidate>> out(frames);
  for (int f = 0; f < frames; ++f) {
    out[f].push_back({cv::Rect(100 + 4 * f, 150, 60, 120), 2500, 0.6});
    out[f].push_back({cv::Rect(500, 250, 50, 80), 3000, 0.3});
  }
  return out;
}

// A synthetic room rendered into DIR/room (rdsf-synth with `args`), the shipped model, and the session's
// per-track settings on the room (uncertain order, n answers stored).
void render_room(const test::TempDir& dir, const std::string& args) {
  const test::RunResult r =
      test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(dir / "room") + " --force " + args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

BoostedModel shipped_model() { return BoostedModel::load(std::string(RDSF_SOURCE_DIR) + "/models/people/v2.yml"); }

LabelingConfig per_track_config(const test::TempDir& dir) {
  LabelingConfig config;
  config.sources = {dir / "room"};
  config.ask = AskOrder::uncertain;
  config.per_track = true;
  config.keep_rejected = true;
  config.threads = 2;
  return config;
}

SampleSetWriter open_set(const std::string& path, const LabelingConfig& config) {
  return SampleSetWriter::open_or_create(path, config.analyser.features, config.camera, "test",
                                         crop_provenance(config.analyser.candidates));
}

}  // namespace

TEST(TrackPropagation, PersonWalkingIsLabelledBothWaysFromOneAnswer) {
  const auto frames = walking(20);
  const PropagatedTrack t = propagate_track(frames, {10, 0}, 'y', {}, CameraModel{});
  ASSERT_EQ(t.labelled.size(), 19u);  // every other frame's person, none of the chair
  for (std::size_t i = 0; i < t.labelled.size(); ++i) {
    EXPECT_EQ(t.labelled[i].index, 0u);
    EXPECT_EQ(t.labelled[i].frame, i < 10 ? i : i + 1);  // frame order, the seed left out
  }
  EXPECT_TRUE(t.ask.empty());
  // max_frames limits each direction.
  PropagationParams near;
  near.max_frames = 3;
  EXPECT_EQ(propagate_track(frames, {10, 0}, 'y', near, CameraModel{}).labelled.size(), 6u);
}

TEST(TrackPropagation, TwoPeopleCrossingStopTheTrackAndAreAsked) {
  // A walks right, B walks left at the same depth; they meet at frame 20.
  std::vector<std::vector<TrackCandidate>> frames(41);
  for (int f = 0; f <= 40; ++f) {
    frames[f].push_back({cv::Rect(200 + 6 * f, 150, 60, 120), 2500, 0.7});
    frames[f].push_back({cv::Rect(440 - 6 * f, 150, 60, 120), 2550, 0.7});
  }
  const PropagatedTrack t = propagate_track(frames, {0, 0}, 'y', {}, CameraModel{});
  ASSERT_FALSE(t.labelled.empty());
  for (const TrackLink& l : t.labelled) {
    EXPECT_EQ(l.index, 0u);  // never B
    EXPECT_LT(l.frame, 20u);
  }
  ASSERT_FALSE(t.ask.empty());  // where it stopped, both people passed the gates
  EXPECT_EQ(t.ask.front().frame, t.labelled.back().frame + 1);
  EXPECT_GE(t.ask.size(), 2u);
}

TEST(TrackPropagation, GatesStopAtADepthJumpAScoreAndAnotherAnswer) {
  PropagationParams no_gap;  // stops at the first frame where nothing passes (the default)
  no_gap.max_gap_frames = 0;
  auto frames = walking(10);
  frames[6][0].depth_mm = 3200;  // a jump of 70 cm: another object
  PropagatedTrack t = propagate_track(frames, {2, 0}, 'y', no_gap, CameraModel{});
  EXPECT_EQ(t.labelled.size(), 5u);  // frames 0, 1, 3, 4, 5
  frames[7][0].depth_mm = 3200;  // two frames: stepped over by neither rule
  EXPECT_EQ(propagate_track(frames, {2, 0}, 'y', {}, CameraModel{}).labelled.size(), 5u);
  frames = walking(10);
  frames[6][0].probability = 0.01;  // the model rejects it surely: a 'y' track does not enter it ...
  EXPECT_EQ(propagate_track(frames, {2, 0}, 'y', no_gap, CameraModel{}).labelled.size(), 5u);
  EXPECT_EQ(propagate_track(frames, {2, 0}, 'n', no_gap, CameraModel{}).labelled.size(), 9u);  // ... an 'n' one does
  // An answer given otherwise stops it; the same answer is gone through without relabelling.
  frames = walking(10);
  t = propagate_track(frames, {2, 0}, 'y', {}, CameraModel{}, [](const TrackLink& l) {
    return l.frame == 4 ? 'y' : l.frame == 7 ? 'n' : '\0';
  });
  EXPECT_EQ(t.labelled.size(), 5u);  // 0, 1, 3, 5, 6 (4 was answered y already, 7 n)
}

// within_image (on for the model's tracks): a track neither enters nor starts at a candidate whose window
// reaches beyond the image; without it the same candidate is labelled, and followed from.
TEST(TrackPropagation, WithinImageStopsATrackAtACropCutByTheImage) {
  auto frames = walking(10);
  frames[6][0].cut_by_image = true;  // the person's window leaves the image there
  PropagationParams gated;
  gated.max_gap_frames = 0;
  gated.within_image = true;
  EXPECT_EQ(propagate_track(frames, {2, 0}, 'n', gated, CameraModel{}).labelled.size(), 5u);  // 0, 1, 3, 4, 5
  EXPECT_TRUE(propagate_track(frames, {6, 0}, 'n', gated, CameraModel{}).labelled.empty());  // nor starts there
  gated.within_image = false;
  EXPECT_EQ(propagate_track(frames, {2, 0}, 'n', gated, CameraModel{}).labelled.size(), 9u);
  EXPECT_EQ(propagate_track(frames, {6, 0}, 'n', gated, CameraModel{}).labelled.size(), 9u);
}

TEST(TrackPropagation, FramesWhereNothingPassesAreSteppedOverUpToMaxGapFrames) {
  auto missing = [](std::vector<int> gone) {  // the person's candidate moved away (nothing overlaps there)
    auto frames = walking(20);
    for (int f : gone) frames[f][0] = {cv::Rect(0, 400, 30, 40), 1500, 0.5};
    return frames;
  };
  PropagationParams stop, one, two;
  stop.max_gap_frames = 0;
  one.max_gap_frames = 1;
  two.max_gap_frames = 2;
  EXPECT_EQ(PropagationParams{}.max_gap_frames, 0);
  EXPECT_EQ(propagate_track(missing({6}), {2, 0}, 'y', stop, CameraModel{}).labelled.size(), 5u);  // 0, 1, 3-5
  PropagatedTrack t = propagate_track(missing({6}), {2, 0}, 'y', one, CameraModel{});
  ASSERT_EQ(t.labelled.size(), 18u);  // 0, 1, 3-5, 7-19: frame 6 stepped over, nothing there labelled
  for (const TrackLink& l : t.labelled) EXPECT_TRUE(l.frame != 6 && l.index == 0) << l.frame;
  EXPECT_EQ(propagate_track(missing({6}), {15, 0}, 'y', one, CameraModel{}).labelled.size(), 18u);  // backwards too
  EXPECT_EQ(propagate_track(missing({6, 7}), {2, 0}, 'y', one, CameraModel{}).labelled.size(), 5u);
  EXPECT_EQ(propagate_track(missing({6, 7}), {2, 0}, 'y', two, CameraModel{}).labelled.size(), 17u);
  // A candidate there that fails a gate (a depth glitch of one frame) is stepped over the same way, unlabelled.
  auto glitch = walking(20);
  glitch[6][0].depth_mm = 3200;
  t = propagate_track(glitch, {2, 0}, 'y', one, CameraModel{});
  EXPECT_EQ(t.labelled.size(), 18u);
  for (const TrackLink& l : t.labelled) EXPECT_NE(l.frame, 6u);
  // Where something passes but is ambiguous, the track stops there as before (two people crossing).
  std::vector<std::vector<TrackCandidate>> crossing(41);
  for (int f = 0; f <= 40; ++f) {
    crossing[f].push_back({cv::Rect(200 + 6 * f, 150, 60, 120), 2500, 0.7});
    crossing[f].push_back({cv::Rect(440 - 6 * f, 150, 60, 120), 2550, 0.7});
  }
  for (const TrackLink& l : propagate_track(crossing, {0, 0}, 'y', two, CameraModel{}).labelled) EXPECT_LT(l.frame, 20u);
}

TEST(TrackPropagation, UndoOfTheAnswerRemovesEveryPropagatedLabel) {
  test::TempDir dir;
  const std::string path = (dir / "labeler-answers.tsv");
  const auto frames = walking(8);
  const CandidateKey seed{"room", "000003", frames[3][0].box};
  {
    AnswerJournal journal(path);
    journal.record({seed, 'y', 7, "human"});
    const PropagatedTrack t = propagate_track(frames, {3, 0}, 'y', {}, CameraModel{});
    for (const TrackLink& l : t.labelled) {
      journal.record({{"room", "00000" + std::to_string(l.frame), frames[l.frame][0].box}, 'y', -1, track_answerer(seed)});
    }
    journal.record({{"room", "000001", frames[1][1].box}, 'n', -1, "human"});  // another answer
    EXPECT_EQ(journal.answers_in_force(), 9u);
  }
  AnswerJournal journal(path);  // replayed after a restart
  const std::vector<JournalEntry> propagated = propagated_from(journal, seed);
  ASSERT_EQ(propagated.size(), 7u);
  for (auto it = propagated.rbegin(); it != propagated.rend(); ++it) journal.record_undo(*it);
  journal.record_undo({seed, 'y', 7, "human"});
  EXPECT_EQ(journal.answers_in_force(), 1u);  // only the other answer is left
  EXPECT_TRUE(propagated_from(AnswerJournal(path), seed).empty());
}

// The session with per_track on a rendered synthetic room and the shipped model: the track the window
// would show is what an answer labels, and undo takes the answer and its whole track back.
TEST(TrackPropagation, SessionLabelsTheTrackAndUndoTakesItAllBack) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(render_room(dir, "--frames 30 --people 2..2 --clip-frames 30 --seed 5"));
  const BoostedModel model = shipped_model();
  const LabelingConfig config = per_track_config(dir);
  SampleSetWriter writer = open_set(dir / "set", config);
  LabelingSession session(config, writer, &model, nullptr);
  // The first question whose track reaches other frames (answered n until then).
  std::size_t preview = 0;
  for (int asked = 0; asked < 40 && session.current() != nullptr; ++asked) {
    preview = session.track_preview('y').size();
    if (preview > 0) break;
    ASSERT_TRUE(session.answer('s'));
  }
  ASSERT_GT(preview, 0u) << "no question with a track in 40";
  const std::size_t in_force = session.journal().answers_in_force();
  const std::size_t samples = writer.records().size();
  ASSERT_TRUE(session.answer('y'));
  EXPECT_EQ(static_cast<std::size_t>(session.stats().propagated_positives), preview);
  EXPECT_EQ(session.journal().answers_in_force(), in_force + 1 + preview);
  EXPECT_EQ(writer.records().size(), samples + 1 + preview);
  ASSERT_TRUE(session.answer('u'));
  EXPECT_EQ(session.stats().propagated_positives, 0);
  EXPECT_EQ(session.journal().answers_in_force(), in_force);
  EXPECT_EQ(SampleSet::open_read(dir / "set").records().size(), samples);  // retracted samples are left out
}

// One answer per place (test_place_propagation.cpp for the rule): the session on a rendered room with a still camera and the shipped model: the first n whose place reaches
// other frames labels what place_preview() showed (the window's second strip), as propagated negatives of
// origin labeler-place; u takes the answer, its track and its place back. With per_place off nothing is.
TEST(TrackPropagation, SessionLabelsThePlaceAndUndoTakesItAllBack) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(render_room(dir, "--frames 40 --people 1..2 --clip-frames 40 --seed 5 --moving-camera 0"));
  const BoostedModel model = shipped_model();
  LabelingConfig config = per_track_config(dir);
  for (const bool per_place : {false, true}) {
    config.propagation.per_place = per_place;
    const std::string set = dir / (per_place ? "set-place" : "set-track");
    SampleSetWriter writer = open_set(set, config);
    LabelingSession session(config, writer, &model, nullptr);
    std::size_t place = 0;
    for (int asked = 0; asked < 60 && session.current() != nullptr; ++asked) {
      place = session.place_preview().size();
      if (place > 0) break;
      ASSERT_TRUE(session.answer('s'));
    }
    if (!per_place) {
      EXPECT_EQ(place, 0u);
      EXPECT_EQ(session.stats().placed_negatives, 0);
      continue;
    }
    ASSERT_GT(place, 0u) << "no question with a place beyond its track in 60";
    const std::size_t track = session.track_preview('n').size();
    const std::size_t in_force = session.journal().answers_in_force();
    const std::size_t samples = writer.records().size();
    ASSERT_TRUE(session.answer('n'));
    EXPECT_EQ(static_cast<std::size_t>(session.stats().placed_negatives), place);
    EXPECT_EQ(static_cast<std::size_t>(session.stats().propagated_negatives), track + place);
    EXPECT_EQ(session.journal().answers_in_force(), in_force + 1 + track + place);
    std::size_t by_place = 0;
    for (const SampleRecord& s : writer.records()) by_place += s.origin == "labeler-place" ? 1 : 0;
    EXPECT_EQ(by_place, place);
    EXPECT_EQ(writer.records().size(), samples + 1 + track + place);
    ASSERT_TRUE(session.answer('u'));
    EXPECT_EQ(session.stats().placed_negatives, 0);
    EXPECT_EQ(session.stats().propagated_negatives, 0);
    EXPECT_EQ(session.journal().answers_in_force(), in_force);
    EXPECT_EQ(SampleSet::open_read(set).records().size(), samples);  // retracted samples are left out
    EXPECT_EQ(session.place_preview().size(), place);  // asked again, the same place shown again
  }
}

// From the model's answers (propagation.from_model): when the session is read, the tracks of the candidates the
// model answered label the unanswered ones on them (origin labeler-model-track, by "model-track ..."), which
// leave the queue; a person's answer and its undo leave them in force. Off (the default) nothing is.
TEST(TrackPropagation, SessionFollowsTheModelsAnswersAlongTheirTracks) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(render_room(dir, "--frames 30 --people 2..2 --clip-frames 30 --seed 5"));
  const BoostedModel model = shipped_model();
  LabelingConfig config = per_track_config(dir);
  std::size_t pending_without = 0;
  for (const bool from_model : {false, true}) {
    config.propagation.from_model = from_model;
    const std::string set = dir / (from_model ? "set-model" : "set-people");
    SampleSetWriter writer = open_set(set, config);
    LabelingSession session(config, writer, &model, nullptr);
    ASSERT_NE(session.current(), nullptr);
    const LabelingStats& st = session.stats();
    const long by_track = st.model_track_positives + st.model_track_negatives;
    std::size_t journalled = 0, stored = 0;
    for (const JournalEntry& e : session.journal().in_force()) journalled += e.by.rfind("model-track ", 0) == 0 ? 1 : 0;
    for (const SampleRecord& s : writer.records()) stored += s.origin == "labeler-model-track" ? 1 : 0;
    EXPECT_EQ(static_cast<long>(journalled), by_track);
    EXPECT_EQ(static_cast<long>(stored), by_track);  // n answers are stored too (keep_rejected)
    EXPECT_EQ(st.propagated_positives + st.propagated_negatives, 0);  // no person's answer yet
    if (!from_model) {
      EXPECT_EQ(by_track, 0);
      pending_without = session.pending();
      continue;
    }
    ASSERT_GT(by_track, 0) << "no model answer's track reached an unanswered candidate";
    EXPECT_EQ(session.pending() + static_cast<std::size_t>(by_track), pending_without);
    const std::size_t in_force = session.journal().answers_in_force();
    const std::size_t samples = writer.records().size();
    ASSERT_TRUE(session.answer('y'));
    ASSERT_TRUE(session.answer('u'));  // the person's answer and its track go, the model's tracks stay
    EXPECT_EQ(session.journal().answers_in_force(), in_force);
    EXPECT_EQ(st.model_track_positives + st.model_track_negatives, by_track);
    EXPECT_EQ(session.pending() + static_cast<std::size_t>(by_track), pending_without);
    EXPECT_EQ(SampleSet::open_read(set).records().size(), samples);  // the model's tracks' samples kept
  }
}

// The model's tracks stay off crops cut by the image's edge (model_within_image, on by default): every sample
// they store has a window inside the image, and they label fewer than without the rule.
TEST(TrackPropagation, SessionKeepsTheModelsTracksWithinTheImage) {
  test::TempDir dir;
  ASSERT_NO_FATAL_FAILURE(render_room(dir, "--frames 30 --people 2..2 --clip-frames 30 --seed 5"));
  const BoostedModel model = shipped_model();
  LabelingConfig config = per_track_config(dir);
  config.propagation.from_model = true;
  long labelled[2] = {0, 0};
  for (const bool within : {true, false}) {
    config.propagation.model_within_image = within;
    const std::string set = dir / (within ? "set-within" : "set-anywhere");
    SampleSetWriter writer = open_set(set, config);
    LabelingSession session(config, writer, &model, nullptr);
    ASSERT_NE(session.current(), nullptr);
    labelled[within ? 0 : 1] = session.stats().model_track_positives + session.stats().model_track_negatives;
    if (!within) continue;
    for (const SampleRecord& s : writer.records()) {
      if (s.origin != "labeler-model-track") continue;
      EXPECT_GT(s.window.x, 0) << s.frame;  // the window is clipped to the image: touching it is leaving it
      EXPECT_GT(s.window.y, 0) << s.frame;
      EXPECT_LT(s.window.x + s.window.width, 640) << s.frame;
      EXPECT_LT(s.window.y + s.window.height, 480) << s.frame;
    }
  }
  EXPECT_GT(labelled[0], 0) << "no model track inside the image";
  EXPECT_LT(labelled[0], labelled[1]);  // this room has candidates cut by the image's edge: 17 against 30
}
