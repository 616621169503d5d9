#include "rdsf/core/shipped_data.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

namespace rdsf {
namespace fs = std::filesystem;
namespace {

// The file of the shared library or program this code was loaded from; empty when unknown.
fs::path binary_holding_this_code() {
  std::error_code ec;
#ifdef RDSF_LIBRARY_IS_SHARED
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&shipped_data_models_dir), &info) != 0 && info.dli_fname != nullptr) {
    return fs::weakly_canonical(fs::absolute(info.dli_fname, ec), ec);
  }
  return {};
#else
  return fs::weakly_canonical(fs::read_symlink("/proc/self/exe", ec), ec);
#endif
}

bool is_inside(const fs::path& file, const fs::path& folder) {
  const fs::path relative = file.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

std::string shipped_data_models_dir() {
  std::error_code ec;
  const fs::path binary = binary_holding_this_code();
  if (!binary.empty()) {
    const fs::path installed = (binary.parent_path() / RDSF_MODELS_FROM_BINARY).lexically_normal();
    if (fs::is_directory(installed, ec)) return installed.string();
    const bool build_tree = is_inside(binary, fs::weakly_canonical(RDSF_BUILD_TREE, ec)) ||
                            is_inside(binary, fs::weakly_canonical(RDSF_PROJECT_BUILD_TREE, ec));
    if (build_tree && fs::is_directory(RDSF_SOURCE_MODELS_DIR, ec)) return RDSF_SOURCE_MODELS_DIR;
  }
  if (fs::is_directory(RDSF_INSTALLED_MODELS_DIR, ec)) return RDSF_INSTALLED_MODELS_DIR;
  return "";
}

}  // namespace rdsf
