// The synthetic Kinect generator as a library: its random numbers, determinism, its parameter table (the
// --classic values, range checks), ground-truth boxes, the --empty rooms, smooth tracks, the sensor's range
// and quantisation, and that the frame analyser finds the people it renders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/stable_hash.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/synth/depth_statistics.hpp"
#include "rdsf/synth/kinect_sensor.hpp"
#include "rdsf/synth/people_planner.hpp"
#include "rdsf/synth/person_model.hpp"
#include "rdsf/synth/random.hpp"
#include "rdsf/synth/room_generator.hpp"
#include "rdsf/synth/synth_params.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "support/test_support.hpp"

namespace {

using rdsf::synth::SynthFrame;
using rdsf::synth::SynthParams;
using rdsf::synth::SynthSequence;
using rdsf::synth::people_scene;

SynthParams small_params(std::uint64_t seed) {
  SynthParams p = people_scene(24, 1, 3, seed);
  p.clip_frames = 8;
  p.width_px = 320;
  p.height_px = 240;
  return p;
}

std::uint64_t hash_frame(const SynthFrame& f) {
  std::uint64_t h = rdsf::fnv1a64(std::string_view(reinterpret_cast<const char*>(f.depth_mm.data),
                                                   f.depth_mm.total() * f.depth_mm.elemSize()));
  for (const auto& p : f.people) {
    const std::string row = std::to_string(p.track) + "," + std::to_string(p.box.x) + "," +
                            std::to_string(p.box.y) + "," + std::to_string(p.box.width) + "," +
                            std::to_string(p.box.height);
    h = rdsf::fnv1a64(row, h);
  }
  return h;
}

TEST(SynthRandom, SameSeedSameNumbersAndSaneNormals) {
  rdsf::synth::Rng a(123), b(123), c(124);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const std::uint64_t x = a.next();
    EXPECT_EQ(x, b.next());
    differs |= x != c.next();
  }
  EXPECT_TRUE(differs);
  rdsf::synth::Rng r(7);
  double sum = 0, sum2 = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double v = r.normal();
    sum += v;
    sum2 += v * v;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.05);
  EXPECT_NEAR(sum2 / n, 1.0, 0.05);
  EXPECT_NE(rdsf::synth::derive_seed(1, 2, 3), rdsf::synth::derive_seed(1, 2, 4));
}

TEST(SynthSequence, SameSeedSameFramesOtherSeedOtherFrames) {
  SynthSequence a(small_params(5)), b(small_params(5)), c(small_params(6));
  std::uint64_t ha = 0, hb = 0, hc = 0;
  for (int i = 0; i < 24; i += 3) {  // also out of order for b: frames do not depend on what came before
    ha = rdsf::fnv1a64(std::to_string(hash_frame(a.frame(i))), ha);
    hc = rdsf::fnv1a64(std::to_string(hash_frame(c.frame(i))), hc);
  }
  std::map<int, std::uint64_t> out_of_order;
  for (int i = 21; i >= 0; i -= 3) out_of_order[i] = hash_frame(b.frame(i));
  for (const auto& [i, h] : out_of_order) hb = rdsf::fnv1a64(std::to_string(h), hb);
  EXPECT_EQ(ha, hb);
  EXPECT_NE(ha, hc);
}

