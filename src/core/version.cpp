#include "rdsf/version.hpp"

namespace rdsf {

std::string version() { return RDSF_VERSION_STRING; }

bool has_openni() { return RDSF_WITH_OPENNI != 0; }
bool has_rosbag() { return RDSF_WITH_ROSBAG != 0; }

}  // namespace rdsf
