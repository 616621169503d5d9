#pragma once
// Writes a synthetic recording in the frame-source layout (readable by open_frame_source):
//   DIR/NNNNNN.depth.png  16-bit depth in millimetres (0 = no reading)
//   DIR/NNNNNN.rgb.png    registered colour (with rgb)
//   DIR/boxes.csv         frame,person,x,y,w,h,visible_fraction,track - one row per visible person
//   DIR/clips.csv         one row per clip (ClipDescription): room kind and size, the camera's height, pitch
//                         and roll at the clip's first frame and whether it drives, the sensor profile's noise
//                         factor and 8-bit step, people and furniture; to read detection figures by condition
//                         (rdsf-detect's clips.csv has the same clips, named "#clip" with --clip-frames)
//   DIR/synth.yml         how the set was made: seed, options, camera, sensor model
//   DIR/camera.yml        the camera model (rdsf/frame/camera_file.hpp), only with a field of view (--fov);
//                         without it readers scale the Kinect v1's model to the size, as the renderer does
// Every file is written under a temporary name and renamed into place; boxes.csv, clips.csv and synth.yml
// appear only when the whole set is written. A folder that already holds frames is refused unless `force`.
#include <memory>
#include <string>

#include "rdsf/core/atomic_file.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace rdsf::synth {

/// Checks that `dir` can take a new set: creates it when missing; throws Error when it already holds
/// frames, boxes.csv or synth.yml and `force` is false. With `force`, removes the files of an earlier set
/// (NNNNNN.depth.png, NNNNNN.rgb.png, boxes.csv, synth.yml, camera.yml) and throws when other depth images remain.
void prepare_output_folder(const std::string& dir, bool force);

class SynthWriter {
 public:
  /// Call prepare_output_folder first.
  SynthWriter(std::string dir, const SynthParams& params, bool force);
  void write(const SynthFrame& frame);
  /// One row of clips.csv; call once per clip, in order.
  void add_clip(const ClipDescription& clip);
  /// Writes camera.yml (with a field of view) and synth.yml and puts boxes.csv in place.
  void commit(const std::string& command_line);

  /// The text of synth.yml for `params`.
  static std::string describe(const SynthParams& params, const std::string& command_line);

 private:
  std::string dir_;
  SynthParams params_;
  bool force_;
  std::unique_ptr<AtomicTextFile> boxes_;
  std::unique_ptr<AtomicTextFile> clips_;
};

}  // namespace rdsf::synth
