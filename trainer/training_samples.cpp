#include "trainer/training_samples.hpp"

#include <algorithm>
#include <ostream>

#include "rdsf/classifier/seeded_sampling.hpp"
#include "cli/progress.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/ordered_pool.hpp"
#include "rdsf/core/stable_hash.hpp"
#include "rdsf/dataset/sample_groups.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/features/feature_spec_record.hpp"
#include "rdsf/features/feature_subset.hpp"
#include "rdsf/features/rdsf_extractor.hpp"

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
                     const std::string& role, const std::string& asked_by, std::optional<FeatureSpec>& spec,
                     CropProvenance& crops, std::ostream& log) {
  const char* what = label == 1 ? "positives" : "negatives";
  ClassPick pick;
  std::vector<PoolEntry> pool;
  for (const std::string& path : paths) {
    SampleSet set = SampleSet::open_read(path);
    if (!spec) spec = set.feature_spec();
    if (set.feature_spec() != *spec) {
      fail(path, feature_spec_mismatch("sample set feature spec", set.feature_spec(), "the training's", *spec));
    }
    const std::string crops_differ =
        crop_provenance_mismatch(set.manifest().crops, "its crops", crops, "the training's crops so far");
    if (!crops_differ.empty()) fail(path, "crops cut differently: " + crops_differ);
    crops = known_of(crops, set.manifest().crops);
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


// Rank of the k-th of `count` chosen samples of a class: `shards` contiguous blocks of nearly equal size.
int block_owner(std::size_t k, std::size_t count, int shards) {
  return static_cast<int>(k * static_cast<std::size_t>(shards) / std::max<std::size_t>(1, count));
}

// Appends a class's rows (those of rank `shard` only: the others are another rank's) and every row's label,
// origin, source and owner. `row` counts every row, `local` the rows computed here.
void append_rows(const ClassPick& pick, int label, const FeatureSubset* subset, const RdsfExtractor& extractor,
                 int threads, const SampleChoice& choice, ChosenSamples& out, int& row, int& local,
                 cli::Progress& progress, std::vector<SampleOrigin>& origins,
                 std::vector<std::pair<std::size_t, std::size_t>>& sources) {
  std::size_t k = 0;  // the class's chosen sample
  for (std::size_t s = 0; s < pick.sets.size(); ++s) {
    std::vector<std::size_t> indices;
    for (const PoolEntry& e : pick.chosen) {
      if (e.set == s) indices.push_back(e.record);
    }
    for (std::size_t begin = 0; begin < indices.size(); begin += kChunk) {
      const std::vector<std::size_t> chunk(indices.begin() + static_cast<long>(begin),
                                          indices.begin() + static_cast<long>(std::min(indices.size(), begin + kChunk)));
      std::vector<std::size_t> mine;
      for (std::size_t r : chunk) {
        const SampleRecord& record = pick.sets[s].records()[r];
        origins.push_back({record.source, record.frame});
        sources.emplace_back(s, r);
        const int owner = block_owner(k++, pick.chosen.size(), choice.shards);
        if (choice.shards > 1) out.owner.push_back(owner);
        if (owner == choice.shard) mine.push_back(r);
      }
      out.labels.insert(out.labels.end(), chunk.size(), label);
      row += static_cast<int>(chunk.size());
      if (!mine.empty()) {
        const cv::Mat1f rows = subset != nullptr ? pick.sets[s].features(*subset, mine, threads)
                                                 : pick.sets[s].features(extractor, mine, threads);
        if (rows.rows != static_cast<int>(mine.size()) || rows.cols != out.rows.cols) {
          fail(pick.sets[s].dir(), "feature rows of the wrong size were returned");
        }
        rows.copyTo(out.rows.rowRange(local, local + rows.rows));
        local += rows.rows;
      }
      progress.update(row, (label == 1 ? "positives from " : "negatives from ") + pick.sets[s].dir());
    }
  }
}

// Positives with a crop among this rank's (augmentation copies them), in append_rows' order of ranks.
std::size_t positives_with_crop_here(const ClassPick& pick, const SampleChoice& choice) {
  std::size_t k = 0, count = 0;
  for (std::size_t s = 0; s < pick.sets.size(); ++s) {
    for (const PoolEntry& e : pick.chosen) {
      if (e.set != s) continue;
      const bool here = block_owner(k++, pick.chosen.size(), choice.shards) == choice.shard;
      if (here && pick.sets[s].records()[e.record].has_crop) ++count;
    }
  }
  return count;
}

// The columns to train on: --feature-pool's seeded draw (or as many as fit the memory budget, 4 bytes of
// float and 1 of bin per value) plus the features an --init model reads; the given columns when there are
// any; empty for all of the spec's features.
std::vector<int> feature_pool_columns(const SampleChoice& choice, const FeatureSpec& spec, std::size_t samples,
                                      std::ostream& log) {
  if (!choice.columns.empty()) return choice.columns;
  const auto dimension = static_cast<std::size_t>(spec.dimension());
  std::size_t pool = choice.feature_pool;
  if (pool == 0) {
    pool = std::max<std::size_t>(1, choice.memory_budget_mb * (std::size_t{1} << 20) / (5 * std::max<std::size_t>(1, samples)));
  }
  std::vector<int> columns;
  if (pool >= dimension) return columns;
  for (const std::size_t f : seeded_subset(dimension, pool, choice.seed ^ fnv1a64("feature pool"))) {
    columns.push_back(static_cast<int>(f));
  }
  const std::size_t drawn = columns.size();
  columns.insert(columns.end(), choice.required_features.begin(), choice.required_features.end());
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  log << "rdsf-train: feature pool of " << columns.size() << " of the " << dimension << " features of " << spec.name()
      << " (seeded; --feature-pool";
  if (columns.size() > drawn) log << "; " << columns.size() - drawn << " more that the --init model reads";
  log << ")\n";
  return columns;
}

// Rows computed by this rank: its block of each class.
std::size_t rows_of_rank(const ClassPick& pos, const ClassPick& neg, const SampleChoice& choice) {
  if (choice.shards < 1 || choice.shard < 0 || choice.shard >= choice.shards) {
    throw Error("rank " + std::to_string(choice.shard) + " of " + std::to_string(choice.shards) + " is not a rank");
  }
  std::size_t here = 0;
  for (const std::size_t count : {pos.chosen.size(), neg.chosen.size()}) {
    for (std::size_t k = 0; k < count; ++k) here += block_owner(k, count, choice.shards) == choice.shard ? 1 : 0;
  }
  return here;
}

// Variants of every positive with a crop, after the originals (rows from `here` on, already allocated), with
// their original's origin (group). With ranks, each computes the copies of its own positives; every rank
// knows how many each has. Each copy depends on its crop and the sample's id only: the rows are the same
// with any thread count.
void append_augmented(const ClassPick& pos, const std::vector<std::pair<std::size_t, std::size_t>>& pos_sources,
                      const SampleChoice& choice, const FeatureSubset* subset, const RdsfExtractor& extractor,
                      std::size_t here, std::size_t here_augmented, int threads, std::vector<SampleOrigin>& origins,
                      ChosenSamples& out, std::ostream& log) {
  const auto per_crop = static_cast<std::size_t>(choice.augmentation.variants_per_crop());
  std::vector<SampleOrigin> extra_origins;
  std::vector<int> extra_owners;
  std::vector<std::size_t> mine;  // positives (of pos_sources) whose copies are computed here, in row order
  for (std::size_t k = 0; k < pos_sources.size(); ++k) {
    const SampleSet& set = pos.sets[pos_sources[k].first];
    if (!set.records()[pos_sources[k].second].has_crop) continue;
    const int owner = out.owner.empty() ? 0 : out.owner[k];
    extra_origins.insert(extra_origins.end(), per_crop, origins[k]);
    extra_owners.insert(extra_owners.end(), per_crop, owner);
    if (owner == choice.shard) mine.push_back(k);
  }
  if (mine.size() * per_crop != here_augmented) fail(pos.sets.front().dir(), "the augmented rows were miscounted");
  parallel_for_chunks(mine.size(), 64, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t m = begin; m < end; ++m) {
      const SampleSet& set = pos.sets[pos_sources[mine[m]].first];
      const std::size_t record = pos_sources[mine[m]].second;
      const std::vector<cv::Mat1w> copies =
          augmented_crops(set.depth_crop(record), choice.augmentation, set.records()[record].id);
      if (copies.size() != per_crop) fail(set.dir(), "augmentation gave another number of copies than expected");
      for (std::size_t c = 0; c < per_crop; ++c) {
        float* values = out.rows.ptr<float>(static_cast<int>(here + m * per_crop + c));
        if (subset) {
          subset->compute(copies[c], values);
        } else {
          extractor.compute(copies[c], values);
        }
      }
    }
  });
  out.labels.insert(out.labels.end(), extra_origins.size(), 1);
  out.augmented.insert(out.augmented.end(), extra_origins.size(), true);
  origins.insert(origins.end(), extra_origins.begin(), extra_origins.end());
  if (!out.owner.empty()) out.owner.insert(out.owner.end(), extra_owners.begin(), extra_owners.end());
  log << "rdsf-train: augmentation (" << choice.augmentation.describe() << "): " << extra_origins.size()
      << " more positives\n";
}

