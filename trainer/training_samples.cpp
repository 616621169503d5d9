#include "trainer/training_samples.hpp"

#include <charconv>
#include <ostream>

#include "classifier/seeded_sampling.hpp"
#include "cli/progress.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/stable_hash.hpp"
#include "dataset/sample_set.hpp"
#include "features/rdsf_extractor.hpp"

namespace rdsf {
namespace {

struct PoolEntry {
  std::size_t set = 0;     // index into the opened sets
  std::size_t record = 0;  // record index within the set
};

struct ClassPick {
  std::vector<SampleSet> sets;
  std::vector<PoolEntry> chosen;
  std::vector<SampleSetUse> uses;
};

ClassPick pick_class(const std::vector<std::string>& paths, int label, std::size_t wanted, std::uint64_t seed,
                     const std::string& role, const std::string& asked_by, std::ostream& log) {
  const FeatureSpec spec;
  const char* what = label == 1 ? "positives" : "negatives";
  ClassPick pick;
  std::vector<PoolEntry> pool;
  for (const std::string& path : paths) {
    SampleSet set = SampleSet::open_read(path);
    if (set.feature_spec() != spec) {
      fail(path, "sample set feature spec '" + set.feature_spec().canonical() + "' (hash " +
                     set.feature_spec().hash() + ") differs from this build's '" + spec.canonical() + "' (hash " +
                     spec.hash() + ")");
    }
    SampleSetUse use;
    use.role = role;
    use.path = path;
    use.manifest_hash = set.manifest_hash();
    for (std::size_t r = 0; r < set.records().size(); ++r) {
      if (set.records()[r].label == label) {
        pool.push_back({pick.sets.size(), r});
        ++use.available;
      }
    }
    if (use.available == 0) log << "rdsf-train: warning: " << path << " holds no " << what << "\n";
    pick.uses.push_back(use);
    pick.sets.push_back(std::move(set));
  }
  if (pool.empty()) {
    throw Error(std::string("no ") + what + " to train with (" + (paths.empty() ? "no sets given" : "the sets hold none") + ")");
  }
  if (wanted > pool.size()) {
    log << "rdsf-train: warning: " << asked_by << " asks for " << wanted << " " << what << " but the sets hold "
        << pool.size() << ": using all " << pool.size() << "\n";
  }
  const std::vector<std::size_t> subset =
      seeded_subset(pool.size(), wanted == 0 ? pool.size() : wanted, seed ^ fnv1a64(role));
  for (std::size_t k : subset) {
    pick.chosen.push_back(pool[k]);
    ++pick.uses[pool[k].set].used;
  }
  return pick;
}

// Features are fetched in chunks: little memory beyond the result, and progress as they come.
constexpr std::size_t kChunk = 2048;

void append_rows(const ClassPick& pick, int label, const RdsfExtractor& extractor, int threads, ChosenSamples& out,
                 int& row, cli::Progress& progress) {
  for (std::size_t s = 0; s < pick.sets.size(); ++s) {
    std::vector<std::size_t> indices;
    for (const PoolEntry& e : pick.chosen) {
      if (e.set == s) indices.push_back(e.record);
    }
    for (std::size_t begin = 0; begin < indices.size(); begin += kChunk) {
      const std::vector<std::size_t> chunk(indices.begin() + static_cast<long>(begin),
                                          indices.begin() + static_cast<long>(std::min(indices.size(), begin + kChunk)));
      const cv::Mat1f rows = pick.sets[s].features(extractor, chunk, threads);
      if (rows.rows != static_cast<int>(chunk.size()) || rows.cols != extractor.dimension()) {
        fail(pick.sets[s].dir(), "feature rows of the wrong size were returned");
      }
      rows.copyTo(out.rows.rowRange(row, row + rows.rows));
      row += rows.rows;
      out.labels.insert(out.labels.end(), chunk.size(), label);
      progress.update(row, (label == 1 ? "positives from " : "negatives from ") + pick.sets[s].dir());
    }
  }
}

}  // namespace

ChosenSamples choose_samples(const SampleChoice& choice, std::ostream& log, int threads) {
  const ClassPick pos = pick_class(choice.pos_sets, 1, choice.positives, choice.seed, choice.role_prefix + "pos",
                                   choice.asked_by, log);
  const ClassPick neg = pick_class(choice.neg_sets, 0, choice.negatives, choice.seed, choice.role_prefix + "neg",
                                   choice.asked_by, log);
  const RdsfExtractor extractor;
  ChosenSamples out;
  out.rows.create(static_cast<int>(pos.chosen.size() + neg.chosen.size()), extractor.dimension());
  int row = 0;
  cli::Progress progress(log, "samples", out.rows.rows);
  append_rows(pos, 1, extractor, threads, out, row, progress);
  append_rows(neg, 0, extractor, threads, out, row, progress);
  progress.finish(row, "features ready");
  out.sets = pos.uses;
  out.sets.insert(out.sets.end(), neg.uses.begin(), neg.uses.end());
  return out;
}

std::size_t write_thesis_text(const ChosenSamples& samples, const std::string& path, bool overwrite) {
  AtomicTextFile file(path, overwrite);
  std::ostream& out = file.stream();
  std::string line;
  char number[32];
  for (int r = 0; r < samples.rows.rows; ++r) {
    line.assign(samples.labels[static_cast<std::size_t>(r)] == 1 ? "1" : "0");
    const float* values = samples.rows[r];
    for (int c = 0; c < samples.rows.cols; ++c) {
      const auto written = std::to_chars(number, number + sizeof number, values[c]);
      line.push_back(' ');
      line.append(number, written.ptr);
    }
    line.push_back('\n');
    out << line;
  }
  file.commit();
  return static_cast<std::size_t>(samples.rows.rows);
}

}  // namespace rdsf
