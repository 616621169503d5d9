#pragma once
// Parameters of candidate shaping (thesis names where the thesis names them), with their defaults.

namespace rdsf {

enum class HeightMode {
  strict,   ///< threshold_height: near_height_cm for layers nearer than near_far_boundary_mm, else far_height_cm
  relaxed,  ///< threshold_height: near_height_cm everywhere
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
  /// Floor trimming: rows at the bottom of an object whose farthest layer pixel is nearer than the object's
  /// median depth by more than this (mm) are floor in front of the feet, not the object, and are cut off
  /// the box. 0 turns it off (the thesis's behaviour).
  double floor_tolerance_mm = 150.0;
  /// The window is the strict box enlarged by this factor in both directions (thesis: 25%).
  double window_scale = 1.25;
  /// threshold_height for a layer at the given depth.
  double threshold_height_cm(double layer_depth_mm) const {
    if (mode == HeightMode::relaxed) return near_height_cm;
    return layer_depth_mm < near_far_boundary_mm ? near_height_cm : far_height_cm;
  }
};

}  // namespace rdsf