// The analyser options every set records, when they all record the same; else none.
RecordedParameters agreed_analyser_options(const std::vector<SampleSet>& pos, const std::vector<SampleSet>& neg) {
  std::optional<RecordedParameters> agreed;
  for (const std::vector<SampleSet>* sets : {&pos, &neg}) {
    for (const SampleSet& set : *sets) {
      const RecordedParameters& options = set.manifest().analyser_options;
      if (options.empty() || (agreed && *agreed != options)) return {};
      agreed = options;
    }
  }
  return agreed.value_or(RecordedParameters{});
}

}  // namespace

ChosenSamples choose_samples(const SampleChoice& choice, std::ostream& log, int threads) {
  std::optional<FeatureSpec> spec = choice.spec;
  CropProvenance crops = choice.crops;
  const ClassPick pos = pick_class(choice.pos_sets, 1, choice.positives, choice.seed, choice.role_prefix + "pos",
                                   choice.asked_by, spec, crops, log);
  const ClassPick neg = pick_class(choice.neg_sets, 0, choice.negatives, choice.seed, choice.role_prefix + "neg",
                                   choice.asked_by, spec, crops, log);
  ChosenSamples out;
  out.spec = *spec;
  out.crops = crops;
  out.analyser_options = agreed_analyser_options(pos.sets, neg.sets);
  const std::size_t samples = pos.chosen.size() + neg.chosen.size();
  out.columns = feature_pool_columns(choice, out.spec, samples, log);
  const RdsfExtractor extractor(out.spec);
  std::optional<FeatureSubset> subset;
  if (!out.columns.empty()) subset.emplace(out.spec, out.columns);
  const int columns = subset ? subset->size() : extractor.dimension();
  const std::size_t here = rows_of_rank(pos, neg, choice);
  choice.augmentation.validate();
  // The augmented copies' rows follow the originals in the same matrix, allocated once (rows of a large
  // base are gigabytes: growing them would copy every row again).
  const auto per_crop = static_cast<std::size_t>(choice.augmentation.variants_per_crop());
  const std::size_t here_augmented = per_crop * positives_with_crop_here(pos, choice);
  out.rows.create(static_cast<int>(here + here_augmented), columns);
  int row = 0, local = 0;
  cli::Progress progress(log, "samples", static_cast<std::int64_t>(samples));
  std::vector<SampleOrigin> origins;
  std::vector<std::pair<std::size_t, std::size_t>> pos_sources, neg_sources;
  append_rows(pos, 1, subset ? &*subset : nullptr, extractor, threads, choice, out, row, local, progress, origins,
              pos_sources);
  append_rows(neg, 0, subset ? &*subset : nullptr, extractor, threads, choice, out, row, local, progress, origins,
              neg_sources);
  progress.finish(row, "features ready");
  out.augmented.assign(out.labels.size(), false);
  if (choice.augmentation.enabled()) {
    append_augmented(pos, pos_sources, choice, subset ? &*subset : nullptr, extractor, here, here_augmented, threads,
                     origins, out, log);
  }
  if (choice.group_frames > 0) {
    out.groups = sample_groups(origins, choice.group_frames, choice.group_by).group;
    out.origins = std::move(origins);
  }
  out.sets = pos.uses;
  out.sets.insert(out.sets.end(), neg.uses.begin(), neg.uses.end());
  return out;
}

}  // namespace rdsf
