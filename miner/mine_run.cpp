#include "miner/mine_run.hpp"

#include <charconv>
#include <cstdio>
#include <iostream>
#include <optional>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "cli/cli.hpp"
#include "cli/progress.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_merge.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/pipeline/model_fit.hpp"
#include "rdsf/pipeline/model_scorer.hpp"

namespace rdsf {

namespace {

void report_open(const SampleSetWriter& writer, const char* program) {
  if (writer.took_over_stale_lock()) {
    std::cerr << program << ": " << writer.dir() << ": took over the lock left by a killed writer ("
              << writer.stale_holder() << ")\n";
  }
  for (const std::string& repair : writer.repairs()) {  // torn rows, orphan crops, unusable crops
    std::cerr << program << ": " << writer.dir() << ": repaired " << repair << "\n";
  }
  if (!writer.records().empty()) {
    std::cerr << program << ": " << writer.dir() << " already holds " << writer.records().size()
              << " samples; continuing (exact duplicates are skipped)\n";
  }
}

}  // namespace

void parse_shard(const std::string& text, MineParams& params) {
  const std::size_t slash = text.find('/');
  int index = 0, count = 0;
  bool ok = slash != std::string::npos;
  if (ok) {
    const char* begin = text.data();
    const auto a = std::from_chars(begin, begin + slash, index);
    const auto b = std::from_chars(begin + slash + 1, begin + text.size(), count);
    ok = a.ec == std::errc() && a.ptr == begin + slash && b.ec == std::errc() && b.ptr == begin + text.size() &&
         count >= 1 && index >= 1 && index <= count;
  }
  if (!ok) throw cli::UsageError("--shard '" + text + "' must be i/n with 1 <= i <= n, e.g. 3/8");
  params.shard_index = index;
  params.shard_count = count;
}

namespace {

// The options, checked in one place: the shard, the library's limits (usage errors here), --min-score.
void check_mine_options(MineOptions& o) {
  parse_shard(o.shard, o.mine);
  try {
    check_mine_params(o.mine);
  } catch (const Error& e) {
    throw cli::UsageError(e.what());
  }
  if (o.model.empty() && o.min_score_given) throw cli::UsageError("--min-score needs --model (hard-negative mode)");
}

// Hard-negative mode: the model's stated detection options for those not given, and its scorer (only the
// features it reads) keeping the candidates it scores >= --min-score.
void take_hard_negative_model(const MineOptions& o, MineParams& p) {
  const BoostedModel model = BoostedModel::load(o.model, o.models_dir);
  p.analyser = o.given.for_model(p.analyser, &model);
  if (const std::string stated = o.given.said_of(model); !stated.empty()) std::cerr << "rdsf-mine: " << stated << "\n";
  check_model_fits(model, p.analyser);
  const ModelScorer scorer(model);
  p.scorer = [scorer](const cv::Mat1w& crop) { return scorer.score(crop); };
  p.min_score = o.min_score;
  p.model = model_reference(model);
  std::cerr << "rdsf-mine: hard-negative mode: keeping candidates that " << p.model << " (" << model.path()
            << ") scores >= " << p.min_score << "\n";
}

// Mines every source into `writer` with a progress line; the wall time in seconds.
MineStats mine_with_progress(NegativeMiner& miner, SampleSetWriter& writer, double& seconds) {
  std::optional<cli::Progress> progress;
  auto extra = [](const MineStats& s) {
    return "candidates " + std::to_string(s.candidates) + "  kept " + std::to_string(s.kept) + "  duplicates " +
           std::to_string(s.duplicates);
  };
  const MineStats stats = miner.run(writer, [&](const MineStats& s) {
    if (!progress) {
      progress.emplace(std::cerr, "frames", s.total_frames);
    } else {
      progress->update(s.frames, extra(s));
    }
  });
  if (!progress) progress.emplace(std::cerr, "frames", stats.total_frames);
  progress->finish(stats.frames, extra(stats));
  seconds = progress->elapsed_s();
  return stats;
}

void report_mining(const MineStats& stats, const MineParams& p, double seconds) {
  const double frames = static_cast<double>(stats.frames);
  std::fprintf(stderr,
               "rdsf-mine: %lld frames, %.2f candidates per frame, kept %lld, duplicates skipped %lld, %.1f s "
               "(%.1f frames/s)\n",
               static_cast<long long>(stats.frames),
               stats.frames > 0 ? static_cast<double>(stats.candidates) / frames : 0.0,
               static_cast<long long>(stats.kept), static_cast<long long>(stats.duplicates), seconds,
               seconds > 0 ? frames / seconds : 0.0);
  if (p.scorer) {
    const std::int64_t scored = stats.candidates;
    std::fprintf(stderr, "rdsf-mine: hard negatives: %lld of %lld candidates scored >= %g (acceptance ratio %.4f)\n",
                 static_cast<long long>(scored - stats.below_score), static_cast<long long>(scored), p.min_score,
                 scored > 0 ? static_cast<double>(scored - stats.below_score) / static_cast<double>(scored) : 0.0);
  }
  if (stats.reached_max) std::cerr << "rdsf-mine: stopped: the set holds --max " << p.max_negatives << " negatives\n";
}

}  // namespace

int run_mine(MineOptions& o) {
  check_mine_options(o);
  MineParams& p = o.mine;
  if (!o.model.empty()) take_hard_negative_model(o, p);
  NegativeMiner miner(p);  // opens the sources: a bad one fails before the set is created
  SampleSetWriter writer = SampleSetWriter::open_or_create(o.out, p.analyser.features, p.camera, "rdsf-mine",
                                                           crop_provenance(p.analyser.candidates),
                                                           stated_options(p.analyser));
  report_open(writer, "rdsf-mine");
  std::cerr << "rdsf-mine: mining " << p.sources.size() << " source(s) into " << o.out << " (shard "
            << p.shard_index << "/" << p.shard_count << ", stride " << p.stride << ")\n";
  double seconds = 0;
  const MineStats stats = mine_with_progress(miner, writer, seconds);
  report_mining(stats, p, seconds);
  std::cerr << "rdsf-mine: " << o.out << " holds " << writer.records().size() << " samples\n";
  return 0;
}

int run_merge(const MineOptions& o) {
  if (o.merge.empty()) throw cli::UsageError("--merge needs at least one input sample set");
  if (!o.mine.sources.empty()) throw cli::UsageError("give either --source or --merge, not both");
  if (o.out.empty()) throw cli::UsageError("--merge needs --out SET");
  const SampleSet first = SampleSet::open_read(o.merge.front());
  SampleSetWriter writer =
      SampleSetWriter::open_or_create(o.out, first.feature_spec(), first.manifest().camera, "rdsf-mine --merge",
                                      first.manifest().crops, first.manifest().analyser_options);
  report_open(writer, "rdsf-mine");
  const MergeResult result = merge_sample_sets(o.merge, writer);
  std::cerr << "rdsf-mine: merged " << result.inputs << " sets into " << o.out << ": added " << result.added
            << ", duplicates skipped " << result.duplicates << "; it holds " << writer.records().size()
            << " samples\n";
  return 0;
}

}  // namespace rdsf