// --classic is the generator before issue 13, byte for byte: the hash of 60 frames (depth, boxes and
// visible fractions) of seed 5 as the generator at commit bb3e584 gave it.
TEST(SynthSequence, ClassicIsTheGeneratorBefore) {
  SynthParams p = small_params(5);
  p.frames = 60;
  p.clip_frames = 10;
  p.width_px = 640;
  p.height_px = 480;
  p = rdsf::synth::with_classic_values(p);
  SynthSequence sequence(p);
  std::uint64_t h = 0;
  for (int i = 0; i < p.frames; ++i) {
    const SynthFrame f = sequence.frame(i);
    std::uint64_t fh = rdsf::fnv1a64(std::string_view(reinterpret_cast<const char*>(f.depth_mm.data),
                                                      f.depth_mm.total() * f.depth_mm.elemSize()));
    for (const auto& t : f.people) {
      fh = rdsf::fnv1a64(std::to_string(t.track) + "," + std::to_string(t.box.x) + "," + std::to_string(t.box.y) +
                             "," + std::to_string(t.box.width) + "," + std::to_string(t.box.height) + "," +
                             std::to_string(t.visible_fraction),
                         fh);
    }
    h = rdsf::fnv1a64(std::to_string(fh), h);
  }
  EXPECT_EQ(h, 0xc911653e222b8990ULL);
}

// --classic is the rows' classic values (synth_parameters()): each member the hand-written set_classic()
// of before set, to the value it set, and the members --clutter sets besides clutter itself kept.
TEST(SynthParameters, ClassicValuesAreTheOldSetClassic) {
  SynthParams given;
  given.room.clutter_min = 2;
  given.room.clutter_max = 4;
  const auto classic_members = [](const SynthParams& p) {
    std::ostringstream text;
    text << "height " << p.room.camera_height_min_m << ".." << p.room.camera_height_max_m << " roll "
         << p.room.roll_max_deg << " yaw " << p.room.yaw_max_deg << " offset " << p.room.camera_offset_max_m
         << " moving " << p.room.moving_share << " clutter " << p.room.clutter << " kinds " << p.room.room_kinds
         << " floor " << p.room.floor_dropout_max << " wall " << p.room.wall_dropout_max << " eight-bit "
         << p.sensor.eight_bit_share << " xtion " << p.sensor.xtion_share << " patch " << p.sensor.patch_cell_px
         << " holes " << p.sensor.coherent_holes_px << " bodies " << p.people.body.varied_bodies << " outfits "
         << p.people.body.outfits << " poses " << p.people.poses << " groups " << p.people.group_share << " sitting "
         << p.people.sitting_share << " in-view " << p.people.in_view_share << " distance " << p.people.nearest_m
         << ".." << p.people.farthest_m << " clearance " << p.people.clearance_m;
    return text.str();
  };
  const SynthParams c = rdsf::synth::with_classic_values(given);
  EXPECT_EQ(classic_members(c),
            "height 0.7..1.2 roll 0 yaw 0 offset 0 moving 0 clutter 0 kinds 0 floor 0.2 wall 0.05 eight-bit 0 "
            "xtion 0 patch 20 holes 0 bodies 0 outfits 0 poses 0 groups 0 sitting 0 in-view 0 distance 1..7 "
            "clearance 0.5");
  EXPECT_NE(classic_members(given), classic_members(c));
  // what set_classic() left alone
  EXPECT_EQ(c.room.clutter_min, 2);
  EXPECT_EQ(c.room.clutter_max, 4);
  EXPECT_EQ(c.room.pitch_min_deg, given.room.pitch_min_deg);
  EXPECT_EQ(c.sensor.eight_bit_step_min_mm, given.sensor.eight_bit_step_min_mm);
  EXPECT_EQ(c.people.body.child_share, given.people.body.child_share);
  // exactly those 23 members: every row with a classic value is one of them (two for a MIN..MAX row)
  int classic_rows = 0;
  for (const auto& row : rdsf::synth::synth_parameters()) classic_rows += row.classic ? 1 : 0;
  EXPECT_EQ(classic_rows, 21);
}

