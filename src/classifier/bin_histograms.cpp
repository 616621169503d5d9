#include "rdsf/classifier/bin_histograms.hpp"

#include <algorithm>
#include <cstring>

namespace rdsf {
namespace {

std::uint64_t load8(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Tables part[y][parity][feature][bin] of kStride >= bin_count entries (class-major, so an update is
// table + bin * 8): two parities break the chains of consecutive samples in the same bin (RDSF values
// crowd at 1), NF features share each weight load, and each feature's bins are read eight at a time and
// shifted out of a register.
template <int NF, int kStride>
void two_part(const std::uint8_t* const* bins, const double* w, std::size_t positives, std::size_t n, int bin_count,
              double* const* sums) {
  alignas(64) double part[2][2][NF][kStride];
  std::memset(part, 0, sizeof part);
  for (int y = 1; y >= 0; --y) {
    const std::size_t begin = y == 1 ? 0 : positives, end = y == 1 ? positives : n;
    double(*even)[kStride] = part[y][0];
    double(*odd)[kStride] = part[y][1];
    std::size_t i = begin;
    for (; i + 8 <= end; i += 8) {
      std::uint64_t v[NF];
      for (int f = 0; f < NF; ++f) v[f] = load8(bins[f] + i);
#pragma GCC unroll 8
      for (int k = 0; k < 8; k += 2) {
        const double wa = w[i + k], wb = w[i + k + 1];
#pragma GCC unroll 8
        for (int f = 0; f < NF; ++f) {
          even[f][v[f] & 0xff] += wa;
          odd[f][(v[f] >> 8) & 0xff] += wb;
          v[f] >>= 16;
        }
      }
    }
    for (; i < end; ++i) {
      double(*p)[kStride] = ((i - begin) & 1) == 0 ? even : odd;
      for (int f = 0; f < NF; ++f) p[f][bins[f][i]] += w[i];
    }
  }
  for (int f = 0; f < NF; ++f) {
    for (int j = 0; j < bin_count; ++j) {
      sums[f][2 * j] = part[0][0][f][j] + part[0][1][f][j];
      sums[f][2 * j + 1] = part[1][0][f][j] + part[1][1][f][j];
    }
  }
}

template <int NF>
void two_part_any(const std::uint8_t* const* bins, const double* w, std::size_t positives, std::size_t n,
                  int bin_count, double* const* sums) {
  if (bin_count <= 64) return two_part<NF, 64>(bins, w, positives, n, bin_count, sums);
  two_part<NF, kMaxHistogramBins>(bins, w, positives, n, bin_count, sums);
}

// Tables [node][part][y][feature][bin]: NodeSamples::table() gives each sample's (node, part, y), shared by
// the NF features of the pass.
template <int NF, int kStride>
void four_part(const std::uint8_t* const* bins, const NodeSamples& nodes, int bin_count, double* const* sums) {
  constexpr std::size_t width = kStride;     // >= bin_count
  constexpr std::size_t stride = NF * width;  // one (node, part, y) table of all NF features
  thread_local std::vector<double> scratch;
  scratch.assign(nodes.nodes() * 8 * stride, 0.0);
  double* const t = scratch.data();
  const std::uint32_t* const table = nodes.table().data();
  const double* const w = nodes.weights().data();
  const std::size_t m = nodes.samples().size();
  if (nodes.dense()) {
    std::size_t i = 0;
    for (; i + 8 <= m; i += 8) {
      std::uint64_t v[NF];
      for (int f = 0; f < NF; ++f) v[f] = load8(bins[f] + i);
#pragma GCC unroll 8
      for (int k = 0; k < 8; ++k) {
        double* const p = t + table[i + k] * stride;
        const double wk = w[i + k];
        for (int f = 0; f < NF; ++f) {
          p[f * width + (v[f] & 0xff)] += wk;
          v[f] >>= 8;
        }
      }
    }
    for (; i < m; ++i) {
      double* const p = t + table[i] * stride;
      for (int f = 0; f < NF; ++f) p[f * width + bins[f][i]] += w[i];
    }
  } else {
    const std::uint32_t* const samples = nodes.samples().data();
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t i = samples[k];
      double* const p = t + table[k] * stride;
      for (int f = 0; f < NF; ++f) p[f * width + bins[f][i]] += w[k];
    }
  }
  for (std::size_t node = 0; node < nodes.nodes(); ++node) {
    for (int f = 0; f < NF; ++f) {
      double* const out = sums[static_cast<std::size_t>(f) * nodes.nodes() + node];
      for (int y = 0; y < 2; ++y) {
        const double* const p0 = t + ((node * 4 + 0) * 2 + y) * stride + f * width;
        const double* const p1 = p0 + 2 * stride;
        const double* const p2 = p0 + 4 * stride;
        const double* const p3 = p0 + 6 * stride;
        for (int j = 0; j < bin_count; ++j) out[2 * j + y] = (p0[j] + p1[j]) + (p2[j] + p3[j]);
      }
    }
  }
}

template <int NF>
void four_part_any(const std::uint8_t* const* bins, const NodeSamples& nodes, int bin_count, double* const* sums) {
  if (bin_count <= 64) return four_part<NF, 64>(bins, nodes, bin_count, sums);
  four_part<NF, kMaxHistogramBins>(bins, nodes, bin_count, sums);
}

}  // namespace

void two_part_histograms(const std::uint8_t* const* bins, int count, const double* w, std::size_t positives,
                         std::size_t n, int bin_count, double* const* sums) {
  switch (count) {
    case 8: return two_part_any<8>(bins, w, positives, n, bin_count, sums);
    case 4: return two_part_any<4>(bins, w, positives, n, bin_count, sums);
    default:
      for (int f = 0; f < count; ++f) two_part_any<1>(bins + f, w, positives, n, bin_count, sums + f);
  }
}

NodeSamples::NodeSamples(const std::vector<const std::vector<std::size_t>*>& members,
                         const std::vector<std::uint8_t>& y, std::size_t n)
    : nodes_(members.size()) {
  // node and part of every sample (UINT32_MAX: in no node), then the samples of some node in order.
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> code(n, kNone);
  std::size_t total = 0;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const std::vector<std::size_t>& list = *members[k];
    const std::size_t whole = list.size() / 4 * 4;
    for (std::size_t r = 0; r < list.size(); ++r) {
      const std::size_t part = r < whole ? r % 4 : 0;
      code[list[r]] = static_cast<std::uint32_t>((k * 4 + part) * 2);
    }
    total += list.size();
  }
  dense_ = total == n;
  samples_.reserve(total);
  table_.reserve(total);
  for (std::size_t i = 0; i < n; ++i) {
    if (code[i] == kNone) continue;
    samples_.push_back(static_cast<std::uint32_t>(i));
    table_.push_back(code[i] + y[i]);
  }
}

void NodeSamples::gather_weights(const std::vector<double>& w) {
  weights_.resize(samples_.size());
  for (std::size_t k = 0; k < samples_.size(); ++k) weights_[k] = w[samples_[k]];
}

void node_histograms(const std::uint8_t* const* bins, int count, const NodeSamples& nodes, int bin_count,
                     double* const* sums) {
  switch (count) {
    case 4: return four_part_any<4>(bins, nodes, bin_count, sums);
    case 2: return four_part_any<2>(bins, nodes, bin_count, sums);
    default:
      for (int f = 0; f < count; ++f) {
        four_part_any<1>(bins + f, nodes, bin_count, sums + static_cast<std::size_t>(f) * nodes.nodes());
      }
  }
}

}  // namespace rdsf
