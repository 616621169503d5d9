#!/usr/bin/python3
"""Two runs of rdsf-detect on the same frames, compared paired over their clips: is B better than A?

  scripts/paired-clips.py [--model-a LABEL] [--model-b LABEL] A:B [A:B ...]

  A, B    report folders of `rdsf-detect --truth ... --clip-frames N --report-dir` on the same frames and
          truth (one set per pair), A the "before" (e.g. today's options), B the "after" (another option
          value, another build); their clips.csv must hold the same clips with the same frames and people
  --model-a / --model-b LABEL  the model rows to read (clips.csv's `model` column, e.g. "people v3");
          default: the first model of each file

For each pair and pooled over all pairs' clips it prints candidate recall, TAR at each run's operating point
and false positives per frame for A and B (from clips.csv), TAR at FPPF <= 0.1 and 0.5 (from each run's exact
curve, redone from its outcomes.csv; rdsf-detect writes it since 2026-12-06, older reports have only the first
three rows), and B - A with a 95 % interval paired over the clips: a percentile
bootstrap (2,000 draws of as many clips as there are, with replacement, numpy's default_rng(1)) in which
each draw takes the same clips for A and B, so rooms both find hard cancel and a difference is pinned far
more tightly than either figure. Pooling several renderings (e.g. the six judges of docs/quality.md) gives
one interval over all their rooms; pooled, TAR at FPPF <= x is each set's own (a set is one recording, the
unit of false positives per frame) with the people found summed over the sets, as docs/quality.md's "judges
pooled" are. This is rdsf-detect's
"paired over the same clips" paragraph for two runs that cannot share one rdsf-detect (candidate options,
builds); with outcomes.csv each draw's TAR is read off its own weighted exact curve, as rdsf-detect does.

Exit codes: 0 done, 1 a file that cannot be read or clips that do not match (one line naming the file),
2 a usage error. Uses Debian's python3-numpy (scripts/setup.sh installs it).
"""
import os
import sys

import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
import detect_clips  # noqa: E402


def die(code, message):
    print(f"paired-clips: {message}", file=sys.stderr)
    sys.exit(code)


def read_outcomes(report_dir, model, clips):
    """The model's candidates in report_dir/outcomes.csv as clip indices, scores and kinds; None without the file
    (a report written before rdsf-detect wrote it)."""
    path = os.path.join(report_dir, "outcomes.csv")
    if not os.path.exists(path):
        return None
    try:
        return detect_clips.read_outcomes(path, model, {c["clip"]: i for i, c in enumerate(clips)})
    except detect_clips.ClipsError as e:
        die(1, str(e))


def read_pair(pair, model_a, model_b):
    """The clips of A and B of one A:B pair, checked to be the same clips with the same frames and people, and
    their candidates' outcomes when both reports have them."""
    if pair.count(":") != 1 or "" in pair.split(":"):
        die(2, f"'{pair}' is not A:B (two report folders)")
    a_dir, b_dir = pair.split(":")
    paths = [os.path.join(a_dir, "clips.csv"), os.path.join(b_dir, "clips.csv")]
    try:
        a, label_a = detect_clips.read_clips(paths[0], model_a)
        b, label_b = detect_clips.read_clips(paths[1], model_b)
    except detect_clips.ClipsError as e:
        die(1, str(e))
    if [c["clip"] for c in a] != [c["clip"] for c in b]:
        die(1, f"{paths[1]}: its clips are not those of {paths[0]} (another set or --clip-frames?)")
    for x, y in zip(a, b):
        if (x["frames"], x["people"]) != (y["frames"], y["people"]):
            die(1, f"{paths[1]}: clip {y['clip']} has {y['frames']} frames and {y['people']} people, "
                   f"{paths[0]} {x['frames']} and {x['people']} (another truth or --min-visible?)")
    outcomes = (read_outcomes(a_dir, label_a, a), read_outcomes(b_dir, label_b, b))
    return {"name": pair, "a": a, "b": b, "labels": (label_a, label_b),
            "sets": [(0, len(a), outcomes if None not in outcomes else None)]}


def pooled(runs):
    """The runs as one: their clips in order, and each set's outcomes with the range of its clips (each set keeps
    its own exact curve)."""
    out = {"a": [], "b": [], "sets": []}
    for r in runs:
        offset = len(out["a"])
        out["a"] += r["a"]
        out["b"] += r["b"]
        out["sets"] += [(offset + start, count, outcomes) for start, count, outcomes in r["sets"]]
    if any(outcomes is None for _, _, outcomes in out["sets"]):
        out["sets"] = [(0, len(out["a"]), None)]
    return out