// A row refuses a value out of its range in one line naming the option and the value, stores nothing, and
// the same check guards SynthParams::validate(); --classic overrides (unchecked) the values of its rows.
TEST(SynthParameters, RowsRefuseValuesOutOfRangeNamingTheOption) {
  using rdsf::synth::set_synth_options;
  using rdsf::test::error_message;
  SynthParams p;
  EXPECT_EQ(error_message([&] { set_synth_options(p, {{"camera-roll", 99.0}}, false); }),
            "--camera-roll 99: must lie in 0..20 degrees");
  EXPECT_EQ(error_message([&] { set_synth_options(p, {{"xtion", 2.0}}, false); }), "--xtion 2: must be a share in 0..1");
  EXPECT_EQ(error_message([&] { set_synth_options(p, {{"people", std::string("3..1")}}, false); }),
            "--people 3..1: MIN is larger than MAX");
  EXPECT_EQ(error_message([&] { set_synth_options(p, {{"camera-height", std::string("0.1..1")}}, false); }),
            "--camera-height 0.1..1: must lie in 0.2..2.5 m with MIN <= MAX");
  EXPECT_EQ(error_message([&] { set_synth_options(p, {{"bodies", std::string("yes")}}, false); }),
            "--bodies yes: expected on or off");
  EXPECT_EQ(error_message([&] { set_synth_options(p, {{"coherent-holes", 9}}, false); }),
            "--coherent-holes 9: must lie in 0..8 pixels");
  EXPECT_EQ(p.room.roll_max_deg, SynthParams{}.room.roll_max_deg);  // a refused value is not stored
  EXPECT_EQ(p.sensor.xtion_share, SynthParams{}.sensor.xtion_share);
  const auto* roll = rdsf::find_parameter(rdsf::synth::synth_parameters(), "camera-roll");
  ASSERT_NE(roll, nullptr);
  EXPECT_EQ(roll->help.substr(roll->help.size() - 7), "(0..20)") << "the help shows the range the row checks";
  p.room.roll_max_deg = 45;
  EXPECT_EQ(error_message([&] { p.validate(); }), "--camera-roll 45: must lie in 0..20 degrees");
  p.room.roll_max_deg = 20;
  EXPECT_NO_THROW(p.validate());
  set_synth_options(p, {{"xtion", 2.0}, {"camera-roll", 5.0}, {"clutter", std::string("2..4")}}, /*classic=*/true);
  EXPECT_EQ(p.sensor.xtion_share, 0.0);
  EXPECT_EQ(p.room.roll_max_deg, 0.0);
  EXPECT_EQ(p.room.clutter_max, 4);  // --clutter has no classic value: given, then clutter off
  EXPECT_FALSE(p.room.clutter);
}

TEST(SynthSequence, BoxesLieInsideTheFrameAndCoverPixelsNearerThanTheEmptyRoom) {
  SynthParams with_people = small_params(21);
  SynthParams empty = with_people;
  empty.empty = true;
  SynthSequence people(with_people), rooms(empty);
  int boxes = 0;
  const cv::Rect image(0, 0, with_people.width_px, with_people.height_px);
  for (int i = 0; i < with_people.frames; ++i) {
    const SynthFrame f = people.frame(i);
    const SynthFrame e = rooms.frame(i);
    EXPECT_TRUE(e.people.empty()) << "an --empty frame has a box";
    // the same room: most pixels are identical
    const double same = static_cast<double>(cv::countNonZero(f.depth_mm == e.depth_mm)) /
                        static_cast<double>(f.depth_mm.total());
    EXPECT_GT(same, 0.5) << "frame " << i << ": empty room differs from the room with people";
    for (const auto& p : f.people) {
      ++boxes;
      EXPECT_EQ(p.box & image, p.box) << "box outside the frame";
      EXPECT_GT(p.visible_fraction, 0.0);
      EXPECT_LE(p.visible_fraction, 1.0);
      long long nearer = 0;
      for (int y = p.box.y; y < p.box.y + p.box.height; ++y) {
        for (int x = p.box.x; x < p.box.x + p.box.width; ++x) {
          const int d = f.depth_mm(y, x), background = e.depth_mm(y, x);
          // in front of the room, or a reading where the room has none (glass, beyond the capture's range)
          if (d > 0 && (background == 0 || d < background - 50)) ++nearer;
        }
      }
      if (p.visible_px < 200) continue;  // slivers at the image edge are mostly edge holes
      EXPECT_GE(static_cast<double>(nearer), 0.3 * static_cast<double>(p.visible_px))
          << "frame " << i << " track " << p.track << ": the box does not cover pixels nearer than the room";
    }
  }
  EXPECT_GT(boxes, 10);
}

