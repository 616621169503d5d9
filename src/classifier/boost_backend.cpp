#include "rdsf/classifier/boost_backend.hpp"

namespace rdsf {

BoostBackend::BoostBackend(const std::string& name) {
  if (name == "native") {
    kind_ = native;
  } else if (name == "opencv") {
    kind_ = opencv;
  } else {
    kind_ = unknown;
    unknown_name_ = name;
  }
}

std::string BoostBackend::name() const {
  switch (kind_) {
    case native: return "native";
    case opencv: return "opencv";
    case unknown: break;
  }
  return unknown_name_;
}

}  // namespace rdsf
