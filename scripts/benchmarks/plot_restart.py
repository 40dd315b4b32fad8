#!/usr/bin/python3
"""Plots of doc/tutorials/step-9-restart: the DCB load-opening curve of the
uninterrupted run against the run stopped at step 65 and resumed (from the
ctest restart/dcb_2d's folders), and the checkpoint cost against the mesh
size (doc/benchmarks/checkpoint_cost.csv).
usage: plot_restart.py RESTART_DCB_DIR COST.csv OUT.png"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    folder, cost_path, out = sys.argv[1:4]
    whole = table(folder + "/whole/history.csv")
    split = table(folder + "/split/history.csv")
    stop = 65
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    left.plot(whole["time"], whole["force_x-"], "k-", lw=3, alpha=0.3,
              label="uninterrupted")
    first = [i for i, s in enumerate(split["step"]) if s <= stop]
    later = [i for i, s in enumerate(split["step"]) if s > stop]
    left.plot([split["time"][i] for i in first],
              [split["force_x-"][i] for i in first], "b.", ms=4,
              label="first job (stopped after step %d)" % stop)
    left.plot([split["time"][i] for i in later],
              [split["force_x-"][i] for i in later], "r.", ms=4,
              label="second job (amfrac --resume)")
    left.set_xlabel("opening [mm]")
    left.set_ylabel("load per width [N/mm]")
    left.set_title("DCB: stopped and resumed")
    left.legend(fontsize=8)

    cost = list(csv.DictReader(open(cost_path)))
    for scene, marker in (("impact", "o"), ("dcb", "s")):
        rows = [r for r in cost if r["scene"] == scene]
        n = [float(r["unknowns"]) for r in rows]
        right.loglog(n, [float(r["write_s_median"]) for r in rows],
                     marker + "-", label=scene + ": write")
        right.loglog(n, [float(r["read_s"]) for r in rows],
                     marker + "--", label=scene + ": read")
    right.set_xlabel("unknowns")
    right.set_ylabel("seconds per checkpoint")
    right.set_title("checkpoint cost (1 rank)")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
