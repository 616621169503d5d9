#include "rdsf/classifier/bin_scheme.hpp"

#include <string>

#include "rdsf/core/error.hpp"

namespace rdsf {

void BinScheme::validate() const {
  if (count < 2 || count > 256) {
    throw Error("bin scheme: " + std::to_string(count) + " bins given (2 to 256 are possible)");
  }
  if (!(max_value > min_value)) throw Error("bin scheme: the value range is empty (max must exceed min)");
}

}  // namespace rdsf