TEST(SynthPeople, PathsAreSmoothAndStayInTheRoom) {
  rdsf::synth::Rng room_rng(5), people_rng(6);
  rdsf::synth::CameraPose camera;
  const rdsf::synth::Room room = rdsf::synth::generate_room(room_rng, {}, camera);
  const rdsf::synth::PeopleParams params;
  const auto tracks = rdsf::synth::plan_people(people_rng, room, 4, 300, 11, params);
  ASSERT_EQ(tracks.size(), 4U);
  double walked_m = 0;
  int sitting_frames = 0;
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    EXPECT_EQ(tracks[t].track, 11 + static_cast<int>(t));
    EXPECT_GE(tracks[t].body.height_m, 1.0);
    EXPECT_LE(tracks[t].body.height_m, 2.0);
    for (std::size_t f = 0; f < tracks[t].poses.size(); ++f) {
      const auto& pose = tracks[t].poses[f];
      if (!pose.present) continue;
      if (pose.posture == rdsf::synth::Posture::sitting) {  // on a chair of the room, for the whole clip
        bool on_a_seat = false;
        for (const auto& seat : room.seats) on_a_seat |= seat.x == pose.position.x && seat.z == pose.position.z;
        EXPECT_TRUE(on_a_seat) << "track " << t << " frame " << f;
        ++sitting_frames;
        continue;
      }
      EXPECT_TRUE(room.walkable(pose.position.x, pose.position.z, 0.3)) << "track " << t << " frame " << f;
      if (f == 0) continue;
      const auto& before = tracks[t].poses[f - 1];
      const double step =
          std::hypot(pose.position.x - before.position.x, pose.position.z - before.position.z);
      walked_m += step;
      EXPECT_LE(step, params.speed_max_mps * params.frame_interval_s + 1e-9) << "jump at frame " << f;
      double turn = std::abs(pose.yaw_rad - before.yaw_rad);
      turn = std::min(turn, 2 * 3.14159265358979 - turn);
      EXPECT_LE(turn, 3.0 * params.frame_interval_s + 1e-9) << "sudden turn at frame " << f;
    }
  }
  EXPECT_GT(walked_m, 4.0) << "nobody walks";
}

TEST(SynthSensor, ReadingsInRangeAndQuantisedCoarserWithDistance) {
  SynthParams p = small_params(9);
  p.width_px = 640;
  p.height_px = 480;
  p.sensor.eight_bit_share = 0;  // 16-bit captures only: every reading on the disparity grid
  SynthSequence sequence(p);
  std::set<int> values;
  for (int i = 0; i < 24; i += 4) {
    const SynthFrame f = sequence.frame(i);
    for (int y = 0; y < f.depth_mm.rows; ++y) {
      for (int x = 0; x < f.depth_mm.cols; ++x) {
        const int d = f.depth_mm(y, x);
        if (d == 0) continue;
        ASSERT_GE(d, 500);
        ASSERT_LE(d, 8000);
        values.insert(d);
      }
    }
  }
  // every reading lies on the disparity grid z = 348 / k metres (k whole): steps of z^2 / 348 m,
  // about 3 mm at 1 m and 4.6 cm at 4 m
  for (int d : values) {
    const double k = std::round(348000.0 / d);
    EXPECT_LE(std::abs(348000.0 / k - d), 0.51) << d << " mm is not a disparity step";
  }
  int between_3_and_6_m = 0;
  for (int d : values) between_3_and_6_m += (d >= 3000 && d <= 6000) ? 1 : 0;
  EXPECT_LE(between_3_and_6_m, 59);  // 348/3 - 348/6 + 1 steps
  EXPECT_GT(values.size(), 100U);
}

