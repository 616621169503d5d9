#include "cli/common_options.hpp"

#include "cli/cli.hpp"

namespace rdsf::cli {

void add_models_dir_option(po::options_description& group, std::string& dir, ModelsDirUse use,
                           const std::string& addition) {
  std::string help = "where model NAMEs are looked up";
  if (use == ModelsDirUse::look_up_and_save) help += " and saved";
  if (!addition.empty()) help += addition;
  group.add_options()("models-dir", po::value(&dir)->default_value(dir), help.c_str());
}

void add_model_option(po::options_description& group, std::string& model, const std::string& role) {
  const std::string help = role + ": a model file, NAME (its newest version) or NAME/vN";
  if (model.empty()) {
    group.add_options()("model", po::value(&model), help.c_str());
  } else {
    group.add_options()("model", po::value(&model)->default_value(model), help.c_str());
  }
}

void add_threads_option(po::options_description& group, int& threads, const std::string& role, const std::string& note) {
  const std::string help = role + " (0: one per core)" + (note.empty() ? "" : "; " + note);
  group.add_options()("threads", po::value(&threads)->default_value(threads)->notifier([](int n) {
    if (n < 0) throw UsageError("--threads must be 0 (one per core) or more, got " + std::to_string(n));
  }), help.c_str());
}

void add_per_place_option(po::options_description& group, bool& per_place) {
  group.add_options()("per-place", po::value(&per_place)->default_value(per_place, per_place ? "on" : "off"),
                      "one answer per place, with one answer per track (on or off): an n also labels n the "
                      "candidates of other frames at the same place (strict box IoU >= 0.65, layer within "
                      "150 mm, the depth of the box's pixels unchanged: the camera did not move); undone with "
                      "the answer (docs/adapting-to-your-room.md)");
}

void add_propagate_model_option(po::options_description& group, bool& from_model) {
  group.add_options()("propagate-model-answers",
                      po::value(&from_model)->default_value(from_model, from_model ? "on" : "off"),
                      "with one answer per track (on or off): the model's sure answers (--accept, --reject) are "
                      "followed along their tracks too, as a person's are (the track only, not the place), "
                      "before the first question; u does not undo them");
}

void add_evaluation_options(po::options_description& group, double& min_visible, int& clip_frames) {
  group.add_options()
      ("min-visible", po::value(&min_visible)->default_value(min_visible)->notifier([](double f) {
        if (!(f >= 0.0 && f <= 1.0)) throw UsageError("--min-visible is a fraction in [0, 1], got " + std::to_string(f));
      }), "evaluation: people with visible_fraction below this are don't-care (no miss, no false positive)")
      ("clip-frames", po::value(&clip_frames)->default_value(clip_frames)->notifier([](int n) {
        if (n < 1) throw UsageError("--clip-frames must be 1 or more, got " + std::to_string(n));
      }), "evaluation: frames named by number form clips of this many (rdsf-synth's --clip-frames: a room each); "
          "other names by their stem (lab_juggling2: lab_juggling). TAR's 95 % intervals over clips, clips.csv");
}

}  // namespace rdsf::cli
