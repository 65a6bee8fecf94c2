#!/usr/bin/env python3
"""The soak's verdicts (bench/soak.sh; docs/soak.md) from GLPT_STATS files.

usage: soak_report.py [--frames N] [--warmup-fraction F] LABEL=STATS_FILE ...

Per run, after the warm-up (the first F of the frames, default 0.1, at least 100):
  * resident memory (rss_kb): at the end of the warm-up and at the end (medians of 50 frames),
    the growth between them, and the least-squares slope per 1,000 frames;
  * Vulkan objects alive (vk_objects): at the end of the warm-up, the most after it, at the end;
  * frame cost (total_ms, recording to presented): the median after the warm-up, the slowest
    frame, and how many frames took more than 3x the median.
Criteria (printed per run): memory growth after the warm-up at most 1 % of the resident size or
2 MiB, whichever is larger; no Vulkan object count above the warm-up's; no frame over 3x the
median. Prints a Markdown table and the slow frames; exits 0 (a report, not a test).
"""
import argparse
import re
import statistics
import sys

FIELD = re.compile(r" (frame|total_ms|rss_kb|vk_objects)=([-0-9.]+)")


def read_stats(path):
    rows = []
    try:
        with open(path, encoding="utf-8", errors="replace") as stats:
            for line in stats:
                if " frame=" not in line:
                    continue
                fields = dict(FIELD.findall(" " + line))
                if {"total_ms", "rss_kb", "vk_objects"} <= fields.keys():
                    rows.append((float(fields["total_ms"]), int(fields["rss_kb"]),
                                 int(fields["vk_objects"])))
    except OSError as error:
        print(f"soak_report: {path}: {error}", file=sys.stderr)
    return rows


def slope_per_1000(values):
    n = len(values)
    if n < 2:
        return 0.0
    mean_x = (n - 1) / 2
    mean_y = sum(values) / n
    sxx = sum((x - mean_x) ** 2 for x in range(n))
    sxy = sum((x - mean_x) * (y - mean_y) for x, y in enumerate(values))
    return 1000 * sxy / sxx


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--frames", type=int, default=0, help="frames each run was meant to have")
    parser.add_argument("--warmup-fraction", type=float, default=0.1)
    parser.add_argument("runs", nargs="+", help="LABEL=STATS_FILE")
    args = parser.parse_args()

    print("| run | frames | RSS after warm-up | RSS at end | growth | slope /1000 frames "
          "| Vulkan objects (warm-up / max after / end) | median ms | slowest ms (x median) "
          "| frames > 3x median | verdict |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    slow_lists = []
    for run in args.runs:
        label, _, path = run.partition("=")
        rows = read_stats(path)
        if len(rows) < 200:
            print(f"| {label} | {len(rows)} | | | | | | | | | too few frames |")
            continue
        warmup = max(100, int(len(rows) * args.warmup_fraction))
        after = rows[warmup:]
        rss = [r[1] for r in after]
        rss_start = statistics.median(r[1] for r in rows[warmup - 50:warmup])
        rss_end = statistics.median(rss[-50:])
        growth = rss_end - rss_start
        objects_start = rows[warmup - 1][2]
        objects_max = max(r[2] for r in after)
        objects_end = after[-1][2]
        times = [r[0] for r in after]
        median = statistics.median(times)
        slowest = max(range(len(times)), key=lambda i: times[i])
        slow = [(warmup + i, t) for i, t in enumerate(times) if median > 0 and t > 3 * median]
        memory_ok = growth <= max(0.01 * rss_start, 2048)
        objects_ok = objects_max <= objects_start
        verdict = ", ".join(
            ["memory flat" if memory_ok else "MEMORY GROWS",
             "objects flat" if objects_ok else "OBJECTS GROW",
             "no slow frame" if not slow else f"{len(slow)} SLOW FRAMES"])
        short = "" if not args.frames or len(rows) >= args.frames else f" (of {args.frames})"
        print(f"| {label} | {len(rows)}{short} | {rss_start / 1024:.1f} MiB | {rss_end / 1024:.1f} MiB "
              f"| {growth / 1024:+.2f} MiB ({100 * growth / rss_start:+.2f} %) "
              f"| {slope_per_1000(rss):+.1f} KiB | {objects_start} / {objects_max} / {objects_end} "
              f"| {median:.2f} | {times[slowest]:.2f} ({times[slowest] / median if median else 0:.1f}x, "
              f"frame {warmup + slowest}) | {len(slow)} | {verdict} |")
        if slow:
            slow_lists.append((label, median, slow))
    for label, median, slow in slow_lists:
        shown = ", ".join(f"{f} ({t:.1f} ms)" for f, t in slow[:20])
        more = f" and {len(slow) - 20} more" if len(slow) > 20 else ""
        print(f"\n{label}: frames over 3x the median ({median:.2f} ms): {shown}{more}")


if __name__ == "__main__":
    main()