// 8-bit captures (like ../shared/realdata): every reading of a frame lies on one linear grid
// offset + k * step with k in 1..255 and a step of 12-28 mm, and the largest is at most 255 steps above it.
TEST(SynthSensor, EightBitCapturesLieOnALinearGrid) {
  SynthParams p = small_params(9);
  p.width_px = 640;
  p.height_px = 480;
  p.sensor.eight_bit_share = 1;
  p.clip_frames = 4;
  SynthSequence sequence(p);
  for (int i = 0; i < 24; i += 4) {
    const SynthFrame f = sequence.frame(i);
    std::set<int> values;
    for (int y = 0; y < f.depth_mm.rows; ++y) {
      for (int x = 0; x < f.depth_mm.cols; ++x) {
        if (f.depth_mm(y, x) > 0) values.insert(f.depth_mm(y, x));
      }
    }
    ASSERT_GT(values.size(), 20U) << "frame " << i;
    ASSERT_LE(values.size(), 255U) << "frame " << i << ": more than 255 codes";
    // some step of 12-28 mm puts every reading within 1 mm (rounding to millimetres) of a whole number of
    // steps above the smallest
    double best_residual = 1e9, best_step = 0;
    for (double step = 11.5; step <= 28.5; step += 0.005) {
      double worst = 0;
      for (int v : values) {
        const double k = (v - *values.begin()) / step;
        worst = std::max(worst, std::abs(k - std::round(k)) * step);
        if (worst > best_residual) break;
      }
      if (worst < best_residual) {
        best_residual = worst;
        best_step = step;
      }
    }
    EXPECT_LE(best_residual, 1.01) << "frame " << i << ": the readings are not on a linear grid (step " << best_step << ")";
    EXPECT_LE(*values.rbegin() - *values.begin(), 255 * best_step + 1) << "frame " << i;
  }
}

// Everything a person wears or carries belongs to the person (so the truth box covers bags, boxes and

// Block matching's coherence on a hand-built row and column: a short hole on one surface takes its ends'
// readings, a hole across a depth edge or longer than the limit stays, and a short run of readings between
// holes is lost.
TEST(SynthSensor, CoherentHolesFillSpecksOnOneSurfaceOnly) {
  using rdsf::synth::KinectSensor;
  // Row: 2000 2000 _ 2010 | 2000 _ 3000 (an edge) | 2000 _ _ _ 2000 (3 px) | _ 1500 _ _ | 1500 ...
  const std::vector<std::uint16_t> row = {2000, 2000, 0, 2010, 2000, 0, 3000, 3000, 0, 0, 0, 3000, 0, 1500,
                                          0,    0,    1500, 1500, 1500, 1500};
  cv::Mat1w depth(1, static_cast<int>(row.size()));
  for (std::size_t i = 0; i < row.size(); ++i) depth(0, static_cast<int>(i)) = row[i];
  cv::Mat1w one = depth.clone();
  KinectSensor::make_holes_coherent(one, 1, 0.05);
  EXPECT_EQ(one(0, 2), 2000) << "a 1-px hole on one surface takes the left end's reading";
  EXPECT_EQ(one(0, 5), 0) << "a hole across a depth edge (2000 | 3000) stays";
  EXPECT_EQ(one(0, 8) + one(0, 9) + one(0, 10), 0) << "a 3-px hole stays with a limit of 1";
  EXPECT_EQ(one(0, 13), 0) << "a lone reading between holes is lost";
  EXPECT_EQ(one(0, 16), 1500);
  cv::Mat1w three = depth.clone();
  KinectSensor::make_holes_coherent(three, 3, 0.05);
  EXPECT_EQ(three(0, 8), 3000);
  EXPECT_EQ(three(0, 10), 3000) << "with a limit of 3 the 3-px hole is filled from its ends";
  EXPECT_EQ(three(0, 14), 1500) << "the 2-px hole between two 1500 readings is filled";
  EXPECT_EQ(three(0, 12), 0) << "a hole across the edge 3000 | 1500 stays";
  EXPECT_EQ(three(0, 13), 1500) << "a reading that joined a run by the filling stays";
  // 0 changes nothing; a column is treated like a row.
  cv::Mat1w zero = depth.clone();
  KinectSensor::make_holes_coherent(zero, 0, 0.05);
  EXPECT_EQ(cv::countNonZero(zero != depth), 0);
  cv::Mat1w column = depth.t();
  KinectSensor::make_holes_coherent(column, 1, 0.05);
  EXPECT_EQ(cv::countNonZero(column.t() != one), 0);
}

