// rdsf-adapt on ROS 1 bags (issues 35 and 36): a lab with a RealSense or a Kinect v2 records its room as a
// bag. A 512x424 room with a Kinect v2's field of view, rendered by rdsf-synth and written to bags by
// scripts/frames-to-bag.py (its camera.yml as each bag's CameraInfo), is adapted end to end: the room and its
// empty recording are read from the bags with their camera model, and a bag's frames are named by their
// index (0, 1, ...), which the truth names too. Skipped where the bag writer's Python packages are missing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "rdsf/dataset/sample_set.hpp"
#include "support/bag_writer.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

TEST(BagAdapt, ARoomRecordedAsBagsIsAdaptedWithItsCameraInfo) {
  if (!test::bag_writer_available()) GTEST_SKIP() << test::kBagWriterMissing;
  test::TempDir dir;
  const std::string synth = test::quote(test::program("rdsf-synth")) +
                            " --force --people 1..2 --clip-frames 30 --seed 7 --size 512x424 --fov 70.6x60 --out ";
  ASSERT_EQ(test::run(synth + test::quote(dir / "room") + " --frames 60").exit_code, 0);
  ASSERT_EQ(test::run(synth + test::quote(dir / "empty") + " --frames 30 --empty").exit_code, 0);
  const std::string room = test::write_bag(dir / "room", dir / "room.bag", "--no-colour");
  const std::string empty = test::write_bag(dir / "empty", dir / "empty.bag", "--no-colour");
  // The truth of the bag: the folder's boxes with each frame named by its index (000007 -> 7).
  {
    std::ifstream in(dir / "room/boxes.csv");
    std::ofstream out(dir / "truth.csv");
    std::string line;
    std::getline(in, line);
    out << line << "\n";
    while (std::getline(in, line)) {
      const std::size_t comma = line.find(',');
      out << std::stoi(line.substr(0, comma)) << line.substr(comma) << "\n";
    }
  }
  const std::filesystem::path models = dir.path() / "models";
  std::filesystem::create_directories(models / "people");
  std::filesystem::copy_file(std::string(RDSF_SOURCE_DIR) + "/models/people/v2.yml", models / "people/v2.yml");
  const test::RunResult r = test::run(
      test::quote(test::program("rdsf-adapt")) + " --source " + test::quote(room) + " --empty " + test::quote(empty) +
      " --truth " + test::quote(dir / "truth.csv") + " --out " + test::quote(dir / "out") +
      " --name room --budget 6 --rounds 3 --threads 2 --base-frames 60 --models-dir " + test::quote(models.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(models / "room/v1.yml"));
  // The room's answered samples and mined negatives come from the bags' 512x424 frames.
  const SampleSet answered = SampleSet::open_read(dir / "out/sets/room");
  const SampleSet negatives = SampleSet::open_read(dir / "out/sets/room-negatives");
  ASSERT_GT(answered.records().size(), 0u);
  ASSERT_GT(negatives.records().size(), 0u);
  for (const SampleSet* set : {&answered, &negatives}) {
    for (const SampleRecord& rec : set->records()) {
      EXPECT_NE(rec.source.find(".bag"), std::string::npos) << rec.source;
      EXPECT_LE(rec.strict_box.x + rec.strict_box.width, 512) << rec.frame;
      EXPECT_LE(rec.strict_box.y + rec.strict_box.height, 424) << rec.frame;
    }
  }
}
