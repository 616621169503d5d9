#include "rdsf/dataset/sample_source.hpp"

#include <filesystem>

namespace rdsf {

std::string sample_source(const std::string& spec) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (spec.empty() || !fs::exists(spec, ec)) return spec;  // a device, or nothing to name
  fs::path path = fs::weakly_canonical(fs::absolute(spec, ec), ec);
  if (ec) path = fs::absolute(spec, ec).lexically_normal();
  std::string name = path.string();
  while (name.size() > 1 && name.back() == '/') name.pop_back();
  return name;
}

}  // namespace rdsf
