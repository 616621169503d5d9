#include "rdsf/frame/frame_source.hpp"

#include "rdsf/core/error.hpp"
#include "rdsf/frame/png_folder_source.hpp"
#include "rdsf/version.hpp"
#if RDSF_WITH_OPENNI
#include "rdsf/frame/openni_source.hpp"
#endif

namespace rdsf {

bool is_openni_spec(const std::string& spec) {
  const bool oni_file = spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".oni") == 0;
  return oni_file || spec == "openni" || spec.find("://") != std::string::npos;
}

std::unique_ptr<FrameSource> open_frame_source(const std::string& spec, const CameraModel& camera) {
  if (is_openni_spec(spec)) {
#if RDSF_WITH_OPENNI
    return std::make_unique<OpenNISource>(spec, camera);
#else
    fail(spec, "this build has no OpenNI2 (reconfigure with -DRDSF_WITH_OPENNI=ON, libopenni2-dev installed)");
#endif
  }
  return std::make_unique<PngFolderSource>(spec, camera);
}

}  // namespace rdsf
