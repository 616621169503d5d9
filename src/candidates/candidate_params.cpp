#include "rdsf/candidates/candidate_params.hpp"

namespace rdsf {

const ParameterTable<CandidateParams>& candidate_parameters() {
  using P = CandidateParams;
  static const ParameterTable<P> table = {
      parameter("k", &P::k,
                "gap tolerance (pixels) inside a column's run", Range::at_least(0)),
      computed_parameter<P, bool>(
          "relaxed", "relaxed threshold_height: near_height everywhere (default strict)",
          [](const P& p) { return p.mode == HeightMode::relaxed; },
          [](P& p, const bool& on) { p.mode = on ? HeightMode::relaxed : HeightMode::strict; }, std::nullopt,
          /*is_switch=*/true),
      parameter("near-height", &P::near_height_cm,
                "threshold_height (cm) for near layers and in relaxed mode", Range::at_least(0)),
      parameter("far-height", &P::far_height_cm,
                "threshold_height (cm) for far layers in strict mode", Range::at_least(0)),
      parameter("near-far-boundary", &P::near_far_boundary_mm,
                "layers nearer than this (mm) are near", Range::at_least(0)),
      parameter("column-gap", &P::column_gap,
                "gap tolerance (columns) when joining columns into an object", Range::at_least(0)),
      parameter("min-width", &P::min_width_cm,
                "minimum real width (cm) of a candidate", Range::at_least(0)),
      parameter("occlusion-gap", &P::occlusion_gap_cm,
                "a column's run goes on across nearer things up to this height (cm); 0 = thesis",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("hole-gap", &P::hole_gap_cm,
                "a column's run goes on across missing readings only up to this height (cm); 0 = off",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("floor-tolerance", &P::floor_tolerance_mm,
                "cut bottom rows nearer than the object's median depth by more than this (mm): floor; 0 "
                "= thesis",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("window-scale", &P::window_scale,
                "window = strict box enlarged by this factor", Range::above(0)),
      parameter("height-at-column-depth", &P::height_at_column_depth,
                "a column failing threshold_height at the layer's mean depth is measured at its own; 0 = "
                "thesis",
                {}, std::optional<bool>(false)),
      parameter("column-depth-layers-below", &P::column_depth_layers_below_mm,
                "... in layers nearer than this (mm) only", Range::at_least(0)),
      parameter("fit-reach", &P::fit, &FitParams::reach_cm,
                "fitted box: reach (cm) over attached pieces (arms) each side; 0 = passing columns only",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("fit-depth-step", &P::fit, &FitParams::depth_step_mm,
                "fitted box: a piece's mean depth within this (mm) of its neighbour's; 0 = any", Range::at_least(0)),
      parameter("fit-occlusion-gap", &P::fit, &FitParams::occlusion_gap_cm,
                "fitted box: ... also across this much (cm) of nearer things in front (an arm behind a "
                "nearer person); 0 = off",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("fit-min-width-ratio", &P::fit, &FitParams::min_width_ratio,
                "fitted box: at least this fraction of its height wide, widened about its centre (limbs "
                "swung out of the layer); 0 = the layer's extent alone",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("join-pieces", &P::join, &JoinParams::pieces,
                "objects whose fitted extents touch are one when no wider than --max-person-width; 0 = "
                "thesis",
                {}, std::optional<bool>(false)),
      parameter("join-narrow-layers-below", &P::join, &JoinParams::narrow_layers_below_mm,
                "pieces each narrower than --min-width join only in layers nearer than this (mm)", Range::at_least(0)),
      parameter("join-narrow-passing", &P::join, &JoinParams::narrow_passing,
                "... and only when their passing columns alone are together at least "
                "--narrow-passing-width wide"),
      parameter("narrow-fitted-width", &P::narrow, &NarrowPersonParams::fitted_width_cm,
                "objects narrower than --min-width are candidates when their fitted box is this wide "
                "(cm), they are person-tall, near and have a background above their top (20 turns it "
                "on); 0 = off, the thesis",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("narrow-passing-width", &P::narrow, &NarrowPersonParams::passing_width_cm,
                "... and their passing columns at least this wide (cm)", Range::at_least(0)),
      parameter("narrow-layers-below", &P::narrow, &NarrowPersonParams::layers_below_mm,
                "... in layers nearer than this (mm)", Range::at_least(0)),
      parameter("narrow-min-height", &P::narrow, &NarrowPersonParams::min_height_cm,
                "... at least this tall (cm)", Range::at_least(0)),
      parameter("narrow-clear-above", &P::narrow, &NarrowPersonParams::clear_above_cm,
                "... with other layers over half of this band (cm) above their top", Range::at_least(0)),
      parameter("border-height", &P::border, &BorderCutParams::height_cm,
                "a column whose run reaches the image's top or bottom (a person the image cuts) passes at "
                "this height (cm) instead of threshold_height (25 turns it on: close cameras); 0 = off, the "
                "thesis",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("border-min-rows", &P::border, &BorderCutParams::min_rows_fraction,
                "... when its run is at least this fraction of the image's rows long", Range::between(0, 1)),
      parameter("border-upright", &P::border, &BorderCutParams::upright_mm,
                "... and the depths at its run's two ends differ by at most this (mm; not the floor)",
                Range::at_least(0)),
      parameter("min-fitted-width", &P::min_fitted_width_cm,
                "objects whose fitted box is narrower than this (cm) are not candidates (border objects "
                "exempt); 0 = thesis",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("max-object-width", &P::max_object_width_cm,
                "objects wider than this (cm) are walls, not candidates; 0 = thesis (no limit)",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("max-person-width", &P::max_person_width_cm,
                "the widest person (cm): wider objects are tried for splitting by depth jumps, valleys "
                "and steps, narrower pieces joined", Range::at_least(0)),
      parameter("split-depth-jump", &P::split, &WideSplitParams::depth_jump_mm,
                "split a wide object where its column depth jumps by more than this (mm); 0 = off",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("split-valley", &P::split, &WideSplitParams::valley_cm,
                "... or at a valley of its height profile this deep (cm); 0 = off",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("split-step", &P::split, &WideSplitParams::step_cm,
                "... or at a step of its height profile this high (cm); 0 = off",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("split-head-drop", &P::split_head, &HeadSplitParams::drop_cm,
                "split an object of any width between two heads (tops of its height profile with "
                "shoulders at least this far below, cm: people overlapping at one depth); 0 = off, the "
                "thesis",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("split-head-width", &P::split_head, &HeadSplitParams::width_cm,
                "... a head's top (within 5 cm of its height) at most this wide (cm)", Range::at_least(0)),
      parameter("split-head-min-width", &P::split_head, &HeadSplitParams::min_width_cm,
                "... and at least this wide (cm; a raised hand is narrower)", Range::at_least(0)),
      parameter("split-head-layers-below", &P::split_head, &HeadSplitParams::layers_below_mm,
                "... in layers nearer than this (mm)", Range::at_least(0)),
      parameter("split-head-keep-whole", &P::split_head, &HeadSplitParams::keep_whole,
                "an object split between heads stays a candidate besides its pieces"),
      parameter("fit-across-head-cut", &P::fit, &FitParams::across_head_cut,
                "... the pieces' fitted boxes reach across the cut over an arm held out to the other's "
                "passing columns; 0 = each side of the cut only",
                {}, std::optional<bool>(false)),
      parameter("min-part-width", &P::min_part_width_cm,
                "the narrowest piece a split leaves (cm)", Range::at_least(0)),
      parameter("split-keep-whole", &P::split, &WideSplitParams::keep_whole,
                "a split object stays a candidate besides its pieces",
                {}, std::optional<bool>(false)),
  };
  return table;
}

}  // namespace rdsf
