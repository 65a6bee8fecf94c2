#!/usr/bin/python3
"""glpt tune's plot: time per frame against error for every setting of a tune CSV, the Pareto
front joined by a line.

usage: pareto_plot.py TUNE_CSV OUT_PNG [TITLE]

Reads the CSV `glpt tune` writes (columns setting, frame_ms, flip, relmse, pareto, failure) and
draws two panels, FLIP and relMSE (log scale) against ms per frame (log scale). Needs
python3-matplotlib (Debian); exits with status 1 and a message without it.
"""
import csv
import sys


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("python3-matplotlib is not installed (apt-get install python3-matplotlib)",
              file=sys.stderr)
        return 1
    with open(argv[1], newline="") as f:
        rows = [r for r in csv.DictReader(f) if not r.get("failure")]
    if not rows:
        print("no measured setting in " + argv[1], file=sys.stderr)
        return 1
    title = argv[3] if len(argv) > 3 else rows[0].get("scene", "")
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
    for ax, metric, label in ((axes[0], "flip", "mean FLIP"), (axes[1], "relmse", "relMSE")):
        xs = [float(r["frame_ms"]) for r in rows]
        ys = [max(float(r[metric]), 1e-6) for r in rows]
        on_front = [r["pareto"] == "1" for r in rows]
        ax.scatter([x for x, p in zip(xs, on_front) if not p],
                   [y for y, p in zip(ys, on_front) if not p], c="#888888", s=22, label="setting")
        front = sorted((x, y) for x, y, p in zip(xs, ys, on_front) if p)
        ax.plot([x for x, _ in front], [y for _, y in front], "o-", c="#d62728", ms=6,
                label="Pareto front (FLIP)")
        # Every setting named when there are few; otherwise the front's only (the CSV has all).
        for r, x, y, p in zip(rows, xs, ys, on_front):
            if p or len(rows) <= 20:
                ax.annotate(r["setting"], (x, y), fontsize=7 if p else 6, xytext=(3, 3),
                            textcoords="offset points", color="black" if p else "#555555")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("ms per frame (median)")
        ax.set_ylabel(label + " against the reference")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("glpt tune: " + title)
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
