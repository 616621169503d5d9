// Live mode (LivePipeline): at most one frame waits per worker, the oldest waiting frame is dropped and
// counted when a newer one arrives (newest wins), frames come out in arrival order, latency percentiles
// from the injected clock. Driven by a ManualClock and by the test deciding when the consumer is free:
// nothing sleeps.
#include <gtest/gtest.h>

#include <future>
#include <thread>
#include <vector>

#include "rdsf/classifier/model_file.hpp"
#include "rdsf/core/clock.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/pipeline/live_pipeline.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

BoostedModel reference_model() {
  return read_model_file(std::string(RDSF_SOURCE_DIR) + "/tests/reference_models/rdsf-model-v2-tree.yml");
}

DepthFrame frame_number(std::int64_t i) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {200 + 5 * static_cast<int>(i % 20), 100, 40, 360}, 2000);
  frame.index = i;
  frame.name = std::to_string(i);
  return frame;
}

}  // namespace

TEST(Percentile, NearestRank) {
  EXPECT_EQ(percentile({}, 50), 0.0);
  EXPECT_EQ(percentile({5.0}, 99), 5.0);
  std::vector<double> v;
  for (int i = 100; i >= 1; --i) v.push_back(i);  // 1..100, any order
  EXPECT_EQ(percentile(v, 50), 50.0);
  EXPECT_EQ(percentile(v, 95), 95.0);
  EXPECT_EQ(percentile(v, 99), 99.0);
  EXPECT_EQ(percentile(v, 100), 100.0);
  EXPECT_EQ(percentile({1, 2, 3}, 50), 2.0);
}

TEST(LivePipeline, SlowConsumerDropsTheOldestWaitingFrameAndCountsIt) {
  // No worker thread: the test is the consumer and runs a frame only when it "has time".
  const BoostedModel model = reference_model();
  PeoplePipeline pipeline(PipelineParams{}, &model);
  ManualClock clock(1'000'000);
  std::vector<std::int64_t> out, latency;
  LivePipeline live(pipeline, {0}, clock, [&](const DepthFrame& f, PipelineFrame&, std::int64_t latency_us) {
    out.push_back(f.index);
    latency.push_back(latency_us);
  });
  // Frames arrive every 33 ms; the consumer is free once every third frame and then takes 40 ms.
  for (std::int64_t i = 0; i < 9; ++i) {
    clock.set_us(1'000'000 + 33'000 * i);
    live.push(frame_number(i));
    EXPECT_EQ(live.queued(), 1u);  // never more than one waiting (one "worker")
    if (i % 3 == 2) {
      clock.advance_us(4'000 * (i + 1) / 3);  // the consumer's delay: 4, 8, 12 ms
      EXPECT_TRUE(live.run_queued());
      EXPECT_FALSE(live.run_queued());  // nothing left
    }
  }
  live.finish();
  EXPECT_EQ(out, (std::vector<std::int64_t>{2, 5, 8}));  // newest frame wins, arrival order
  EXPECT_EQ(latency, (std::vector<std::int64_t>{4'000, 8'000, 12'000}));
  const LiveStats s = live.stats();
  EXPECT_EQ(s.arrived, 9);
  EXPECT_EQ(s.dropped, 6);
  EXPECT_EQ(s.processed, 3);
  EXPECT_EQ(s.p50_ms, 8.0);
  EXPECT_EQ(s.p95_ms, 12.0);
  EXPECT_EQ(s.p99_ms, 12.0);
  EXPECT_EQ(s.max_ms, 12.0);
}

TEST(LivePipeline, FinishRunsWhatIsStillWaitingAndTracksInOrder) {
  const BoostedModel model = reference_model();
  PipelineParams params;
  params.score_threshold = -1e300;  // every candidate is a person: tracking matters
  PeoplePipeline reference(params, &model);
  PeoplePipeline pipeline(params, &model);
  ManualClock clock;
  std::vector<std::vector<int>> person;
  LivePipeline live(pipeline, {0}, clock,
                    [&](const DepthFrame&, PipelineFrame& r, std::int64_t) { person.push_back(r.person); });
  std::vector<std::vector<int>> expected;
  for (std::int64_t i = 0; i < 6; ++i) {
    const DepthFrame f = frame_number(i);
    expected.push_back(reference.process(f).person);
    live.push(f);
    live.run_queued();
  }
  live.push(frame_number(6));
  expected.push_back(reference.process(frame_number(6)).person);
  live.finish();  // runs the waiting frame
  EXPECT_EQ(person, expected);
  EXPECT_EQ(live.stats().dropped, 0);
  EXPECT_THROW(live.push(frame_number(7)), Error);
}

TEST(LivePipeline, WorkersBusyWithASlowConsumerDropAllButTheNewestPerWorker) {
  const BoostedModel model = reference_model();
  PeoplePipeline pipeline(PipelineParams{}, &model);
  ManualClock clock;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::vector<std::int64_t> out;
  LivePipeline live(pipeline, {2}, clock, [&](const DepthFrame& f, PipelineFrame&, std::int64_t) {
    if (f.index == 0) released.wait();  // the consumer is stuck on the first frame
    out.push_back(f.index);
  });
  auto taken = [&] {  // until a worker has taken the waiting frame (no sleeping: yield)
    while (live.queued() != 0) std::this_thread::yield();
  };
  live.push(frame_number(0));
  taken();
  live.push(frame_number(1));
  taken();  // both workers hold a frame now: worker A blocks on frame 0's output, B waits for its turn
  for (std::int64_t i = 2; i < 8; ++i) {
    live.push(frame_number(i));
    EXPECT_LE(live.queued(), 2u);  // one waiting frame per worker at most
  }
  EXPECT_EQ(live.stats().dropped, 4);  // 2, 3, 4, 5 replaced by 6 and 7
  release.set_value();
  live.finish();
  EXPECT_EQ(out, (std::vector<std::int64_t>{0, 1, 6, 7}));
  const LiveStats s = live.stats();
  EXPECT_EQ(s.arrived, 8);
  EXPECT_EQ(s.processed, 4);
  EXPECT_EQ(s.dropped, 4);
}

TEST(LivePipeline, ErrorOfAFrameIsRethrown) {
  const BoostedModel model = reference_model();
  PeoplePipeline pipeline(PipelineParams{}, &model);
  ManualClock clock;
  for (int workers : {0, 2}) {
    LivePipeline live(pipeline, {workers}, clock, {});
    DepthFrame bad;
    bad.name = "bad";
    live.push(bad);
    const std::string message = test::error_message([&] { live.finish(); });
    EXPECT_NE(message.find("frame bad: has no depth image"), std::string::npos) << message;
  }
}