// On whole frames it gives fewer, wider holes, like the real frames' (docs/rdsf-synth.md): the same seed
// with 1 against 0.
TEST(SynthSensor, CoherentHolesAreFewerAndWider) {
  double runs[2] = {0, 0}, specks[2] = {0, 0};
  for (int px : {0, 1}) {
    SynthParams p = small_params(31);
    p.width_px = 640;
    p.height_px = 480;
    p.frames = 8;
    p.clip_frames = 2;
    p.sensor.coherent_holes_px = px;
    SynthSequence sequence(p);
    for (int i = 0; i < p.frames; ++i) {
      const rdsf::synth::DepthStatistics s = rdsf::synth::depth_statistics(sequence.frame(i).depth_mm);
      runs[px] += s.hole_runs_per_row / p.frames;
      specks[px] += s.single_pixel_hole_share / p.frames;
    }
  }
  std::printf("[figures] hole runs per row %.1f -> %.1f, of them 1 px %.2f -> %.2f\n", runs[0], runs[1], specks[0],
              specks[1]);
  EXPECT_LT(runs[1], 0.85 * runs[0]);
  EXPECT_LT(specks[1], 0.15);
  EXPECT_GT(specks[0], 0.2);
}
// trays, as the real boxes from the middleware's user mask do), and carrying a box puts shapes in front.
TEST(SynthPeople, CarriedThingsAndClothesBelongToThePerson) {
  using namespace rdsf::synth;
  PersonBody body;
  body.height_m = 1.7;
  PersonPose pose;
  pose.present = true;
  pose.yaw_rad = 0;  // facing +Z
  std::vector<Shape> plain;
  add_person_shapes(body, pose, 7, plain);
  double plain_front = -1e9;
  for (const Shape& s : plain) plain_front = std::max(plain_front, s.kind == ShapeKind::box ? s.centre.z : std::max(s.a.z, s.b.z) + s.radius_m);
  for (const Carried carried : {Carried::backpack, Carried::shoulder_bag, Carried::handbag, Carried::box, Carried::tray}) {
    PersonBody b = body;
    b.carried = carried;
    b.coat = true;
    b.garment = Garment::skirt;
    b.hair_style = HairStyle::long_hair;
    b.bag_half_m = {0.2, carried == Carried::tray ? 0.012 : 0.15, 0.15};
    std::vector<Shape> shapes;
    add_person_shapes(b, pose, 7, shapes);
    EXPECT_GT(shapes.size(), plain.size());
    int boxes = 0;
    double front = -1e9;
    for (const Shape& s : shapes) {
      EXPECT_EQ(s.owner, 7);
      if (s.kind == ShapeKind::box) {
        ++boxes;
        front = std::max(front, s.centre.z + s.half_m.z);
      }
    }
    EXPECT_EQ(boxes, 1) << static_cast<int>(carried);
    if (carried == Carried::box || carried == Carried::tray) {
      EXPECT_GT(front, plain_front + 0.1);
    }
    if (carried == Carried::backpack) {
      EXPECT_LT(front, 0.0) << "a backpack hangs behind";
    }
  }
  // sitting lowers the head; bending brings it forward
  PersonPose sitting = pose, bending = pose;
  sitting.posture = Posture::sitting;
  bending.posture = Posture::bending;
  bending.bend_rad = 1.0;
  auto top = [&](const PersonPose& p) {
    std::vector<Shape> shapes;
    add_person_shapes(body, p, 7, shapes);
    double y = 0;
    for (const Shape& s : shapes) y = std::max(y, std::max(s.a.y, s.b.y) + s.radius_m);
    return y;
  };
  EXPECT_NEAR(top(pose), 1.7, 0.03);
  EXPECT_LT(top(sitting), 1.45);
  EXPECT_LT(top(bending), 1.45);
}

