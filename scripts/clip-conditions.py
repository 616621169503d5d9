#!/usr/bin/python3
"""Detection by condition over synthetic clips: which rooms, cameras and sensors a model fails in.

  scripts/clip-conditions.py [--model LABEL] SET:REPORT [SET:REPORT ...]

  SET     a folder rendered by rdsf-synth (its clips.csv: one row per clip, what the clip was drawn as)
  REPORT  the report folder of `rdsf-detect --source SET --truth SET/boxes.csv --clip-frames N --report-dir
          REPORT` with N the set's --clip-frames (its clips.csv: each clip's people, people with a candidate,
          people detected and false positives at the model's operating point)
  --model LABEL  the report's model to read (its `model` column, e.g. "people v3"; default: the first)

Prints a Markdown table per condition (room kind, camera height, pitch, roll, moving camera, sensor noise,
8-bit capture, people in the clip, furniture solids): for each value band the clips (and of them those with
someone at least --min-visible visible), people, candidate recall
(people with a candidate / people), TAR at the operating point (people detected / people) with its 95 %
interval over clips (percentile bootstrap, 2,000 draws of the band's clips with replacement, seed 1;
scripts/lib/detect_clips.py), and
false positives per frame. The clips are the unit: a clip's people are the same people in the same room
frame after frame, so a band of few clips says little however many people it holds.

Exit codes: 0 done, 1 a file that cannot be read or does not match (one line naming it), 2 a usage error.
Uses Debian's python3-numpy (scripts/setup.sh installs it).
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
import detect_clips  # noqa: E402


def die(code, message):
    print(f"clip-conditions: {message}", file=sys.stderr)
    sys.exit(code)


def read_csv(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        die(1, f"{path}: {e.strerror}")


def numeric(path, row, key, kind=float):
    try:
        return kind(row[key])
    except (KeyError, TypeError, ValueError):
        die(1, f"{path}: no number in column '{key}' of clip {row.get('clip', '?')}")


def clips_of(pair, model):
    if ":" not in pair:
        die(2, f"'{pair}' is not SET:REPORT")
    set_dir, report_dir = pair.rsplit(":", 1)
    drawn_path = os.path.join(set_dir, "clips.csv")
    found_path = os.path.join(report_dir, "clips.csv")
    drawn = {int(numeric(drawn_path, r, "clip", int)): r for r in read_csv(drawn_path)}
    try:
        found, _ = detect_clips.read_clips(found_path, model)
    except detect_clips.ClipsError as e:
        die(1, str(e))
    out = []
    for item in found:
        name = item["clip"]
        if not name.startswith("#"):
            die(1, f"{found_path}: clip '{name}' is not numbered: give rdsf-detect --clip-frames")
        c = drawn.get(int(name[1:]))
        if c is None:
            die(1, f"{found_path}: clip {name} is not in {drawn_path} (another --clip-frames?)")
        item["set"] = set_dir
        item["room"] = c["room"]
        for k in ("camera_height_m", "pitch_deg", "roll_deg", "noise_factor", "eight_bit_step_mm"):
            item[k] = numeric(drawn_path, c, k)
        for k in ("moving", "people", "furniture_shapes"):
            item["drawn_" + k] = numeric(drawn_path, c, k, int)
        out.append(item)
    return out


def band(value, edges, unit):
    for low, high in zip(edges, edges[1:]):
        if low <= value < high:
            return f"{low:g}-{high:g} {unit}".strip()
    return f">= {edges[-1]:g} {unit}".strip() if value >= edges[-1] else f"< {edges[0]:g} {unit}".strip()


CONDITIONS = [
    ("room", lambda c: c["room"]),
    ("camera height", lambda c: band(c["camera_height_m"], [0.5, 0.8, 1.1, 1.4, 1.7], "m")),
    ("pitch (down)", lambda c: band(c["pitch_deg"], [-3, 0, 3, 6.01], "deg")),
    ("roll", lambda c: band(abs(c["roll_deg"]), [0, 1, 2, 3.01], "deg")),
    ("camera", lambda c: "moving" if c["drawn_moving"] else "still"),
    ("sensor noise", lambda c: "Xtion-like (x1.3-2)" if c["noise_factor"] > 1.0 else "Kinect v1"),
    ("capture", lambda c: "8-bit re-encoded" if c["eight_bit_step_mm"] > 0 else "16-bit mm"),
    ("people in the clip", lambda c: str(c["drawn_people"])),
    ("furniture solids", lambda c: band(c["drawn_furniture_shapes"], [0, 50, 80, 120, 300], "")),
]


def interval(clips):
    if len(clips) < 2:
        return None
    return detect_clips.quantiles(detect_clips.pooled_rate([c["detected"] for c in clips], [c["people"] for c in clips],
                                                           detect_clips.draws(len(clips))))


def table(name, key, clips):
    groups = {}
    for c in clips:
        groups.setdefault(key(c), []).append(c)
    lines = [f"| {name} | clips (with people) | people | candidate recall | TAR at the operating point (95 % over clips) | FP per frame |",
             "| --- | --- | --- | --- | --- | --- |"]
    for value in sorted(groups):
        g = groups[value]
        people = sum(c["people"] for c in g)
        frames = sum(c["frames"] for c in g)
        if people == 0:
            continue
        recall = sum(c["with_candidate"] for c in g) / people
        tar = sum(c["detected"] for c in g) / people
        ci = interval([c for c in g if c["people"] > 0])
        ci_text = f"{ci[0]:.2f}-{ci[1]:.2f}" if ci else "one clip"
        fppf = sum(c["false_positives"] for c in g) / frames if frames else 0.0
        with_people = sum(1 for c in g if c["people"] > 0)
        lines.append(f"| {value} | {len(g)} ({with_people}) | {people} | {recall:.3f} | {tar:.3f} ({ci_text}) | {fppf:.3f} |")
    return "\n".join(lines)


def main(argv):
    options, pairs = detect_clips.parse_arguments(argv, {"--model": None}, die, __doc__)
    model = options["--model"]
    if not pairs:
        die(2, "give at least one SET:REPORT")
    clips = [c for pair in pairs for c in clips_of(pair, model)]
    people = sum(c["people"] for c in clips)
    print(f"{len(clips)} clips of {len(pairs)} sets, {people} people (at least half visible).\n")
    for name, key in CONDITIONS:
        print(table(name, key, clips))
        print()
    worst = sorted((c for c in clips if c["people"] > 0), key=lambda c: c["detected"] / c["people"])[:5]
    print("Clips with the fewest people found: " + "; ".join(
        f"{os.path.basename(os.path.normpath(c['set']))} {c['clip']}: {c['detected']} of {c['people']} "
        f"({c['with_candidate']} with a candidate; {c['room']}, camera {c['camera_height_m']:.2f} m, "
        f"pitch {c['pitch_deg']:.1f}, noise x{c['noise_factor']:.2f}, 8-bit step {c['eight_bit_step_mm']:g} mm)"
        for c in worst))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
