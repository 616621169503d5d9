#include "adapt/adapt_chart.hpp"

#include "rdsf/evaluation/adaptation_results.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace rdsf {

void write_adaptation_chart(const std::string& results_tsv, const std::string& png) {
  write_png_atomically(png, draw_adaptation_chart(read_adaptation_results(results_tsv)));
}

}  // namespace rdsf