// The frame analyser must find the people the generator renders: people with visible_fraction >= 0.8 at
// 1.5-6 m need a candidate whose strict box has IoU >= 0.5 with their box. The strict box is
// height x height/2 (the thesis's), so a person seen from the side (box narrower than 0.26 x its height)
// cannot reach IoU 0.5 even when found exactly; they are counted apart too. Four seeds, 690 frames, so
// that the figure does not hang on one room.
struct Recall {
  int eligible = 0, found = 0, upright = 0, upright_found = 0;
  double recall() const { return eligible > 0 ? static_cast<double>(found) / eligible : 0.0; }
  double upright_recall() const { return upright > 0 ? static_cast<double>(upright_found) / upright : 0.0; }
};

Recall detector_recall(bool classic) {
  const rdsf::FrameAnalyser analyser;
  Recall r;
  for (const std::uint64_t seed : {2024, 11, 12, 13}) {
    SynthParams p = people_scene(seed == 2024 ? 240 : 150, 2, 5, seed);
    p.clip_frames = 15;
    if (classic) p = rdsf::synth::with_classic_values(p);
    SynthSequence sequence(p);
    for (int i = 0; i < p.frames; ++i) {
      const SynthFrame f = sequence.frame(i);
      const rdsf::FrameAnalysis analysis = analyser.analyse(f.depth_frame(p.camera()), /*with_features=*/false);
      for (const auto& person : f.people) {
        if (person.visible_fraction < 0.8 || person.distance_mm < 1500 || person.distance_mm > 6000) continue;
        double best = 0;
        for (const auto& c : analysis.candidates) best = std::max(best, rdsf::iou(c.strict_box, person.box));
        const bool hit = best >= 0.5;
        const bool side_on = person.box.width < 0.26 * person.box.height;
        ++r.eligible;
        r.found += hit ? 1 : 0;
        if (!side_on) {
          ++r.upright;
          r.upright_found += hit ? 1 : 0;
        }
      }
    }
  }
  std::printf(
      "frame analyser on synthetic frames (%s): %d of %d people found (recall %.3f); without side-on people "
      "%d of %d (recall %.3f)\n",
      classic ? "--classic" : "default variety", r.found, r.eligible, r.recall(), r.upright_found, r.upright,
      r.upright_recall());
  return r;
}

// The generator without the variety of issue 13 (--classic): the figures of before it.
TEST(SynthDetector, FrameAnalyserFindsRenderedPeopleClassic) {
  const Recall r = detector_recall(/*classic=*/true);
  // Measured before the variety, and with --classic now (the same frames): 508 of 559 (0.909); without
  // side-on people 502 of 509 (0.986).
  EXPECT_GE(r.eligible, 500);
  EXPECT_GE(r.recall(), 0.90);
  EXPECT_GE(r.upright_recall(), 0.97);
}

// With the default variety (sitting, bending, arms out, coats, bags and boxes, pairs side by side, clutter
// beside people, 8-bit captures) the frame analyser misses more: these are the hard cases of real labs.
TEST(SynthDetector, FrameAnalyserFindsRenderedPeople) {
  const Recall r = detector_recall(/*classic=*/false);
  // Measured: 353 of 445 (0.793); without side-on people 352 of 420 (0.838).
  EXPECT_GE(r.eligible, 350);
  EXPECT_GE(r.recall(), 0.75);
  EXPECT_GE(r.upright_recall(), 0.78);
}

}  // namespace
