"""What the Python helpers of scripts/ share about rdsf-detect's report by clip: one reader of clips.csv and of
outcomes.csv, the exact curve redone from the latter with weights per clip, one bootstrap over clips, and the
scripts' argument reader.

clips.csv (rdsf-detect --truth --report-dir DIR; docs/detect-and-evaluate.md, "By clip") has a row per model and
clip at the model's operating point: model, clip_frames, probability, clip, frames, people (counted: at least
--min-visible visible), with_candidate, detected, false_positives. outcomes.csv has a row per model and
candidate, score descending: model, clip, score (H(x)), outcome (detection, false_positive, neutral).

The bootstrap draws clips with replacement, as many as there are, 2,000 times from numpy's default_rng(seed):
a clip's people are the same people in the same room frame after frame, so clips, not person-frames, are the
independent units. Rates are pooled per draw (detected / people of the drawn clips); a draw whose clips hold
nobody is left out of a rate's quantiles.

Uses Debian's python3-numpy (scripts/setup.sh installs it).
"""
import csv
import sys

import numpy

COUNTS = ("frames", "people", "with_candidate", "detected", "false_positives")
DRAWS = 2000


class ClipsError(Exception):
    """A clips.csv that cannot be read or does not match: the message names the file and the problem."""


def read_clips(path, model=None):
    """The rows of one model in clips.csv at `path` (the first model listed when `model` is None), in file
    order, each a dict with 'clip' and the integer COUNTS, and the model's label."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        raise ClipsError(f"{path}: {e.strerror}") from None
    if not rows:
        raise ClipsError(f"{path}: no clips")
    label = model if model is not None else rows[0].get("model")
    out = []
    for r in rows:
        if r.get("model") != label:
            continue
        item = {"clip": r.get("clip")}
        for k in COUNTS:
            try:
                item[k] = int(r[k])
            except (KeyError, TypeError, ValueError):
                raise ClipsError(f"{path}: no whole number in column '{k}' of clip {r.get('clip', '?')}") from None
        out.append(item)
    if not out:
        models = sorted({r.get("model") or "" for r in rows})
        raise ClipsError(f"{path}: no clips of model '{label}' (models: {', '.join(models)})")
    if len({c["clip"] for c in out}) != len(out):
        raise ClipsError(f"{path}: clip {out[0]['clip']} of model '{label}' is listed more than once (two models of "
                         "one label in one report: evaluate them in separate runs)")
    return out, label


def read_outcomes(path, model, clip_index):
    """outcomes.csv at `path` (rdsf-detect's report: each candidate's model, clip, score H(x) and outcome, score
    descending) for one model: arrays (clip index by `clip_index`, a dict name -> index; score; kind 1 detection,
    -1 false positive, 0 neutral)."""
    try:
        with open(path, newline="") as f:
            rows = [r for r in csv.DictReader(f) if r.get("model") == model]
    except OSError as e:
        raise ClipsError(f"{path}: {e.strerror}") from None
    kinds = {"detection": 1, "false_positive": -1, "neutral": 0}
    clips, scores, outcome = [], [], []
    for r in rows:
        if r.get("clip") not in clip_index:
            raise ClipsError(f"{path}: clip '{r.get('clip')}' is not in clips.csv")
        if r.get("outcome") not in kinds:
            raise ClipsError(f"{path}: outcome '{r.get('outcome')}' is not detection, false_positive or neutral")
        try:
            scores.append(float(r["score"]))
        except (KeyError, TypeError, ValueError):
            raise ClipsError(f"{path}: no number in column 'score' of a candidate of clip {r.get('clip')}") from None
        clips.append(clip_index[r["clip"]])
        outcome.append(kinds[r["outcome"]])
    return numpy.array(clips, dtype=int), numpy.array(scores, dtype=float), numpy.array(outcome, dtype=int)


class ExactCurve:
    """The exact detection curve of candidates over clips (exact_curve.hpp), weighted per clip: a point at the end
    of each run of equal scores, descending; TAR at FPPF <= x is the TAR of the last point whose false
    positives per frame are within x (they only grow along the curve), 0 when none is. The same reading as
    rdsf-detect's, so with every weight 1 it gives the summary's TAR at FPPF <= x."""

    def __init__(self, clips, scores, kinds, frames, people):
        order = numpy.argsort(-scores, kind="stable")
        self.clips = clips[order]
        sorted_scores = scores[order]
        self.detection = (kinds[order] == 1).astype(float)
        self.false_positive = (kinds[order] == -1).astype(float)
        self.ends = numpy.append(sorted_scores[1:] != sorted_scores[:-1], True) if len(order) else numpy.array([], dtype=bool)
        self.frames = numpy.asarray(frames, dtype=float)
        self.people = numpy.asarray(people, dtype=float)

    def tar_at_fppf(self, weights, limits):
        """TAR at FPPF <= each of `limits` with clip c counted weights[c] times; NaN when the weighted clips hold
        nobody."""
        frames = float(numpy.dot(weights, self.frames))
        people = float(numpy.dot(weights, self.people))
        if frames == 0 or people == 0:
            return [float("nan")] * len(limits)
        w = weights[self.clips]
        detections = numpy.cumsum(w * self.detection)[self.ends]
        fppf = numpy.cumsum(w * self.false_positive)[self.ends] / frames
        out = []
        for max_fppf in limits:
            # false positives only grow along the curve (weights >= 0): the points within the limit come first
            within = int(numpy.count_nonzero(fppf <= max_fppf))
            out.append(float(detections[within - 1] / people) if within else 0.0)
        return out


def draws(n, seed=1):
    """DRAWS rows of n clip indices drawn with replacement."""
    return numpy.random.default_rng(seed).integers(0, n, size=(DRAWS, n))


def quantiles(values):
    """The 2.5 % and 97.5 % quantiles of the finite values, None when there are none."""
    values = values[numpy.isfinite(values)]
    if values.size == 0:
        return None
    return numpy.quantile(values, 0.025), numpy.quantile(values, 0.975)


def pooled_rate(numerators, denominators, picks):
    """Per draw, the sum of the picked numerators over the sum of the picked denominators (NaN where that is 0)."""
    top = numpy.asarray(numerators, dtype=float)[picks].sum(axis=1)
    bottom = numpy.asarray(denominators, dtype=float)[picks].sum(axis=1)
    with numpy.errstate(invalid="ignore", divide="ignore"):
        return numpy.where(bottom > 0, top / bottom, numpy.nan)


def parse_arguments(argv, options, die, doc):
    """The values of argv's options (`options`: each option's name and default, every one taking a value) and
    argv's other words, in order. -h or --help prints `doc` and exits 0, no argument prints it and exits 2; an
    unknown word starting with '-' or an option without its value is a usage error: die(2, message)."""
    if not argv or argv[0] in ("-h", "--help"):
        print(doc.strip())
        sys.exit(0 if argv else 2)
    values = dict(options)
    words = []
    i = 0
    while i < len(argv):
        if argv[i] in values:
            if i + 1 >= len(argv):
                die(2, f"{argv[i]} needs a value")
            values[argv[i]] = argv[i + 1]
            i += 2
        elif argv[i].startswith("-"):
            die(2, f"unknown argument '{argv[i]}'")
        else:
            words.append(argv[i])
            i += 1
    return values, words

