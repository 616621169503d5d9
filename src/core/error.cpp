#include "rdsf/core/error.hpp"

namespace rdsf {

void fail(const std::string& where, const std::string& what) { throw Error(where + ": " + what); }

}  // namespace rdsf
