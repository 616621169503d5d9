#include "rdsf/classifier/binned_matrix.hpp"

#include <string>

#include "rdsf/classifier/parallel_chunks.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

BinnedMatrix::BinnedMatrix(const cv::Mat1f& rows, const BinScheme& scheme,
                           const std::vector<std::size_t>& row_order, int threads)
    : samples_(row_order.empty() ? static_cast<std::size_t>(rows.rows) : row_order.size()),
      features_(static_cast<std::size_t>(rows.cols)),
      scheme_(scheme) {
  scheme_.validate();
  for (std::size_t r : row_order) {
    if (r >= static_cast<std::size_t>(rows.rows)) {
      throw Error("binned matrix: row " + std::to_string(r) + " asked of a matrix with " +
                  std::to_string(rows.rows) + " rows");
    }
  }
  bins_.assign(samples_ * features_, 0);
  constexpr std::size_t kBlock = 16;  // rows read together: keeps the feature-major writes in cache lines
  const std::size_t blocks = (samples_ + kBlock - 1) / kBlock;
  parallel_chunks(blocks, resolve_thread_count(threads), [&](std::size_t b0, std::size_t b1) {
    const float* row_ptr[kBlock];
    for (std::size_t b = b0; b < b1; ++b) {
      const std::size_t s0 = b * kBlock, n = std::min(kBlock, samples_ - s0);
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t r = row_order.empty() ? s0 + k : row_order[s0 + k];
        row_ptr[k] = rows[static_cast<int>(r)];
      }
      for (std::size_t f = 0; f < features_; ++f) {
        std::uint8_t* out = bins_.data() + f * samples_ + s0;
        for (std::size_t k = 0; k < n; ++k) out[k] = static_cast<std::uint8_t>(scheme_.bin_of(row_ptr[k][f]));
      }
    }
  });
}

}  // namespace rdsf
