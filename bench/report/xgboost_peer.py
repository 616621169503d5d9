#!/usr/bin/env python3
"""XGBoost as a peer of the native trainer in rdsf-perf-report (issue 17).

Reads the training and held-out matrices the report wrote (8-bit bin indices, feature-major as the native
trainer streams them, so XGBoost sees the same 64-bin quantisation; labels one byte per row), trains
tree_method=hist boosting at the given depth until the time budget or the round limit, and prints one line
per round: "round seconds_since_start held_out_auc". Exit 3 when xgboost or numpy cannot be imported (the
report then says the peer is not installed and skips it).

Usage: xgboost_peer.py FOLDER DEPTH THREADS BUDGET_S MAX_ROUNDS
"""
import os
import sys
import time

try:
    import numpy as np
    import xgboost as xgb
except ImportError as e:  # the report skips this peer
    print("not installed: %s" % e, file=sys.stderr)
    sys.exit(3)


def load(folder, name, features):
    labels = np.fromfile(os.path.join(folder, name + ".labels"), dtype=np.uint8)
    bins = np.fromfile(os.path.join(folder, name + ".bins"), dtype=np.uint8)
    rows = labels.size
    matrix = bins.reshape(features, rows).T  # feature-major on disk
    return np.ascontiguousarray(matrix, dtype=np.float32), labels


def auc(scores, labels):
    order = np.argsort(scores, kind="mergesort")
    ranks = np.empty(len(scores), dtype=np.float64)
    sorted_scores = scores[order]
    # average ranks of ties
    i = 0
    n = len(scores)
    while i < n:
        j = i
        while j + 1 < n and sorted_scores[j + 1] == sorted_scores[i]:
            j += 1
        ranks[order[i:j + 1]] = (i + j) / 2.0 + 1.0
        i = j + 1
    pos = labels == 1
    n_pos = pos.sum()
    n_neg = n - n_pos
    return (ranks[pos].sum() - n_pos * (n_pos + 1) / 2.0) / (n_pos * n_neg)


def main():
    folder, depth, threads, budget, max_rounds = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
    with open(os.path.join(folder, "features")) as f:
        features = int(f.read())
    x, y = load(folder, "train", features)
    vx, vy = load(folder, "held_out", features)
    # The quantised matrix is built before the rounds (as the native trainer bins before its rounds) and
    # its time printed first: "setup SECONDS".
    start = time.perf_counter()
    train = xgb.QuantileDMatrix(x, label=y, max_bin=64, nthread=threads)
    print("setup %.6f" % (time.perf_counter() - start), flush=True)
    held_out = xgb.DMatrix(vx, nthread=threads)
    del x
    params = {"tree_method": "hist", "max_depth": depth, "objective": "binary:logistic", "nthread": threads,
              "max_bin": 64, "eta": 0.3, "verbosity": 0}
    booster = xgb.Booster(params, [train])
    elapsed_training = 0.0
    for r in range(1, max_rounds + 1):
        t = time.perf_counter()
        booster.update(train, r - 1)  # one round, as xgb.train does it
        elapsed_training += time.perf_counter() - t
        # The held-out AUC is not counted in the time, as for the native trainer.
        scores = booster.predict(held_out, output_margin=True)
        print("%d %.6f %.6f" % (r, elapsed_training, auc(scores, vy)), flush=True)
        if elapsed_training >= budget:
            break


if __name__ == "__main__":
    main()
