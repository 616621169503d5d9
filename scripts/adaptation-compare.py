#!/usr/bin/env python3
"""People found, room by room, in runs of scripts/adaptation-benchmark.sh: what its TARs mean in people.

  scripts/adaptation-compare.py RUN                 each mode of one run against the model as given
  scripts/adaptation-compare.py BEFORE AFTER        one mode of two runs of the same rooms (e.g. an option off/on)

Options: --mode M (default track), --budget B (default: the run's largest). A room's people are those counted in
its later frames (the base model's report there: rooms/ROOM/report-people/summary.txt); people found = TAR at
FPPF <= 0.1 x people, rounded. "Lost" sums, over the rooms, the people the model as given found that the adapted
model does not find: max(0, as given - adapted), issue 35's "never worse" in people. Synthetic rooms and the real
ones (lab, home) are summed apart. The switches each run took are listed ("-" when none; "dropped" when its
held-out check kept the model as given without them).
"""
import argparse
import csv
import os
import re
import sys

REAL = ("lab", "home")


def fail(message):
    print("adaptation-compare: " + message, file=sys.stderr)
    sys.exit(2)


def read_run(run):
    path = os.path.join(run, "results.tsv")
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f, delimiter="\t"))
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    if not rows or "tar" not in rows[0] or "room" not in rows[0]:
        fail(f"{path}: not the results of scripts/adaptation-benchmark.sh")
    return rows


def people_of(run, room):
    path = os.path.join(run, "rooms", room, "report-people", "summary.txt")
    try:
        text = open(path).read()
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    m = re.search(r"frames, (\d+) people", text)
    if not m:
        fail(f"{path}: no 'N frames, N people' line")
    return int(m.group(1))


def switches_of(run, room, mode, budget):
    path = os.path.join(run, "rooms", room, f"{mode}-{budget}", "adapt-state.tsv")
    if not os.path.exists(path):
        return ""
    text = open(path).read()
    taken = re.findall(r"^switch\.([a-z-]+)\ton$", text, re.M)
    if not taken:
        return "-"
    dropped = re.search(r"^check\tas given kept$", text, re.M)
    return " ".join(taken) + (" (dropped)" if dropped else "")


def found(rows, room, mode, budget):
    for r in rows:
        if r["room"] == room and r["mode"] == mode and (mode == "none" or r["budget"] == str(budget)):
            return float(r["tar"])
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", metavar="RUN", help="a benchmark's --out folder (one, or two to compare)")
    parser.add_argument("--mode", default="track", help="with two runs: the mode compared (default track)")
    parser.add_argument("--budget", type=int, help="the budget compared (default: the largest in the run)")
    a = parser.parse_args()
    if len(a.runs) > 2:
        fail("give one run, or two to compare")
    runs = [read_run(r) for r in a.runs]
    budgets = sorted({int(r["budget"]) for r in runs[0] if r["mode"] != "none"})
    budget = a.budget if a.budget is not None else (budgets[-1] if budgets else 0)
    rooms = [r["room"] for r in runs[0] if r["mode"] == "none"]
    if len(runs) == 1:
        columns = [(0, m) for m in dict.fromkeys(r["mode"] for r in runs[0]) if m != "none"]
    else:
        columns = [(0, a.mode), (1, a.mode)]
    names = [f"{os.path.basename(a.runs[i].rstrip('/'))} {m}" for i, m in columns]
    print(f"People found at FPPF <= 0.1 on the rooms' later frames (budget {budget}; lost: people the model as given "
          "found that the adapted model does not)")
    print()
    print("| room | people | as given | " + " | ".join(names) + " |")
    print("| --- | --- | --- | " + " | ".join("---" for _ in names) + " |")
    totals = {}
    for room in rooms:
        people = people_of(a.runs[0], room)
        given = round(found(runs[0], room, "none", budget) * people)
        cells = []
        kind = "real" if room in REAL else "synthetic"
        t = totals.setdefault(kind, {"rooms": 0, "people": 0, "given": 0, "found": [0] * len(columns),
                                     "lost": [0] * len(columns)})
        t["rooms"] += 1
        t["people"] += people
        t["given"] += given
        for k, (i, m) in enumerate(columns):
            tar = found(runs[i], room, m, budget)
            if tar is None:
                cells.append("not run")
                continue
            n = round(tar * people)
            t["found"][k] += n
            t["lost"][k] += max(0, given - n)
            sw = switches_of(a.runs[i], room, m, budget)
            cells.append(f"{n}" + (f" [{sw}]" if sw else ""))
        print(f"| {room} | {people} | {given} | " + " | ".join(cells) + " |")
    for kind, t in totals.items():
        cells = [f"**{t['found'][k]}** (lost {t['lost'][k]})" for k in range(len(columns))]
        print(f"| {kind}: {t['rooms']} rooms | {t['people']} | {t['given']} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
