// The table of TrainingDataParams (trainer/training_data_parameters.hpp): each row's option, help, check
// and thesis value. A word the library's parser refuses is refused here with the parser's own message, so
// the words are listed once, by parse_group_by and parse_augmentation.
#include "trainer/training_data_parameters.hpp"

#include "rdsf/core/error.hpp"
#include "rdsf/dataset/crop_augmentation.hpp"
#include "rdsf/dataset/sample_groups.hpp"

namespace rdsf {
namespace {

using P = TrainingDataParams;

// The check of a row whose text `parse` reads: its Error's message, or "" when it reads.
template <typename Parse>
std::function<std::string(const std::string&)> parsed_by(Parse parse) {
  return [parse](const std::string& text) -> std::string {
    try {
      parse(text);
      return "";
    } catch (const Error& e) {
      return e.what();
    }
  };
}

}  // namespace

const ParameterTable<TrainingDataParams>& training_data_parameters() {
  static const ParameterTable<P> table = {
      parameter("group-frames", &P::group_frames,
                "validation groups: a recording's frames in blocks of this many (consecutive frames never split); "
                "0 = split by sample (dishonest: near-identical crops on both sides; only for comparison)",
                Range::at_least(0)),
      parameter<P, std::string>("group-by", &P::group_by,
                                "validation groups: recording-block (a recording's frame blocks), block (frame blocks "
                                "of all recordings together: recordings of the same scenes in step) or recording "
                                "(whole recordings)",
                                {}, std::nullopt, parsed_by([](const std::string& by) { parse_group_by(by); })),
      parameter<P, std::string>("augment", &P::augment,
                                "positives augmented at training time: off, or a list of mirror, shift, scale, occlusion",
                                {}, std::optional<std::string>("off"),
                                parsed_by([](const std::string& a) { parse_augmentation(a, 0, 0); })),
      parameter("augment-copies", &P::augment_copies,
                "random variants per positive (shift / scale / occlusion), besides the mirror", Range::at_least(0)),
  };
  return table;
}

}  // namespace rdsf
