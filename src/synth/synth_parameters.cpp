// The table of SynthParams (core/parameter_table.hpp): rdsf-synth's options, each declared once with its
// help, its check and its value under --classic. A number's bounds are written once: the help shows them
// ("(0..20)") and the check refuses what lies outside ("must lie in 0..20 degrees"). Options whose text is
// MIN..MAX, on/off, WIDTHxHEIGHT or HORIZONTALxVERTICAL are text rows that read and show that text.
#include <cmath>
#include <cctype>
#include <exception>
#include <functional>
#include <type_traits>

#include "rdsf/core/error.hpp"
#include "rdsf/synth/synth_params.hpp"

namespace rdsf::synth {
namespace {

using P = SynthParams;
using Row = Parameter<P>;

// ---- reading the texts ----

bool parse_int(const std::string& text, int& value) {
  if (text.empty() || text.size() > 7) return false;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  value = std::stoi(text);
  return true;
}

bool parse_real(const std::string& text, double& value) {
  if (text.empty() || text.size() > 24) return false;  // 24: every double's shortest text (-2.2250738585072014e-308)
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value);
}

/// "AxB" -> (A, B), each read by `parse`; false for anything else.
template <typename T, typename Parse>
bool parse_pair(const std::string& text, T& a, T& b, Parse parse) {
  const std::size_t x = text.find('x');
  return x != std::string::npos && parse(text.substr(0, x), a) && parse(text.substr(x + 1), b);
}

/// "MIN..MAX" -> (MIN, MAX), "V" -> (V, V), each read by `parse`. Refuses, naming the row, anything else
/// (`expected`) and MIN > MAX.
template <typename T, typename Parse>
void parse_span(const std::string& name, const std::string& text, T& low, T& high, Parse parse, const char* expected) {
  const std::size_t dots = text.find("..");
  const bool ok = dots == std::string::npos ? parse(text, low) && parse(text, high)
                                            : parse(text.substr(0, dots), low) && parse(text.substr(dots + 2), high);
  if (!ok) refuse_parameter(name, expected);
  if (low > high) refuse_parameter(name, "MIN is larger than MAX");
}

const char* const kRealSpan = "expected MIN..MAX (two numbers, e.g. 0.5..1.6) or one number";

/// Inclusive bounds of a number and its unit.
struct Bounds {
  double min, max;
  const char* unit;  ///< "degrees"; "share" for a share in 0..1
  std::string text() const { return parameter_text(min) + ".." + parameter_text(max); }
  bool holds(double value) const { return value >= min && value <= max; }  // NaN: never
  /// "" when `value` lies inside, else "must lie in 0..20 degrees" ("must be a share in 0..1").
  std::string problem(double value) const {
    if (holds(value)) return "";
    return std::string(unit) == "share" ? "must be a share in " + text() : "must lie in " + text() + " " + unit;
  }
  /// `help` ending with the bounds: "help (0..20)", or "help (0..20; note)".
  std::string help(const std::string& help, const std::string& note = "") const {
    return help + " (" + text() + (note.empty() ? "" : "; " + note) + ")";
  }
};

const Bounds kShare{0, 1, "share"};

// ---- where a row's value lives ----

template <typename T>
auto at(T P::*member) {
  return [member](auto& p) -> auto& { return p.*member; };
}
template <typename Group, typename T>
auto at(Group P::*group, T Group::*member) {
  return [group, member](auto& p) -> auto& { return p.*group.*member; };
}
template <typename Group, typename Inner, typename T>
auto at(Group P::*group, Inner Group::*inner, T Inner::*member) {
  return [group, inner, member](auto& p) -> auto& { return p.*group.*inner.*member; };
}

template <typename Field>
using FieldType = std::decay_t<decltype(std::declval<Field>()(std::declval<P&>()))>;

// ---- kinds of rows ----

/// A row of the member `field` reaches (a switch row with `is_switch`), unchecked.
template <typename Field>
Row member(std::string name, std::string help, Field field, bool is_switch = false) {
  using T = FieldType<Field>;
  return computed_parameter<P, T>(
      std::move(name), std::move(help), [field](const P& p) { return field(p); },
      [field](P& p, const T& v) { field(p) = v; }, std::nullopt, is_switch);
}

/// A row of the number `field` reaches, refusing values outside `bounds`.
template <typename Field>
Row bounded(const std::string& name, std::string help, Bounds bounds, Field field) {
  using T = FieldType<Field>;
  return computed_parameter<P, T>(
      name, std::move(help), [field](const P& p) { return field(p); },
      [field, bounds, name](P& p, const T& v) {
        const std::string problem = bounds.problem(static_cast<double>(v));
        if (!problem.empty()) refuse_parameter(name, problem);
        field(p) = v;
      });
}

/// bounded(), its help ending with the bounds and `note`: "help (0..20)", "help (0..20; note)".
template <typename Field>
Row ranged(const std::string& name, const std::string& help, Bounds bounds, Field field, const std::string& note = "") {
  return bounded(name, bounds.help(help, note), bounds, field);
}

/// A MIN..MAX row of the two numbers `low` and `high` reach ("0.5..1.6"; one number V is V..V), refusing
/// MIN > MAX and values outside `bounds`; its help ends with the bounds and `note`.
template <typename Low, typename High>
Row span(const std::string& name, const std::string& help, Bounds bounds, Low low, High high,
         const std::string& note = "") {
  return computed_parameter<P, std::string>(
      name, bounds.help(help, note), [low, high](const P& p) { return parameter_text(low(p)) + ".." + parameter_text(high(p)); },
      [low, high, bounds, name](P& p, const std::string& text) {
        double a = 0, b = 0;
        parse_span(name, text, a, b, parse_real, kRealSpan);
        if (!bounds.holds(a) || !bounds.holds(b)) {
          refuse_parameter(name, "must lie in " + bounds.text() + " " + bounds.unit + " with MIN <= MAX");
        }
        low(p) = a;
        high(p) = b;
      });
}

/// An on/off row of the switch `field` reaches.
template <typename Field>
Row on_off(const std::string& name, std::string help, Field field) {
  return computed_parameter<P, std::string>(
      name, std::move(help), [field](const P& p) { return std::string(field(p) ? "on" : "off"); },
      [field, name](P& p, const std::string& text) {
        if (text != "on" && text != "off") refuse_parameter(name, "expected on or off");
        field(p) = text == "on";
      });
}

/// `row` with `value` under --classic.
Row classic(Row row, ParameterValue value) {
  row.classic = std::move(value);
  return row;
}

/// A hidden row (no option) of the member `field` reaches, which only --classic sets, to `value`.
template <typename Field>
Row classic_only(std::string name, std::string help, Field field, ParameterValue value) {
  Row row = classic(member(std::move(name), std::move(help), field), std::move(value));
  row.hidden = true;
  return row;
}

// ---- the rows that are not simply one number ----

const Bounds kPeople{0, 20, "people"};

Row people_row() {
  return computed_parameter<P, std::string>(
      "people", "people in each clip's room: MIN..MAX",
      [](const P& p) { return std::to_string(p.people_min) + ".." + std::to_string(p.people_max); },
      [](P& p, const std::string& text) {
        int low = 0, high = 0;
        parse_span("people", text, low, high, parse_int,
                   "expected MIN..MAX (two whole numbers, e.g. 0..3) or one number");
        if (high > kPeople.max) refuse_parameter("people", "at most " + parameter_text(kPeople.max) + " people fit in a room");
        p.people_min = low;
        p.people_max = high;
      });
}

/// An AxB row of the two numbers `a` and `b` reach ("640x480"), each read by `parse`, refusing another form
/// (`expected`) and what `check` finds (the problem or ""). With `zero`, that word is the text of 0x0.
template <typename T, typename A, typename B>
Row pair_row(const std::string& name, std::string help, A a, B b, bool (*parse)(const std::string&, T&),
             const char* expected, std::function<std::string(T, T)> check, const std::string& zero = "") {
  return computed_parameter<P, std::string>(
      name, std::move(help),
      [a, b, zero](const P& p) {
        if (!zero.empty() && a(p) == 0 && b(p) == 0) return zero;
        return parameter_text(a(p)) + "x" + parameter_text(b(p));
      },
      [a, b, parse, expected, check, zero, name](P& p, const std::string& text) {
        T x = 0, y = 0;
        if ((zero.empty() || text != zero) && !parse_pair(text, x, y, parse)) refuse_parameter(name, expected);
        const std::string problem = check(x, y);
        if (!problem.empty()) refuse_parameter(name, problem);
        a(p) = x;
        b(p) = y;
      });
}

const int kSizeStep = 8;
const int kMinWidth = 64, kMinHeight = 48, kMaxWidth = 1920, kMaxHeight = 1440;

Row size_row() {
  return pair_row<int>(
      "size", "image size WIDTHxHEIGHT, multiples of " + std::to_string(kSizeStep), at(&P::width_px),
      at(&P::height_px), parse_int, "expected WIDTHxHEIGHT in pixels, e.g. 640x480", [](int w, int h) -> std::string {
        if (w % kSizeStep != 0 || h % kSizeStep != 0) return "width and height must be multiples of " + std::to_string(kSizeStep);
        if (w < kMinWidth || h < kMinHeight || w > kMaxWidth || h > kMaxHeight) {
          return "must be between " + std::to_string(kMinWidth) + "x" + std::to_string(kMinHeight) + " and " +
                 std::to_string(kMaxWidth) + "x" + std::to_string(kMaxHeight);
        }
        return "";
      });
}

const Bounds kFieldOfView{20, 150, "degrees"};

Row field_of_view_row() {
  return pair_row<double>(
      "fov",
      "field of view HORIZONTALxVERTICAL degrees (e.g. 70.6x60 Kinect v2 at 512x424, 87x58 RealSense D435; " +
          kFieldOfView.text() +
          "), centred pinhole, written to camera.yml; kinect: the Kinect v1's fx = fy = 525 px at 640x480 scaled "
          "to --size (no camera.yml)",
      at(&P::fov_h_deg), at(&P::fov_v_deg), parse_real, "expected HORIZONTALxVERTICAL in degrees, e.g. 87x58, or kinect",
      [](double h, double v) -> std::string {
        if ((h == 0 && v == 0) || (kFieldOfView.holds(h) && kFieldOfView.holds(v))) return "";  // 0x0: kinect
        return "each angle must lie in " + kFieldOfView.text() + " " + kFieldOfView.unit;
      },
      "kinect");
}

const Bounds kClutter{0, 40, "pieces"};

// --clutter MIN..MAX pieces sets the pieces and turns clutter on when MAX > 0; --classic turns it off
// (the hidden row clutter-on) and leaves the pieces.
Row clutter_row() {
  return computed_parameter<P, std::string>(
      "clutter",
      "extra clutter per room, MIN..MAX pieces (plants, lamps, doors, coat racks, desks with monitors, "
      "cupboards, stacked chairs, partitions, robots; 0 = off, at most " + parameter_text(kClutter.max) + ")",
      [](const P& p) { return std::to_string(p.room.clutter_min) + ".." + std::to_string(p.room.clutter_max); },
      [](P& p, const std::string& text) {
        double low = 0, high = 0;
        parse_span("clutter", text, low, high, parse_real, kRealSpan);
        if (low != std::floor(low) || high != std::floor(high)) refuse_parameter("clutter", "expected whole numbers of pieces");
        if (!kClutter.holds(low) || !kClutter.holds(high)) {
          refuse_parameter("clutter", "must lie in " + kClutter.text() + " pieces with MIN <= MAX");
        }
        p.room.clutter_min = static_cast<int>(low);
        p.room.clutter_max = static_cast<int>(high);
        p.room.clutter = p.room.clutter_max > 0;
      });
}

ParameterTable<P> make_table() {
  using R = RoomParams;
  using S = KinectSensorParams;
  using H = PeopleParams;
  using B = BodyParams;
  const std::string off = "off";
  return {
      // the recording (rdsf-synth's first group; --seed, between --people and --empty, is its own)
      bounded("frames", "number of frames", {1, 999999, "frames"}, at(&P::frames)),
      people_row(),
      member("empty", "render the same rooms without people (negatives)", at(&P::empty), /*is_switch=*/true),
      size_row(),
      field_of_view_row(),
      member("rgb", "also write the registered colour image NNNNNN.rgb.png", at(&P::rgb), /*is_switch=*/true),
      parameter("clip-frames", &P::clip_frames, "frames per clip: each clip has a new room, camera pose and people",
                Range::at_least(1)),
      // the variety (issue 13)
      classic(span("camera-height", "camera height above the floor, MIN..MAX metres, per clip", {0.2, 2.5, "m"},
                   at(&P::room, &R::camera_height_min_m), at(&P::room, &R::camera_height_max_m)),
              std::string("0.7..1.2")),
      span("camera-pitch", "downward tilt, MIN..MAX degrees, per clip", {-30, 30, "degrees"},
           at(&P::room, &R::pitch_min_deg), at(&P::room, &R::pitch_max_deg)),
      classic(ranged("camera-roll", "roll about the optical axis, uniform in +-DEG, per clip", {0, 20, "degrees"},
                     at(&P::room, &R::roll_max_deg)),
              0.0),
      classic(ranged("camera-yaw", "camera turned against the room (walls at angles), uniform in +-DEG",
                     {0, 60, "degrees"}, at(&P::room, &R::yaw_max_deg)),
              0.0),
      classic(ranged("moving-camera", "share of clips in which the camera drives, turns and rocks", kShare,
                     at(&P::room, &R::moving_share)),
              0.0),
      ranged("camera-speed", "top speed of a driving camera, m/s", {0, 1.5, "m/s"}, at(&P::room, &R::camera_speed_max_mps)),
      classic(on_off("room-kinds", "on: corridors and open-plan offices besides rooms; off: rooms only",
                     at(&P::room, &R::room_kinds)),
              off),
      ranged("corridors", "share of corridors with --room-kinds on", kShare, at(&P::room, &R::corridor_share)),
      ranged("open-plan", "share of open-plan offices and halls with --room-kinds on", kShare,
             at(&P::room, &R::open_plan_share)),
      clutter_row(),
      ranged("near-clutter",
             "pieces of furniture and clutter 0.6-1.6 m in front of the camera, 1..N a room (0: none)",
             {0, 6, "pieces"}, at(&P::room, &R::near_clutter_max),
             "a camera close to people is close to things too: boxes, desks, chair backs filling the image"),
      classic(on_off("bodies", "on: children to tall adults (1.0-2.0 m), slim to heavy; off: adults 1.5-1.95 m",
                     at(&P::people, &H::body, &B::varied_bodies)),
              off),
      ranged("children", "share of children with --bodies on", kShare, at(&P::people, &H::body, &B::child_share)),
      classic(on_off("outfits",
                     "on: coats, skirts, dresses, loose clothes, long hair, backpacks, bags, boxes and trays; off: plain",
                     at(&P::people, &H::body, &B::outfits)),
              off),
      classic(on_off("poses", "on: sitting, bending, arms raised, out, crossed, in pockets, pointing, waving; off: the four basic",
                     at(&P::people, &H::poses)),
              off),
      classic(ranged("sitting", "chance that a person sits on a free chair, with --poses on", kShare,
                     at(&P::people, &H::sitting_share)),
              0.0),
      classic(span("people-distance", "people's paths stay MIN..MAX metres in front of the room's camera end",
                   {0.5, 10, "m"}, at(&P::people, &H::nearest_m), at(&P::people, &H::farthest_m),
                   "nearer than about 1.5 m the image's edges cut heads or feet"),
              std::string("1..7")),
      classic(ranged("wall-clearance", "people's paths keep this far from walls and furniture, metres", {0.2, 1, "m"},
                     at(&P::people, &H::clearance_m), "0.25: people stand against walls, cupboards and chair backs"),
              0.5),
      classic(ranged("groups", "chance that a person walks and stands beside the one before (pairs, groups)", kShare,
                     at(&P::people, &H::group_share)),
              0.0),
      ranged("furniture-dropout",
             "largest share of a piece of furniture's surface lost in patches (dark, shiny materials), drawn per piece",
             kShare, at(&P::room, &R::furniture_dropout_max),
             "real rooms' clutter has fewer holes than their people; 0.3 makes it holier (docs/quality.md, \"Holes\")"),
      classic(ranged("eight-bit", "share of clips stored as 8-bit linear captures, like ../shared/realdata", kShare,
                     at(&P::sensor, &S::eight_bit_share)),
              0.0),
      span("eight-bit-step", "step of an 8-bit capture, MIN..MAX mm", {1, 60, "mm"},
           at(&P::sensor, &S::eight_bit_step_min_mm), at(&P::sensor, &S::eight_bit_step_max_mm)),
      classic(ranged("xtion", "share of clips with Xtion-like noise: 1.3-2x stronger, half of it shared by neighbours",
                     kShare, at(&P::sensor, &S::xtion_share)),
              0.0),
      classic(ranged("coherent-holes",
                     "block matching's coherence: holes of at most this many pixels on one surface are filled and "
                     "runs of at most this many readings between holes lost, along rows and columns",
                     {0, 8, "pixels"}, at(&P::sensor, &S::coherent_holes_px),
                     "0 = per-pixel holes; 1 gives the real frames' share of 1-px holes, docs/rdsf-synth.md"),
              0),
      // members --classic sets that have no option (the values before issue 13)
      classic_only("clutter-on", "extra clutter at all (--clutter turns it on when MAX > 0)", at(&P::room, &R::clutter), false),
      classic_only("camera-offset", "largest sideways offset of the camera from the room's middle, m", at(&P::room, &R::camera_offset_max_m), 0.0),
      classic_only("floor-dropout", "largest share of a room's floor lost to dropout", at(&P::room, &R::floor_dropout_max), 0.2),
      classic_only("wall-dropout", "largest share of a room's walls lost to dropout", at(&P::room, &R::wall_dropout_max), 0.05),
      classic_only("dropout-patch", "scale of the blobby dropout field, px at 640 px wide", at(&P::sensor, &S::patch_cell_px), 20),
      classic_only("in-view", "share of people's spots drawn in the camera's view", at(&P::people, &H::in_view_share), 0.0),
  };
}

}  // namespace

const ParameterTable<SynthParams>& synth_parameters() {
  static const ParameterTable<SynthParams> table = make_table();
  return table;
}

SynthParams with_classic_values(SynthParams params) {
  return with_preset_values(synth_parameters(), &Parameter<SynthParams>::classic, std::move(params));
}

void set_synth_options(SynthParams& params, const std::vector<std::pair<std::string, ParameterValue>>& values,
                       bool classic) {
  for (const auto& [name, value] : values) {
    const Row* row = find_parameter(synth_parameters(), name);
    if (row == nullptr) fail("--" + name, "is no option of rdsf-synth");
    if (classic && row->classic) continue;  // --classic overrides it
    try {
      row->set(params, value);
    } catch (const Error& e) {
      const std::string message = e.what(), named = name + " ";
      fail("--" + name + " " + parameter_text(value), message.rfind(named, 0) == 0 ? message.substr(named.size()) : message);
    }
  }
  if (classic) params = with_classic_values(params);
}

}  // namespace rdsf::synth
