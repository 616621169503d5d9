#pragma once
// Native Real AdaBoost with look-up-table weak classifiers (Schapire and Singer's domain partitioning).
// Each round, for every feature in parallel, the weights of the positive and negative samples are summed
// per bin (W+_j, W-_j); the feature with the smallest Z = 2 sum_j sqrt(W+_j W-_j) is chosen, its bin
// responses are h_j = 0.5 ln((W+_j + eps) / (W-_j + eps)), and the weights become w_i exp(-y_i h(x_i)),
// normalised to sum 1 (y = +1 person, -1 not). Deterministic: no randomness, ties go to the lower feature
// index, and every feature's sums are taken in sample order whatever the thread count.
//
// Deeper weak learners (depth d >= 2): a tree grown level by level (domain-partitioning trees). An inner
// node is the best two-way split of one feature's bins, bins <= t left and the others right, by the same
// criterion: the smallest Z = 2 (sqrt(W+_L W-_L) + sqrt(W+_R W-_R)) over the samples that reach it (stored as
// a table of -1 / +1: > 0 routes right). A leaf is the best look-up table over the samples that reach it.
// The nodes of a level share each pass over the bins, so a level reads the bins once, like a depth-1 round.
// Optionally (histogram_subtraction, off by default) one child of two is counted and the other is its
// parent minus its sibling. The tree's response is its
// leaf's; Z of the tree is the sum of its leaves' Z.
//
// Shrinkage: every response is multiplied by the learning rate nu (0 < nu <= 1) before it is added and
// before the reweighting (nu = 1: plain Real AdaBoost).
#include <cstddef>
#include <vector>

#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/classifier/row_shards.hpp"
#include "rdsf/classifier/weak_classifier.hpp"

namespace rdsf {

class NodeSamples;  // bin_histograms.hpp

/// The learner's settings (what its rounds are), apart from where the rows are: also the native backend's
/// part of BoostTrainingParams, which derives from it with its own defaults (depth 2, learning rate 0.5).
struct RealAdaBoostSettings {
  /// eps in the responses; 0 means 1 / (number of training samples).
  double smoothing = 0.0;
  /// Weight trimming: each round the lightest samples holding this fraction of the total weight are left
  /// out of the histograms (they are still reweighted and can come back). 0 = off; 0.05 is OpenCV's
  /// weight_trim_rate 0.95.
  double weight_trim = 0.0;
  /// Threads for the per-feature histograms; 0 = all cores (does not change the result).
  int threads = 0;
  /// Levels of look-up tables per weak classifier: 1 = one table (the thesis's kind of weak learner),
  /// 2-4 = trees of tables.
  int depth = 1;
  /// Shrinkage nu in (0, 1]: responses are multiplied by it.
  double learning_rate = 1.0;
  /// Histogram subtraction for trees (depth >= 2; issue 17): of two children of a node, only the one with
  /// fewer samples is counted and the other's sums are the parent's minus its sibling's (a difference
  /// below 1e-9 of the parent's sum is 0, so that an empty bin stays empty), so a level below the root
  /// costs about half a pass. The chosen features' tables are still summed directly, but the differences
  /// are rounded differently, so a near tie can choose another feature: models are then not the same
  /// bits as without it. Off by default.
  bool histogram_subtraction = false;
};

struct RealAdaBoostParams : RealAdaBoostSettings {
  /// Data-parallel training (row_shards.hpp): the data are this rank's rows; the per-bin sums of every
  /// feature and node, the class counts, node weights and the weights' normaliser are summed over the
  /// ranks (in rank order) so that every rank picks the same weak classifier. Null: one process.
  /// Weight trimming and histogram subtraction are not available with more than one rank.
  const RowShards* shards = nullptr;
};

struct RealAdaBoostRound {
  int round = 0;              ///< 1-based
  int feature = 0;            ///< chosen feature
  double z = 0.0;             ///< its normalisation factor Z (smaller is better; 1 = useless)
  double train_error = 0.0;   ///< training error of the sign of the sum so far
  std::size_t samples_used = 0;  ///< samples in the histograms (fewer than all when trimming)
};

/// `indices` (all of 0..labels.size()-1 when empty) reordered positives first, each class in its given
/// order: the sample order with which RealAdaBoost takes its faster path (build the BinnedMatrix with it).
std::vector<std::size_t> positives_first_order(const std::vector<int>& labels,
                                               const std::vector<std::size_t>& indices = {});

class RealAdaBoost {
 public:
  /// `labels` (1 person, 0 not) in the sample order of `data`, which must outlive this object.
  RealAdaBoost(const BinnedMatrix& data, std::vector<int> labels, RealAdaBoostParams params = {});

  /// Continued training (before the first round): every sample starts at the score F0 of a model it
  /// continues, so its weight is exp(-y F0) normalised to sum 1, the weight it would have after training
  /// that model from uniform weights (w ~ exp(-y F) holds for every round of Real AdaBoost); train_scores()
  /// and the training error start from F0. Throws Error when the count differs from the samples'.
  void start_from_scores(const std::vector<double>& scores);

  /// Adds one weak classifier and returns what was chosen.
  RealAdaBoostRound next_round();

