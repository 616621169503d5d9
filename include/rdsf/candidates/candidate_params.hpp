#pragma once
// Parameters of candidate shaping (thesis names where the thesis names them), with their defaults. Each
// member's option name, help, check and thesis value are declared once in candidate_parameters()
// (core/parameter_table.hpp). The departures of each object step have a struct of their own (fit, join,
// narrow, split, split_head), so that a step reads only its group; their keys and options keep the
// group's name as a prefix (fit.reach_cm: fit_reach_cm, --fit-reach).
#include "rdsf/core/parameter_table.hpp"

namespace rdsf {

enum class HeightMode {
  strict,   ///< threshold_height: near_height_cm for layers nearer than near_far_boundary_mm, else far_height_cm
  relaxed,  ///< threshold_height: near_height_cm everywhere
};

/// Step 1, the fitted extent, and the fitted box (object_fit.hpp, candidate_finder.cpp); keys fit_*.
struct FitParams {
  /// An object's fitted box reaches over the columns beside it that hold the layer's pixels within its
  /// rows (arms, hands: too short to pass threshold_height) up to this far each side (cm). 0: the fitted
  /// box spans the passing columns only.
  double reach_cm = 60.0;
  /// ... over columns whose mean depth (of the layer's pixels in the object's rows) differs from the last
  /// column taken by at most this (mm): an arm continues the body, a table beside it at another depth
  /// within the layer does not. 0: any depth within the layer.
  double depth_step_mm = 150.0;
  /// ... and across columns that do not continue it where something nearer stands in front of the band
  /// (pixels of nearer layers there, at least two and at least half as many as the column last taken has
  /// of the layer: a small thing low in the band is no occluder) for up to this far (cm) after the column
  /// last taken, besides the column_gap columns any gap may have: a farther person's arm or stride
  /// reaching out behind a nearer person. 0: only column_gap, the default: at 15 cm the quality report
  /// measured the 16 held-out rooms' candidate recall 0.829 -> 0.876 but detection figures no better there
  /// and the real frames' lower (lever models' TAR at FPPF <= 0.5 0.895 -> 0.854; docs/candidates.md).
  double occlusion_gap_cm = 0.0;
  /// Fitted box: at least this fraction of its height wide, widened about its centre (and clipped to the
  /// image) when narrower. A walking person swings the limbs out of the body's depth layer (the stride's
  /// trailing leg behind, the arm swung forward in front), so the layer's pixels alone can be half the
  /// person's width; nearly every person's tight box is wider than 0.3 of its height (the real frames'
  /// narrowest 3 of 49 are 0.21-0.25, which 0.3 still matches at IoU >= 0.7). Only reported boxes change:
  /// never crops, scores or labelling by overlap with true boxes (Candidate::extent_box). 0: the layer's
  /// extent alone (the sixth wave); 0.3 measured by the quality report (main job's sequence 222 -> 226 of
  /// 234 people with a candidate, 16 held-out rooms 583 -> 600 of 700, real frames 47 of 49 and every real
  /// detection figure the same; docs/candidates.md, "A person's width from their height").
  double min_width_ratio = 0.3;
  /// The pieces of an object cut between heads (HeadSplitParams) fit their boxes across the cut: each
  /// reaches over the attached columns around it up to the other piece's passing columns (the arm one
  /// person holds out across the other's side belongs to either), instead of stopping at the cut. Only
  /// reported boxes change, never crops or scores. false: each piece fits within its side of the cut (the
  /// fifth wave); on measured by the quality report (main job's sequence 219 -> 222 of 234 people with a
  /// candidate, 16 held-out rooms 580 -> 583 of 700, real frames and empty rooms unchanged;
  /// docs/candidates.md).
  bool across_head_cut = true;
};

/// Step 2, joining pieces (object_join.hpp); keys join_*.
struct JoinParams {
  /// Neighbouring objects of a layer whose fitted extents touch are one object when together no wider
  /// than max_person_width_cm (a person whose torso columns fail threshold_height because the legs part
  /// below). false: the thesis's objects.
  bool pieces = true;
  /// ... pieces that are each narrower than min_width_cm join only in layers nearer than this (mm).
  double narrow_layers_below_mm = 3500.0;
  /// ... and only when their passing columns alone (without the gaps between them) are together at least
  /// NarrowPersonParams::passing_width_cm wide (a person's two legs; not the thin slats of a chair's back:
  /// the real empty rooms' extra candidate). false: any (docs/candidates.md has both measured).
  bool narrow_passing = true;
};

/// Step 4, narrow people (narrow_person.hpp); keys narrow_*.
struct NarrowPersonParams {
  /// An object whose passing columns are narrower than min_width_cm is still a candidate when its fitted
  /// extent is at least this wide (cm) and it looks like a whole person: passing columns at least
  /// passing_width_cm wide, a layer nearer than layers_below_mm, a real height (fitted top to lowest row)
  /// of at least min_height_cm, and other layers' readings, not missing ones or the border, over at least
  /// half of a clear_above_cm band above its top (the background above a head). A person's legs or a leg
  /// behind a pole and holes can be all of its columns that pass threshold_height, narrower than
  /// min_width_cm, while the body above is a person's width. 0 turns it off (the thesis's min_width_cm
  /// alone): the default, because the quality report measured it helping the synthetic held-out rooms
  /// (16-room candidate recall 0.824 -> 0.881) and hurting the real frames (no real person gained, six
  /// narrow non-person candidates, candidate AUC 0.969 -> 0.960 over the lever models); 20 turns it on for
  /// scenes with poles and occluders (docs/candidates.md).
  double fitted_width_cm = 0.0;
  /// ... the narrowest its passing columns may be (cm).
  double passing_width_cm = 5.0;
  /// ... in layers nearer than this (mm): the Kinect's people range.
  double layers_below_mm = 5000.0;
  /// ... the shortest it may be (cm; the thesis's far threshold_height).
  double min_height_cm = 90.0;
  /// ... the band above its top that must show other layers (cm).
  double clear_above_cm = 10.0;
};

/// Step 3, an object wider than max_person_width_cm cut (object_cut.hpp); keys split_*.
struct WideSplitParams {
  /// Cut where the layer's median column depth jumps by more than this between neighbouring columns (mm;
  /// a person before a cupboard in the same layer). 0 turns it off.
  double depth_jump_mm = 0.0;
  /// ... else at a valley of its column-height profile this deep below the lower of the highest points on
  /// either side (cm; two people side by side). 0 turns it off.
  double valley_cm = 0.0;
  /// ... else where the mean height of a min_part_width_cm band on one side differs from the other side's
  /// by more than this (cm; a person beside a lower or taller piece of furniture). 0 turns it off.
  double step_cm = 0.0;
  /// A split object stays a candidate as a whole besides its pieces.
  bool keep_whole = false;
};

/// Step 3, an object cut between heads (object_heads.hpp); keys split_head_*.
struct HeadSplitParams {
  /// An object in a layer nearer than layers_below_mm with two or more heads on top of its profile is cut
  /// between neighbouring heads at the lowest point between them (people overlapping in the image at one
  /// depth, whatever their width together), each piece again while it has two. The profile: per column of
  /// the fitted extent, the height of its highest pixel of the layer at or below the fitted top. A head: a
  /// local maximum over half a head's width either side whose top (the columns within 5 cm of its height)
  /// is min_width_cm to width_cm wide (a raised hand's is narrower), at least 3/4 of the profile's maximum,
  /// with the profile dropping by at least this (cm) within width_cm beyond its top on both sides (the
  /// shoulders: inside the fitted extent, or beyond it where the extent ends at the image's left or right
  /// border); of two heads closer than min_part_width_cm the lower goes. 0 turns it off.
  double drop_cm = 15.0;
  /// ... the widest a head's top may be (cm).
  double width_cm = 30.0;
  /// ... the narrowest a head's top may be (cm).
  double min_width_cm = 12.0;
  /// ... in layers nearer than this (mm): farther, the tops of walls and shelves are ragged with missing
  /// readings and look like rows of heads.
  double layers_below_mm = 4000.0;
  /// ... the object cut between heads stays a candidate besides its pieces (overlapping people have
  /// overlapping boxes, and the whole is the nearer one's when an arm crosses the other). Off: the quality
  /// report measured it finding more people a candidate (main job's held-out sequence 224 instead of 219 of
  /// 234) but the whole and a piece both detected on one person (MOTA 0.73 -> 0.69 there, real frames'
  /// TAR at FPPF <= 0.1 0.70 -> 0.65 over the lever models; docs/candidates.md). Suppressing the
  /// duplicate (duplicate_candidates.hpp) lifts that MOTA to 0.72 but not the TARs: still off.
  bool keep_whole = false;
};

/// A column of a person the image cuts (layer_shape.hpp); keys border_*. A column whose run reaches the
/// image's top or bottom (within the first or last twentieth of its rows: sensors leave a band without
/// readings there) holds a person who goes on beyond the frame: a person within about 3 m of a camera at
/// chest height is cut at the feet, nearer ones at the head too, and what the image shows of them can be
/// shorter than threshold_height. Such a column passes at height_cm (at the layer's mean depth) instead,
/// when it is
///   at least min_rows_fraction of the image's rows long (a cut person fills much of the image; a low box
///   or a strip of wall at the border does not),
///   upright: the medians of the layer's readings in the first and last 8 rows of its run differ by at
///   most upright_mm (the floor along a column changes depth; a body does not).
/// (A third of the rows is about 90 cm at 3 m for any camera of the Kinect's vertical field of view, which
/// passes threshold_height anyway: the rule acts on near layers only.) Chosen on two tuning sets rendered
/// for it (close people, seed 73; ordinary rooms, seed 35), checked on two rendered after (seeds 74, 37)
/// and run once on the rest with people/v2: people 0.8-2.5 m away (seed 72) TAR at FPPF <= 0.1 0.617 ->
/// 0.734, every other set within a few people, the real frames the same. Off by default: weaker models
/// (people/v1, the quality report's small ones) score its new border objects high and lose real people
/// (people/v1 in the lab 21 -> 17 of 27; docs/candidates.md, "People the image cuts").
struct BorderCutParams {
  double height_cm = 0.0;  ///< 0: off (the default and the thesis); 25 turns it on
  double upright_mm = 400.0;
  double min_rows_fraction = 0.33;
};

struct CandidateParams {
  /// Gap tolerance (pixels) inside a column's run of occupied pixels.
  int k = 6;
  HeightMode mode = HeightMode::strict;
  /// threshold_height for near layers, and for every layer in relaxed mode (cm).
  double near_height_cm = 50.0;
  /// threshold_height for far layers in strict mode (cm).
  double far_height_cm = 90.0;
  /// Layers whose mean depth is below this are near (mm).
  double near_far_boundary_mm = 1500.0;
  /// Gap tolerance (columns) when joining passing columns into one object.
  int column_gap = 6;
  /// An object narrower than this in real centimetres is not a candidate.
  double min_width_cm = 10.0;
  /// A column's run goes on across things standing in front of the layer (pixels of nearer layers only)
  /// up to this real height (cm): a table before a person's legs does not cut the person in two. 0 turns
  /// it off (the thesis's behaviour).
  double occlusion_gap_cm = 60.0;
  /// A column's run goes on across gaps of missing readings only (no pixel of any layer: holes a sensor
  /// leaves on dark clothes, hair or noise) up to this real height (cm) at the layer's mean depth; gaps up
  /// to k rows are crossed anyway. 0 turns it off (the default and the thesis's behaviour).
  double hole_gap_cm = 0.0;
  /// Floor trimming: rows at the bottom of an object whose farthest layer pixel is nearer than the object's
  /// median depth by more than this (mm) are floor in front of the feet, not the object, and are cut off
  /// the box. 0 turns it off (the thesis's behaviour).
  double floor_tolerance_mm = 150.0;
  // --- Departures for recall and boxes that fit (include/rdsf/candidates/layer_objects.hpp; docs/candidates.md) ---
  /// A column whose run fails threshold_height at the layer's mean depth is measured again at the median
  /// depth of its own run (a layer spans up to candidate_threshold of depth, and a person at its far end
  /// looks shorter than they are). false: the layer's mean depth only (the thesis).
  bool height_at_column_depth = true;
  /// ... in layers nearer than this (mm) only: the Kinect's people range; far layers are walls, and their
  /// pieces would become candidates.
  double column_depth_layers_below_mm = 3500.0;
  FitParams fit;
  JoinParams join;
  NarrowPersonParams narrow;
  BorderCutParams border;
  /// An object whose fitted extent (arms included) is narrower than this (cm) is not a candidate: pieces
  /// of furniture, not people, whose narrowest (side-on) view is wider. Objects touching the left or right
  /// image border are exempt (a person cut by it looks narrow). 0 turns it off.
  double min_fitted_width_cm = 15.0;
  /// Objects wider than this over their passing columns (cm) are walls, not candidates. 0 turns it off.
  double max_object_width_cm = 400.0;
  /// Objects taller than this (cm) at their own depth (object_height.hpp) are not candidates; 0: off. Not a
  /// user's option here: PeoplePipeline sets it from PipelineParams::max_person_height_cm (rdsf-detect's
  /// --max-height, a decision of the detector), and mining and labelling leave it 0, so training sees every
  /// candidate (a model trained without the tall ones lost the UC3M home's people; docs/quality.md).
  double max_height_cm = 0.0;
  /// The widest a person is expected to be (cm, arms akimbo): wider objects are tried for splitting by
  /// depth jumps, valleys and steps (split), narrower pieces may be joined (join).
  double max_person_width_cm = 100.0;
  WideSplitParams split;
  HeadSplitParams split_head;
  /// The narrowest piece a split leaves (cm; split and split_head).
  double min_part_width_cm = 25.0;
  /// The window is the strict box enlarged by this factor in both directions (thesis: 25%).
  double window_scale = 1.25;
  /// threshold_height for a layer at the given depth.
  double threshold_height_cm(double layer_depth_mm) const {
    if (mode == HeightMode::relaxed) return near_height_cm;
    return layer_depth_mm < near_far_boundary_mm ? near_height_cm : far_height_cm;
  }
};

/// The table of CandidateParams: options, config keys, checks and thesis values.
const ParameterTable<CandidateParams>& candidate_parameters();

}  // namespace rdsf
