#pragma once
// The upright objects of one depth layer, from its column runs: the thesis's objects (passing columns
// joined across small gaps; with height_at_column_depth a column's height is measured at its own depth
// when it fails at the layer's mean), then the departures that make every person an object of their own with a box
// that fits (each one a parameter of CandidateParams that can be turned off):
//   1. fitted extent: an object reaches out over the columns attached to it (the layer's pixels beside it,
//      within its rows, such as arms, which are too short to pass threshold_height) - fit.reach_cm - also
//      across something nearer standing before them (an arm behind a nearer person) - fit.occlusion_gap_cm;
//   2. joining pieces: objects whose fitted extents touch and that together are no wider than a person
//      are one object (a person whose torso columns fail the height test because the legs part) -
//      join_pieces (pieces each narrower than min_width_cm: in layers nearer than
//      join.narrow_layers_below_mm, and with join.narrow_passing when their passing columns alone are
//      together at least narrow.passing_width_cm);
//   3. splitting: an object of any width with two heads on top of its profile (the highest pixel per
//      column) is cut between them at the lowest point (people overlapping in the image at one depth:
//      split_head.drop_cm; the whole stays one too, split_head.keep_whole; each piece's fitted extent
//      reaches across the cut to the other's passing columns, fit.across_head_cut); else an object wider than a
//      person is cut where the layer's depth jumps between neighbouring columns (split.depth_jump_mm), at
//      deep valleys of its column-height profile (split.valley_cm) or at steps (split.step_cm); the pieces
//      become objects, and the whole stays one too when split.keep_whole is set;
//   4. narrow people: an object narrower than min_width_cm over its passing columns stays one when its
//      fitted extent is at least narrow.fitted_width_cm wide, its passing columns at least
//      narrow.passing_width_cm, its layer nearer than narrow.layers_below_mm, its height (fitted top to
//      lowest row) at least narrow.min_height_cm, and at least half of the narrow.clear_above_cm band above
//      its top over its passing columns holds other layers' readings (no missing readings, no border: the
//      background above a head) - narrow.fitted_width_cm.
// Objects wider than max_object_width_cm (walls) and, unless they touch the left or right border, objects
// whose fitted extent is narrower than min_fitted_width_cm (posts, furniture legs) are dropped.
// Each step is a unit of its own, applied in this order: the thesis's objects (object_join.hpp), 1
// (object_fit.hpp), 2 (object_join.hpp), 4 and the drops (object_keep.hpp, narrow_person.hpp), 3
// (object_split.hpp).
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate_params.hpp"
#include "rdsf/candidates/column_heights.hpp"
#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

struct LayerObject {
  int first = 0, last = 0;          ///< first and last passing column
  int fit_first = 0, fit_last = 0;  ///< the fitted extent: first..last plus attached columns
  int top = 0, bottom = 0;          ///< highest and lowest row of the passing columns' runs
  int fit_top = 0;                  ///< the fitted extent's highest row (<= top)
  int tallest = 0;                  ///< longest passing run (rows)
  int highest = 0;                  ///< column of the highest point (middle of those reaching `top`)
  bool part = false;                ///< a piece cut out of a wider object (step 3)
  int object = 0;                   ///< the object it is or was cut from (0, 1, ... in the layer, left to right)
};

/// Everything find_candidates() needs of one layer to find its objects.
struct LayerView {
  const std::vector<ColumnRun>* runs = nullptr;  ///< the layer's longest run per column
  const cv::Mat1b* labels = nullptr;             ///< Segmentation::labels
  const cv::Mat1w* depth_mm = nullptr;
  int label = 0;
  double depth_mm_mean = 0;                      ///< the layer's mean depth
  double depth_mm_max = 0;                       ///< the farthest depth in the layer
  const CameraModel* camera = nullptr;
};

struct LayerObjects {
  /// Left to right (a split object's pieces follow it), each at least min_width_cm wide over its passing
  /// columns.
  std::vector<LayerObject> objects;
  std::vector<char> passing;  ///< per column: its run passes threshold_height
};

/// The objects of one layer.
LayerObjects layer_objects(const LayerView& layer, const CandidateParams& params);

}  // namespace rdsf