  const std::vector<WeakClassifier>& weak_classifiers() const { return weak_; }
  /// Current strong-classifier score of every training sample.
  const std::vector<double>& train_scores() const { return scores_; }

 private:
  std::vector<std::size_t> trimmed_samples() const;
  struct TableFit {
    std::size_t feature = 0;
    double z = 0.0;
    std::vector<double> responses;
  };
  /// For every node (its samples ascending; all samples when the only entry is null) the table with the
  /// smallest Z over its samples, responses unshrunk; with `split`, the best two-way split instead, as a
  /// routing table of -1 (left) / +1 (right). All the nodes share each pass over the bins.
  /// Histogram subtraction: node j of best_tables with sibling[j] >= 0 takes, per feature, the sums of
  /// node parent[j] of the previous level (parent_sums, [node][feature][2 * bins]) minus those of node
  /// sibling[j] of this call.
  struct Subtraction {
    const std::vector<double>* parent_sums = nullptr;
    std::vector<std::ptrdiff_t> parent, sibling;
  };
  /// `keep`, when given, receives every node's sums of every feature ([node][feature][2 * bins]).
  std::vector<TableFit> best_tables(const std::vector<const std::vector<std::size_t>*>& members,
                                    const std::vector<std::uint8_t>& y, bool split,
                                    const Subtraction* derived = nullptr, std::vector<double>* keep = nullptr) const;
  /// One call of best_tables over the features of one chunk, [f0, f1): each feature's sums (two-part,
  /// four-part per node, or parent - sibling), kept when `keep` is given; the smallest Z per node and its
  /// feature (the lowest of equals) go to best_z / best_f.
  struct TableScan {
    const RealAdaBoost& booster;
    const std::vector<std::uint8_t>& y;
    bool split;
    const Subtraction* derived;
    std::vector<double>* keep;
    const NodeSamples& samples;
    const std::vector<std::size_t>& direct_of;  ///< per node: its index among the direct ones
    std::size_t direct;                         ///< nodes whose sums are taken directly
    bool two_part;
    int pass;                                   ///< features per pass over the samples
    void features(std::size_t f0, std::size_t f1, double* best_z, std::size_t* best_f) const;
  };
  /// Z of a table (or split) from its sums[2 * bin + y].
  double table_z(const double* sums, bool split) const;
  /// The table (or split) of `feature` from its sums[2 * bin + y], with the given Z.
  TableFit fit_sums(std::size_t feature, double z, const double* sums, bool split) const;
  /// Data-parallel best_tables: every node's sums of every feature on this rank; each rank sums every
  /// rank's sums of its block of features (RowShards::sum_own_block) and finds the block's best; the best
  /// of the blocks per node (lowest feature of equals) and its summed sums are exchanged.
  std::vector<TableFit> best_tables_sharded(const std::vector<const std::vector<std::size_t>*>& members,
                                            const std::vector<std::uint8_t>& y, bool split) const;
  bool sharded() const { return params_.shards != nullptr && params_.shards->distributed(); }
  /// `feature`'s table (or split) over `subset` (all samples when null), with the given Z.
  TableFit fit_feature(std::size_t feature, double z, const std::vector<std::size_t>* subset,
                       const std::vector<std::uint8_t>& y, bool split) const;

  // The steps of a round: the weak classifier (a table at depth 1, else a tree grown level by level) with
  // its shrunk response per sample and Z; then the reweighting, which returns the samples the strong
  // classifier now gets wrong (over every rank).
  double fit_table(const std::vector<std::size_t>& trimmed, const std::vector<std::uint8_t>& y, WeakClassifier& weak,
                   std::vector<double>& response) const;
  double fit_tree(const std::vector<std::size_t>& trimmed, const std::vector<std::uint8_t>& y, WeakClassifier& weak,
                  std::vector<double>& response) const;
  /// What histogram subtraction carries from one level of a tree to the next: the sums of the previous
  /// level's fitted nodes ([node][feature][2 * bins]), this level's, and each node's index among them (-1:
  /// not kept).
  struct LevelSums {
    std::vector<double> parent_sums, level_sums;
    std::vector<std::ptrdiff_t> parent_index;
  };
  /// Fits the nodes k0 .. 2 k0 of a tree and routes the samples of inner nodes one level down (node_of);
  /// returns the Z of its leaves (0 for an inner level).
  double fit_tree_level(std::size_t k0, const std::vector<std::size_t>& trimmed, const std::vector<std::uint8_t>& y,
                        std::vector<std::size_t>& node_of, LevelSums& sums, WeakClassifier& weak) const;
  double reweight(const std::vector<double>& response);

  const BinnedMatrix& data_;
  std::vector<int> labels_;
  RealAdaBoostParams params_;
  double eps_ = 0.0;
  bool positives_first_ = false;  ///< labels are 1...1 0...0: the two-part histograms apply
  std::size_t positives_ = 0;
  std::size_t total_samples_ = 0;  ///< over every rank (data().samples() with one process)
  int threads_ = 1;
  std::vector<double> weights_;
  std::vector<double> scores_;
  std::vector<WeakClassifier> weak_;
};

}  // namespace rdsf
