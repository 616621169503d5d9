#include "rdsf/frame/frame_source.hpp"

#include "rdsf/core/error.hpp"
#include "rdsf/frame/png_folder_source.hpp"
#include "rdsf/version.hpp"
#if RDSF_WITH_OPENNI
#include "rdsf/frame/openni_source.hpp"
#endif
#if RDSF_WITH_ROSBAG
#include "rdsf/frame/bag_source.hpp"
#endif

namespace rdsf {

bool is_openni_spec(const std::string& spec) {
  const bool oni_file = spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".oni") == 0;
  return oni_file || spec == "openni" || spec.find("://") != std::string::npos;
}

bool FrameSource::next_deferred(FrameDecode& decode) {
  auto frame = std::make_shared<DepthFrame>();
  if (!next(*frame)) return false;
  decode = [frame] { return std::move(*frame); };
  return true;
}

std::vector<std::string> index_frame_names(std::int64_t count) {
  std::vector<std::string> names;
  for (std::int64_t i = 0; i < count; ++i) names.push_back(std::to_string(i));
  return names;
}

bool is_bag_spec(const std::string& spec) {
  return spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".bag") == 0;
}

std::unique_ptr<FrameSource> open_frame_source(const std::string& spec, const CameraModel& camera) {
  FrameSourceOptions options;
  options.camera = camera;
  return open_frame_source(spec, options);
}

std::unique_ptr<FrameSource> open_frame_source(const std::string& spec, const FrameSourceOptions& options) {
  if (is_openni_spec(spec)) {
#if RDSF_WITH_OPENNI
    return std::make_unique<OpenNISource>(spec, options);
#else
    fail(spec, "this build has no OpenNI2 (reconfigure with -DRDSF_WITH_OPENNI=ON, libopenni2-dev installed)");
#endif
  }
  if (is_bag_spec(spec)) {
#if RDSF_WITH_ROSBAG
    return std::make_unique<BagSource>(spec, options);
#else
    fail(spec, "this build has no ROS 1 bag reading (reconfigure with -DRDSF_WITH_ROSBAG=ON, librosbag-dev installed)");
#endif
  }
  return std::make_unique<PngFolderSource>(spec, options);
}

}  // namespace rdsf
