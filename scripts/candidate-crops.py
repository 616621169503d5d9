#!/usr/bin/python3
"""Candidates' windows side by side, one row per recording: what a model takes for a person, at a glance.

  scripts/candidate-crops.py OUT.png ROW [ROW ...]

  ROW is CSV:FRAMES:KIND:N[:TRUTH]
    CSV     an `rdsf-detect --out` file (one line per candidate: frame, box, depth_mm, score, ...)
    FRAMES  the folder holding the frames it names (NAME.depth.png)
    KIND    top-clutter: the N highest-scoring candidates that overlap no person (IoU < 0.1 with every box
              of TRUTH; without TRUTH every candidate, as in a people-free recording)
            top-pieces: the N highest-scoring ones that overlap a person by IoU 0.1-0.5 (needs TRUTH)
            people: N candidates of people (IoU >= 0.5), drawn at random with seed 1 (needs TRUTH)
    N       how many (1-32)
    TRUTH   a boxes.csv (frame, person, x, y, w, h[, visible_fraction, ...])

Each tile is the candidate's window (its reported box enlarged by 25 % about the centre, as the crop's
window is cut from the strict box) resampled by nearest neighbour to 64x128 and shown at twice that size,
unmasked: grey 128 is the window's median depth, one grey level per 8 mm, black no reading. The model sees
only the pixels of the candidate's depth layer; the tile shows what stands around them too. Prints each
row's scores (H) to stdout.

Example (docs/clutter-crops.png):
  rdsf-detect --source ../shared/realdata/empty --out empty.csv
  rdsf-detect --source held-out --out held.csv
  scripts/candidate-crops.py docs/clutter-crops.png empty.csv:../shared/realdata/empty:top-clutter:8 \\
      held.csv:held-out:top-clutter:8:held-out/boxes.csv held.csv:held-out:people:8:held-out/boxes.csv

Exit codes: 0 done, 1 a file that cannot be read, 2 a usage error (one line on stderr, nothing written).
Uses Debian's python3-numpy and python3-png (scripts/setup.sh installs them).
"""
import csv
import os
import random
import sys

import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from depth_frames import iou  # noqa: E402
import depth_frames  # noqa: E402

KINDS = ("top-clutter", "top-pieces", "people")


def fail(message, code=1):
    print(f"candidate-crops: {message}", file=sys.stderr)
    sys.exit(code)


def usage_error(message):
    fail(message, 2)


def read_depth(path):
    try:
        return depth_frames.read_depth(path)
    except depth_frames.FrameError as e:
        fail(str(e))


def read_rows(path, fields):
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f"{path}: {e}")
    if rows and not all(k in rows[0] for k in fields):
        fail(f"{path}: expected the columns {', '.join(fields)}")
    return rows


def box(r, path):
    try:
        return tuple(int(r[k]) for k in ("x", "y", "w", "h"))
    except ValueError:
        fail(f"{path}: frame {r['frame']}: the box {r['x']},{r['y']},{r['w']},{r['h']} is not four whole numbers")


def tile(depth, b):
    x, y, w, h = b
    cx, cy, ww, hh = x + w / 2, y + h / 2, w * 1.25, h * 1.25
    xs = numpy.clip((cx - ww / 2 + (numpy.arange(64) + 0.5) * ww / 64).astype(int), 0, depth.shape[1] - 1)
    ys = numpy.clip((cy - hh / 2 + (numpy.arange(128) + 0.5) * hh / 128).astype(int), 0, depth.shape[0] - 1)
    crop = depth[ys][:, xs].astype(float)
    valid = crop[crop > 0]
    median = numpy.median(valid) if len(valid) else 0
    grey = numpy.clip(128 + (crop - median) / 8, 1, 255)
    grey[crop == 0] = 0
    return grey.astype(numpy.uint8)


def parse_row(spec):
    """ROW's parts (csv_path, frames, kind, n, truth_path or None); a usage error when they are not a ROW."""
    parts = spec.split(":")
    if len(parts) not in (4, 5):
        usage_error(f"row '{spec}': expected CSV:FRAMES:KIND:N[:TRUTH]")
    csv_path, frames, kind, n = parts[:4]
    truth_path = parts[4] if len(parts) == 5 else None
    if kind not in KINDS:
        usage_error(f"row '{spec}': KIND is one of {', '.join(KINDS)}, not '{kind}'")
    if not n.isdigit() or not 1 <= int(n) <= 32:
        usage_error(f"row '{spec}': N is a whole number from 1 to 32")
    if kind != "top-clutter" and truth_path is None:
        usage_error(f"row '{spec}': {kind} needs a TRUTH file")
    return csv_path, frames, kind, int(n), truth_path


def pick(spec, csv_path, frames, kind, n, truth_path):
    truth = {}
    for r in read_rows(truth_path, ("frame", "x", "y", "w", "h")) if truth_path else []:
        truth.setdefault(r["frame"], []).append(box(r, truth_path))
    chosen = []
    for r in read_rows(csv_path, ("frame", "x", "y", "w", "h", "score")):
        b = box(r, csv_path)
        overlap = max([iou(b, t) for t in truth.get(r["frame"], [])] or [0.0])
        wanted = {"top-clutter": overlap < 0.1, "top-pieces": 0.1 <= overlap < 0.5, "people": overlap >= 0.5}[kind]
        if wanted:
            chosen.append((float(r["score"]), r["frame"], b))
    if kind == "people":
        chosen = random.Random(1).sample(chosen, min(n, len(chosen)))
    else:
        chosen = sorted(chosen, key=lambda c: -c[0])[:n]
    if not chosen:
        fail(f"row '{spec}': no candidate of that kind")
    tiles = [tile(read_depth(os.path.join(frames, f"{frame}.depth.png")), b) for _, frame, b in chosen]
    print(f"{kind} of {csv_path}: H " + " ".join(f"{s:.2f}" for s, _, _ in chosen))
    return tiles


def main():
    if len(sys.argv) < 3 or sys.argv[1] in ("-h", "--help"):
        asked = len(sys.argv) > 1 and sys.argv[1] in ("-h", "--help")
        print(__doc__, file=sys.stdout if asked else sys.stderr)
        sys.exit(0 if asked else 2)
    out = sys.argv[1]
    if not out.endswith(".png"):
        usage_error(f"the first argument is the picture to write, OUT.png, not '{out}'")
    specs = [(spec, *parse_row(spec)) for spec in sys.argv[2:]]  # every row checked before any file is read
    rows = [pick(*spec) for spec in specs]
    width = max(len(r) for r in rows) * 68
    lines = []
    for r in rows:
        line = numpy.full((128, width), 255, numpy.uint8)
        for i, t in enumerate(r):
            line[:, i * 68:i * 68 + 64] = t
        lines += [line, numpy.full((6, width), 255, numpy.uint8)]
    depth_frames.write_png(out, numpy.kron(numpy.vstack(lines[:-1]), numpy.ones((2, 2), numpy.uint8)))


if __name__ == "__main__":
    main()
