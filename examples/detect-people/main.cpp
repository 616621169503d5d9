// detect-people: runs the rdsf people detector on a folder of depth frames (NAME.depth.png, 16-bit,
// millimetres; NAME.rgb.png beside them for tracking by colour) and prints one line per detection:
//   frame name, person id, box x y w h (pixels), P(person)
// Usage: detect-people FRAMES MODEL.yml   (e.g. <prefix>/share/rdsf/models/people/v1.yml)
#include <cstdio>
#include <exception>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"
#include "rdsf/version.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: detect-people FRAMES MODEL.yml\n");
    return 2;
  }
  try {
    const rdsf::BoostedModel model = rdsf::BoostedModel::load(argv[2]);
    rdsf::PipelineParams params;
    params.detector.features = model.feature_spec();  // the detector computes the features the model reads
    rdsf::PeoplePipeline pipeline(params, &model);

    const auto frames = rdsf::open_frame_source(argv[1]);
    std::printf("# rdsf %s, %s\n# frame person x y w h p_person\n", rdsf::version().c_str(),
                frames->description().c_str());
    rdsf::DepthFrame frame;
    while (frames->next(frame)) {
      const rdsf::PipelineFrame result = pipeline.process(frame);
      for (std::size_t i = 0; i < result.person.size(); ++i) {
        if (result.person[i] == 0) continue;  // a candidate, not a detection
        const cv::Rect& box = rdsf::reported_box(result.analysis.candidates[i], params.detector.reported_box);
        std::printf("%s %d %d %d %d %d %.3f\n", frame.name.c_str(), result.person[i], box.x,
                    box.y, box.width, box.height, result.probabilities[i]);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "detect-people: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
