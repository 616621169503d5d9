// detect-people: runs the rdsf people detector (rdsf::PeopleDetector) on a folder of depth frames
// (NAME.depth.png, 16-bit, millimetres; NAME.rgb.png beside them for tracking by colour) and prints one
// line per detection:
//   frame name, track id, box x y w h (pixels), P(person), position x y z in the camera frame (metres)
// Usage: detect-people FRAMES MODEL.yml   (e.g. <prefix>/share/rdsf/models/people/v1.yml)
#include <cstdio>
#include <exception>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/people_detector.hpp"
#include "rdsf/version.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: detect-people FRAMES MODEL.yml\n");
    return 2;
  }
  try {
    rdsf::BoostedModel model = rdsf::BoostedModel::load(argv[2]);
    const rdsf::PipelineParams params = rdsf::PeopleDetector::params_for(model);  // the model's feature spec
    rdsf::PeopleDetector detector(std::move(model), params);

    const auto frames = rdsf::open_frame_source(argv[1]);
    std::printf("# rdsf %s, %s\n# frame track x y w h p_person x_m y_m z_m\n", rdsf::version().c_str(),
                frames->description().c_str());
    rdsf::DepthFrame frame;
    while (frames->next(frame)) {
      for (const rdsf::Detection& d : detector.detect(frame)) {
        std::printf("%s %d %d %d %d %d %.3f %.2f %.2f %.2f\n", frame.name.c_str(), d.track_id, d.box.x, d.box.y,
                    d.box.width, d.box.height, d.probability, d.position_m.x, d.position_m.y, d.position_m.z);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "detect-people: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
