// rdsf-synth: renders a synthetic Kinect v1 recording (depth, optional colour, person boxes).
#include <string>

#include "cli/cli.hpp"
#include "rdsf/synth/synth_params.hpp"
#include "synth/synth_run.hpp"

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-synth", [&] {
    namespace po = rdsf::cli::po;
    namespace synth = rdsf::synth;
    rdsf::SynthOptions o;
    for (int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
    po::options_description options("rdsf-synth");
    // clang-format off
    options.add_options()
        ("out", po::value(&o.out_dir)->required(),
         "folder for NNNNNN.depth.png, NNNNNN.rgb.png, boxes.csv, synth.yml")
        ("frames", po::value(&o.params.frames)->default_value(o.params.frames), "number of frames")
        ("people", po::value(&o.people)->default_value(o.people), "people in each clip's room: MIN..MAX")
        ("seed", po::value(&o.params.seed)->default_value(o.params.seed), "random seed (same seed, same bytes)")
        ("empty", po::bool_switch(&o.params.empty), "render the same rooms without people (negatives)")
        ("size", po::value(&o.size)->default_value(o.size), "image size WIDTHxHEIGHT, multiples of 8")
        ("fov", po::value(&o.fov)->default_value(o.fov),
         "field of view HORIZONTALxVERTICAL degrees (e.g. 70.6x60 Kinect v2 at 512x424, 87x58 RealSense D435; "
         "20..150), centred pinhole, written to camera.yml; kinect: the Kinect v1's fx = fy = 525 px at "
         "640x480 scaled to --size (no camera.yml)")
        ("rgb", po::bool_switch(&o.params.rgb), "also write the registered colour image NNNNNN.rgb.png")
        ("clip-frames", po::value(&o.params.clip_frames)->default_value(o.params.clip_frames),
         "frames per clip: each clip has a new room, camera pose and people")
        ("force", po::bool_switch(&o.force), "replace the frames of an earlier set in --out");
    po::options_description variety("variety of rooms, people and captures (all on by default)");
    synth::SynthParams& p = o.params;
    const auto g = rdsf::cli::shortest_text;
    variety.add_options()
        ("camera-height", po::value(&o.camera_height)->default_value(o.camera_height),
         "camera height above the floor, MIN..MAX metres, per clip (0.2..2.5)")
        ("camera-pitch", po::value(&o.camera_pitch)->default_value(o.camera_pitch),
         "downward tilt, MIN..MAX degrees, per clip (-30..30)")
        ("camera-roll", po::value(&p.room.roll_max_deg)->default_value(p.room.roll_max_deg, g(p.room.roll_max_deg)),
         "roll about the optical axis, uniform in +-DEG, per clip (0..20)")
        ("camera-yaw", po::value(&p.room.yaw_max_deg)->default_value(p.room.yaw_max_deg, g(p.room.yaw_max_deg)),
         "camera turned against the room (walls at angles), uniform in +-DEG (0..60)")
        ("moving-camera", po::value(&p.room.moving_share)->default_value(p.room.moving_share, g(p.room.moving_share)),
         "share of clips in which the camera drives, turns and rocks (0..1)")
        ("camera-speed", po::value(&p.room.camera_speed_max_mps)->default_value(p.room.camera_speed_max_mps, g(p.room.camera_speed_max_mps)),
         "top speed of a driving camera, m/s (0..1.5)")
        ("room-kinds", po::value(&o.room_kinds)->default_value(o.room_kinds),
         "on: corridors and open-plan offices besides rooms; off: rooms only")
        ("corridors", po::value(&p.room.corridor_share)->default_value(p.room.corridor_share, g(p.room.corridor_share)),
         "share of corridors with --room-kinds on (0..1)")
        ("open-plan", po::value(&p.room.open_plan_share)->default_value(p.room.open_plan_share, g(p.room.open_plan_share)),
         "share of open-plan offices and halls with --room-kinds on (0..1)")
        ("clutter", po::value(&o.clutter)->default_value(o.clutter),
         "extra clutter per room, MIN..MAX pieces (plants, lamps, doors, coat racks, desks with monitors, "
         "cupboards, stacked chairs, partitions, robots; 0 = off, at most 40)")
        ("bodies", po::value(&o.bodies)->default_value(o.bodies),
         "on: children to tall adults (1.0-2.0 m), slim to heavy; off: adults 1.5-1.95 m")
        ("children", po::value(&p.people.body.child_share)->default_value(p.people.body.child_share, g(p.people.body.child_share)),
         "share of children with --bodies on (0..1)")
        ("outfits", po::value(&o.outfits)->default_value(o.outfits),
         "on: coats, skirts, dresses, loose clothes, long hair, backpacks, bags, boxes and trays; off: plain")
        ("poses", po::value(&o.poses)->default_value(o.poses),
         "on: sitting, bending, arms raised, out, crossed, in pockets, pointing, waving; off: the four basic")
        ("sitting", po::value(&p.people.sitting_share)->default_value(p.people.sitting_share, g(p.people.sitting_share)),
         "chance that a person sits on a free chair, with --poses on (0..1)")
        ("people-distance", po::value(&o.people_distance)->default_value(o.people_distance),
         "people's paths stay MIN..MAX metres in front of the room's camera end (0.5..10; nearer than about 1.5 m "
         "the image's edges cut heads or feet)")
        ("wall-clearance", po::value(&p.people.clearance_m)->default_value(p.people.clearance_m, g(p.people.clearance_m)),
         "people's paths keep this far from walls and furniture, metres (0.2..1; 0.25: people stand against "
         "walls, cupboards and chair backs)")
        ("groups", po::value(&p.people.group_share)->default_value(p.people.group_share, g(p.people.group_share)),
         "chance that a person walks and stands beside the one before (pairs, groups) (0..1)")
        ("eight-bit", po::value(&p.sensor.eight_bit_share)->default_value(p.sensor.eight_bit_share, g(p.sensor.eight_bit_share)),
         "share of clips stored as 8-bit linear captures, like ../shared/realdata (0..1)")
        ("eight-bit-step", po::value(&o.eight_bit_step)->default_value(o.eight_bit_step),
         "step of an 8-bit capture, MIN..MAX mm (1..60)")
        ("xtion", po::value(&p.sensor.xtion_share)->default_value(p.sensor.xtion_share, g(p.sensor.xtion_share)),
         "share of clips with Xtion-like noise: 1.3-2x stronger, half of it shared by neighbours (0..1)")
        ("coherent-holes", po::value(&p.sensor.coherent_holes_px)->default_value(p.sensor.coherent_holes_px),
         "block matching's coherence: holes of at most this many pixels on one surface are filled and runs "
         "of at most this many readings between holes lost, along rows and columns (0..8; 0 = per-pixel "
         "holes; 1 gives the real frames' share of 1-px holes, docs/rdsf-synth.md)")
        ("classic", po::bool_switch(&o.classic),
         "turn all of the variety above off: the generator before it (overrides these options)");
    options.add(variety);
    // clang-format on
    po::variables_map values;
    const rdsf::cli::ProgramInfo info{
        "rdsf-synth", "--out DIR [--frames N] [--people MIN..MAX] [--seed S] [--empty] [--size WxH] [--rgb]",
        "Renders a synthetic Kinect v1 recording: indoor rooms with furniture and walking, standing people,\n"
        "seen through a model of the sensor (range 0.5-8 m, noise growing with distance squared, shadows\n"
        "and holes). Writes the frame-source layout (readable by every --source option) and boxes.csv with\n"
        "the tight box of each person's visible pixels and its track id. Same options, same bytes.\n"
        "Rooms, people and captures vary as in a lab (see docs/synthetic.md); each variety can be turned off."};
    if (!rdsf::cli::parse(argc, argv, info, options, values)) return 0;
    return rdsf::run_synth(o);
  });
}