def column(clips, key):
    return numpy.array([c[key] for c in clips], dtype=float)


class PooledCurves:
    """One side's TAR at FPPF <= x over several sets: each set's TAR off its own exact curve (a set is one
    recording, whose false positives per frame the limit is about), people found summed over the sets, as
    docs/quality.md's "judges pooled" are; for one set, its curve's TAR."""

    def __init__(self, sets, side, frames, people):
        self.parts = [(start, count, detect_clips.ExactCurve(*outcomes[side], frames[start:start + count], people[start:start + count]))
                      for start, count, outcomes in sets]
        self.people = people

    def tar_at_fppf(self, weights, limits):
        found = numpy.zeros(len(limits))
        for start, count, curve in self.parts:
            w = weights[start:start + count]
            set_people = float(numpy.dot(w, self.people[start:start + count]))
            if set_people > 0:
                found += numpy.array(curve.tar_at_fppf(w, limits)) * set_people
        total = float(numpy.dot(weights, self.people))
        return found / total if total > 0 else numpy.full(len(limits), numpy.nan)


def figures(run):
    """Rates of A and B and B - A with paired intervals over the clips (None: fewer than two clips); TAR at FPPF
    <= 0.1 and 0.5 from the exact curves when both reports have outcomes.csv."""
    a, b = run["a"], run["b"]
    people, frames = column(a, "people"), column(a, "frames")
    picks = detect_clips.draws(len(a)) if len(a) >= 2 else None
    rows = []
    for name, key, per in (("candidate recall", "with_candidate", people), ("TAR at the operating point", "detected", people),
                           ("false positives per frame", "false_positives", frames)):
        xa, xb = column(a, key), column(b, key)
        total = per.sum()
        ra = xa.sum() / total if total > 0 else float("nan")
        rb = xb.sum() / total if total > 0 else float("nan")
        interval = None if picks is None else detect_clips.quantiles(detect_clips.pooled_rate(xb - xa, per, picks))
        rows.append((name, ra, rb, rb - ra, interval))
    if run["sets"][0][2] is not None:
        curves = [PooledCurves(run["sets"], side, frames, people) for side in (0, 1)]
        limits = (0.1, 0.5)
        point = [c.tar_at_fppf(numpy.ones(len(a)), limits) for c in curves]
        diffs = []
        for p in ([] if picks is None else picks):
            w = numpy.bincount(p, minlength=len(a)).astype(float)
            diffs.append(curves[1].tar_at_fppf(w, limits) - curves[0].tar_at_fppf(w, limits))
        for i, max_fppf in enumerate(limits):
            interval = detect_clips.quantiles(numpy.array([d[i] for d in diffs])) if diffs else None
            rows.append((f"TAR at FPPF <= {max_fppf:g}", point[0][i], point[1][i], point[1][i] - point[0][i], interval))
    return rows


def report(title, run):
    a = run["a"]
    people = int(column(a, "people").sum())
    frames = int(column(a, "frames").sum())
    few = " (few: under 10 clips, read with care)" if len(a) < 10 else ""
    lines = [f"## {title}: {len(a)} clip{'' if len(a) == 1 else 's'}, {frames} frames, {people} people{few}", "",
             "| figure | A | B | B - A (95 % paired over clips) |", "| --- | --- | --- | --- |"]
    for name, ra, rb, d, interval in figures(run):
        span = f"{interval[0]:+.3f} to {interval[1]:+.3f}" if interval else "no interval"
        lines.append(f"| {name} | {ra:.3f} | {rb:.3f} | {d:+.3f} ({span}) |")
    if run["sets"][0][2] is None:
        lines.append("\n(no outcomes.csv in both reports: no TAR at FPPF <= 0.1 / 0.5; rdsf-detect writes it since 2026-12-06)")
    return "\n".join(lines)


def main(argv):
    models, pairs = detect_clips.parse_arguments(argv, {"--model-a": None, "--model-b": None}, die, __doc__)
    if not pairs:
        die(2, "give at least one A:B pair of report folders")
    runs = [read_pair(p, models["--model-a"], models["--model-b"]) for p in pairs]
    label_a, label_b = runs[0]["labels"]
    print(f"A: {label_a} ({', '.join(r['name'].split(':')[0] for r in runs)})")
    print(f"B: {label_b} ({', '.join(r['name'].split(':')[1] for r in runs)})\n")
    for r in runs:
        print(report(r["name"], r) + "\n")
    if len(runs) > 1:
        print(report(f"pooled over the {len(runs)} sets", pooled(runs)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
