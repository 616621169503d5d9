#pragma once
// Validation groups of samples: consecutive frames of a recording give near-identical crops, so a split
// by sample puts copies of the same person on both sides and validation figures come out far better than
// on new recordings. A frame's block is number / group_frames when its name is a number (recordings and
// synthetic sets name frames by index), else its rank among the recording's frame names that occur among
// the samples, in name order, / group_frames. The recording is the last component of a sample's source
// path (so the same folder named relatively or absolutely is one recording). Groups by GroupBy:
//   recording_block  "recording#block" (default): frames of one recording, in blocks;
//   block            "#block": the same block of every recording together, for recordings made of the same
//                    scenes in step (the main job's people and people-free renderings of the same rooms:
//                    frame i of both shows room i / clip_frames, so a room is never on both sides);
//   recording        "recording": whole recordings (many recordings, one scene each).
// Every sample of one frame, of either label, lands in the same group.
#include <cstddef>
#include <string>
#include <vector>

namespace rdsf {

struct SampleOrigin {
  std::string source;  ///< the recording or folder the frame came from
  std::string frame;   ///< the frame's name
};

struct SampleGroups {
  std::vector<std::size_t> group;  ///< per sample: index into names
  std::vector<std::string> names;  ///< sorted, "recording#block"
};

enum class GroupBy { recording_block, block, recording };

/// "recording-block", "block" or "recording"; throws Error naming the known ones otherwise.
GroupBy parse_group_by(const std::string& text);

/// The recording a source path names (its last path component).
std::string recording_of(const std::string& source);

/// Groups of `origins` (throws Error when group_frames < 1).
SampleGroups sample_groups(const std::vector<SampleOrigin>& origins, int group_frames,
                           GroupBy by = GroupBy::recording_block);

}  // namespace rdsf
