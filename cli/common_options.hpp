#pragma once
// The options several programs share, each declared once here: --models-dir, --model and --threads. A
// program names what the option does for it (the role); the option's name, value, default, check and the
// rest of its help are the same everywhere.
//   --models-dir DIR  "where model NAMEs are looked up[ and saved]" (+ the program's addition);
//   --model M         "<role>: a model file, NAME (its newest version) or NAME/vN"; a default is shown only
//                     when there is one;
//   --threads N       "<role> (0: one per core)[; <note>]"; N < 0 is a UsageError
//                     ("--threads must be 0 (one per core) or more, got N").
//   --per-place on|off one answer per place for n answers (rdsf-label --per-track, rdsf-adapt); the default
//                     is the library's (PropagationParams::per_place).
//   --propagate-model-answers on|off  the model's sure answers followed along their tracks too (rdsf-label
//                     --per-track, rdsf-adapt); the default is the library's (PropagationParams::from_model).
//   --min-visible F, --clip-frames N  the evaluation against boxes.csv (rdsf-detect, rdsf-pcl-people):
//                     don't-care people, and the clips of the intervals over clips (clip_bootstrap.hpp).
#include <string>

#include <boost/program_options.hpp>

namespace rdsf::cli {

/// Whether a program only reads models from --models-dir or also saves the ones it makes there.
enum class ModelsDirUse { look_up, look_up_and_save };

/// --models-dir DIR bound to `dir` (its value now is the default shown).
void add_models_dir_option(boost::program_options::options_description& group, std::string& dir,
                           ModelsDirUse use = ModelsDirUse::look_up, const std::string& addition = "");

/// --model M bound to `model`: `role` says what the program does with it.
void add_model_option(boost::program_options::options_description& group, std::string& model, const std::string& role);

/// --threads N bound to `threads`: `role` says what the threads do; `note` (optional) follows the default's
/// meaning, e.g. that results do not depend on the count.
void add_threads_option(boost::program_options::options_description& group, int& threads, const std::string& role,
                        const std::string& note = "");

/// --per-place on|off bound to `per_place` (its value now is the default shown).
void add_per_place_option(boost::program_options::options_description& group, bool& per_place);
/// --propagate-model-answers on|off bound to `from_model` (PropagationParams::from_model).
void add_propagate_model_option(boost::program_options::options_description& group, bool& from_model);

/// --min-visible F and --clip-frames N bound to `min_visible` and `clip_frames` (their values now are the
/// defaults shown); F outside [0, 1] or N < 1 is a UsageError.
void add_evaluation_options(boost::program_options::options_description& group, double& min_visible, int& clip_frames);

}  // namespace rdsf::cli
