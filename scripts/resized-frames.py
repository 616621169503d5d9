#!/usr/bin/python3
"""Frames resized to another sensor's size, and whether a model finds the same people in them.

  scripts/resized-frames.py resize SRC DST --size 512x424
      writes SRC's NAME.depth.png resized by nearest neighbour (OpenCV's INTER_NEAREST rule: source pixel
      floor(x * src_width / width)) to DST, with camera.yml = the Kinect v1 model (fx = fy = 525 px,
      cx = 319.5, cy = 239.5 at 640x480) scaled to the size, as CameraModel::scaled_to does: f * s,
      c' = (c + 0.5) * s - 0.5. Depth only (colour is not written: the workbench's models use depth).
      boxes.csv is copied with its boxes scaled (round(x * sx) ...), as the test scales them.

  scripts/resized-frames.py compare ORIGINAL.csv RESIZED.csv --size 512x424 [--truth boxes.csv]
      ORIGINAL.csv and RESIZED.csv are rdsf-detect --out files (one row per candidate, person > 0 for a
      detection) on the 640x480 frames and on the resized ones. Prints one line:
        found F of N  other O  labelled L_orig L_resized of T
      F: the original's detections found again (a resized detection with IoU >= 0.7 with the original's
      box scaled to the size, each used once, in the original's order); O: resized detections not used;
      L: labelled people with a detection at IoU >= 0.5 (boxes scaled for the resized frames). The same
      rules as the test CameraFile.ResizedRealFramesWithTheirCameraModelFindTheSamePeople.

Uses Debian's python3-numpy and python3-png (scripts/setup.sh installs them).
"""
import argparse
import csv
import io
import os
import sys

import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from depth_frames import iou  # noqa: E402
import depth_frames  # noqa: E402


def size_arg(text):
    w, _, h = text.partition("x")
    if not (w.isdigit() and h.isdigit()) or int(w) < 16 or int(h) < 16:
        raise argparse.ArgumentTypeError(f"--size {text}: expected WIDTHxHEIGHT, e.g. 512x424")
    return int(w), int(h)


def read_depth(path):
    try:
        return depth_frames.read_depth(path)
    except depth_frames.FrameError as e:
        sys.exit(f"resized-frames: {e}")


def nearest(depth, width, height):
    src_h, src_w = depth.shape
    xs = numpy.minimum(numpy.floor(numpy.arange(width) * (src_w / width)).astype(int), src_w - 1)
    ys = numpy.minimum(numpy.floor(numpy.arange(height) * (src_h / height)).astype(int), src_h - 1)
    return depth[ys][:, xs]


def camera_text(width, height):
    sx, sy = width / 640.0, height / 480.0
    return ("%YAML:1.0\n---\nformat: rdsf-camera\nformat_version: 1\n"
            f"width_px: {width}\nheight_px: {height}\n"
            f"fx_px: {525.0 * sx!r}\nfy_px: {525.0 * sy!r}\n"
            f"cx_px: {(319.5 + 0.5) * sx - 0.5!r}\ncy_px: {(239.5 + 0.5) * sy - 0.5!r}\n"
            "depth_unit_mm: 1\n")


def scaled(box, sx, sy):  # round half away from zero, as cvRound of positive values
    return tuple(int(numpy.floor(v * s + 0.5)) for v, s in zip(box, (sx, sy, sx, sy)))


def resize(args):
    width, height = args.size
    names = sorted(n for n in os.listdir(args.src) if n.endswith(".depth.png"))
    if not names:
        sys.exit(f"resized-frames: {args.src}: no NAME.depth.png frames")
    os.makedirs(args.dst, exist_ok=True)
    for i, name in enumerate(names):
        first = read_depth(os.path.join(args.src, name))
        if first.shape != (480, 640):
            sys.exit(f"resized-frames: {args.src}/{name}: {first.shape[1]}x{first.shape[0]}, expected 640x480")
        depth_frames.write_png(os.path.join(args.dst, name), nearest(first, width, height))
        print(f"\rresized-frames: {i + 1}/{len(names)} frames -> {args.dst}", end="", file=sys.stderr)
    print(file=sys.stderr)
    depth_frames.write_text(os.path.join(args.dst, "camera.yml"), camera_text(width, height))
    truth = os.path.join(args.src, "boxes.csv")
    if os.path.exists(truth):
        sx, sy = width / 640.0, height / 480.0
        text = io.StringIO()
        with open(truth) as src:
            rows = csv.reader(src)
            out = csv.writer(text, lineterminator="\n")
            out.writerow(next(rows))
            for row in rows:
                box = scaled([int(v) for v in row[2:6]], sx, sy)
                out.writerow(row[:2] + [str(v) for v in box] + row[6:])
        depth_frames.write_text(os.path.join(args.dst, "boxes.csv"), text.getvalue())


def detections(path):
    frames = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            frames.setdefault(row["frame"], [])
            if row["person"] not in ("", "0"):
                frames[row["frame"]].append(tuple(int(row[k]) for k in ("x", "y", "w", "h")))
    return frames


def compare(args):
    width, height = args.size
    sx, sy = width / 640.0, height / 480.0
    want, got = detections(args.original), detections(args.resized)
    people = found = other = 0
    for frame, boxes in want.items():
        resized = got.get(frame, [])
        used = [False] * len(resized)
        for box in boxes:
            people += 1
            target = scaled(box, sx, sy)
            for k, r in enumerate(resized):
                if not used[k] and iou(r, target) >= 0.7:
                    used[k] = True
                    found += 1
                    break
        other += used.count(False)
    line = f"found {found} of {people}  other {other}"
    if args.truth:
        total = hit_orig = hit_resized = 0
        with open(args.truth) as f:
            for row in csv.DictReader(f):
                box = tuple(int(row[k]) for k in ("x", "y", "w", "h"))
                total += 1
                hit_orig += any(iou(d, box) >= 0.5 for d in want.get(row["frame"], []))
                hit_resized += any(iou(d, scaled(box, sx, sy)) >= 0.5 for d in got.get(row["frame"], []))
        line += f"  labelled {hit_orig} {hit_resized} of {total}"
    print(line)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("resize", help="resize a folder of 640x480 depth frames")
    r.add_argument("src")
    r.add_argument("dst")
    r.add_argument("--size", type=size_arg, required=True)
    c = sub.add_parser("compare", help="the original's detections found again in the resized frames")
    c.add_argument("original")
    c.add_argument("resized")
    c.add_argument("--size", type=size_arg, required=True)
    c.add_argument("--truth", help="boxes.csv of the original frames: also count the labelled people found")
    args = parser.parse_args()
    resize(args) if args.command == "resize" else compare(args)


if __name__ == "__main__":
    main()
