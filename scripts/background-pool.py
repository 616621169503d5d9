#!/usr/bin/env python3
"""Pools rdsf-detect reports of several parts of one set (clips evaluated apart, each with its own background
model) into the figures of the whole set: candidate recall, TAR at FPPF <= 0.1 and <= 0.5 from the exact
curves, false positives per frame there, with 95 % Wilson intervals over people.

usage: background-pool.py LABEL PART_DIR...   (each PART_DIR holds report/curve.csv and detect.err)

The pooled curve: at every score threshold h that occurs in a part's curve.csv, each part contributes the
row with the smallest threshold >= h (its detections and false positives at h; none when it has no such
row); TAR = sum n_det / sum n_people, FPPF = sum n_fp / sum n_frames. TAR at FPPF <= x is the largest TAR
of a threshold whose FPPF <= x (as rdsf-detect's own exact curve, which this equals for one part).
"""
import csv
import math
import re
import sys


def wilson(k, n, z=1.959964):
    if n == 0:
        return (0.0, 0.0)
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / d
    return (max(0.0, c - h), min(1.0, c + h))


def read_part(folder):
    rows = []
    frames = people = 0
    with open(folder + "/report/curve.csv") as f:
        for r in csv.DictReader(f):
            rows.append((float(r["threshold"]), int(r["n_det"]), int(r["n_fp"])))
            frames, people = int(r["n_frames"]), int(r["n_people"])
    rows.sort(key=lambda r: -r[0])  # descending thresholds: counts grow
    text = open(folder + "/detect.err").read()
    m = re.search(r"(\d+) of (\d+) people have a candidate", text)
    found, asked = (int(m.group(1)), int(m.group(2))) if m else (0, 0)
    t = re.search(r"per frame: segmentation ([\d.]+) ms, candidates ([\d.]+) ms", text)
    f = re.search(r"rdsf-detect: (\d+) frames, ([\d.]+) candidates per frame", text)
    seg, cand = (float(t.group(1)), float(t.group(2))) if t else (0.0, 0.0)
    nframes, cpf = (int(f.group(1)), float(f.group(2))) if f else (0, 0.0)
    if frames == 0:  # no curve rows (no candidate scored): frames from the log
        frames = nframes
    return {"rows": rows, "frames": frames, "people": people, "found": found, "asked": asked,
            "seg_ms": seg * nframes, "cand_ms": cand * nframes, "candidates": cpf * nframes, "nframes": nframes}


def at(part, h):
    best = (0, 0)
    for threshold, det, fp in part["rows"]:
        if threshold >= h:
            best = (det, fp)
        else:
            break
    return best


def main():
    label, folders = sys.argv[1], sys.argv[2:]
    parts = [read_part(f) for f in folders]
    frames = sum(p["frames"] for p in parts)
    people = sum(p["people"] for p in parts)
    thresholds = sorted({r[0] for p in parts for r in p["rows"]}, reverse=True)
    best = {0.1: (0, 0, None), 0.5: (0, 0, None)}
    for h in thresholds:
        det = fp = 0
        for p in parts:
            d, f = at(p, h)
            det += d
            fp += f
        for x in best:
            if frames and fp / frames <= x and det > best[x][0]:
                best[x] = (det, fp, h)
    found = sum(p["found"] for p in parts)
    asked = sum(p["asked"] for p in parts)
    nframes = sum(p["nframes"] for p in parts)
    ms = (sum(p["seg_ms"] for p in parts) + sum(p["cand_ms"] for p in parts)) / max(1, nframes)
    cpf = sum(p["candidates"] for p in parts) / max(1, nframes)
    out = [label, str(frames), str(people)]
    lo, hi = wilson(found, asked)
    out.append("%.3f (%.2f-%.2f) [%d/%d]" % (found / asked if asked else 0, lo, hi, found, asked))
    for x in (0.1, 0.5):
        det, fp, h = best[x]
        lo, hi = wilson(det, people)
        out.append("%.3f (%.2f-%.2f) [%d; FP/frame %.3f]" % (det / people if people else 0, lo, hi, det,
                                                              fp / frames if frames else 0))
    out.append("%.2f cand/frame" % cpf)
    out.append("%.2f ms seg+cand" % ms)
    print(" | ".join(out))


if __name__ == "__main__":
    main()
