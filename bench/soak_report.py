#!/usr/bin/env python3
"""The soak's verdicts (bench/soak.sh; docs/soak.md) from GLPT_STATS files.

usage: soak_report.py [--frames N] [--warmup-fraction F] LABEL=STATS_FILE ...

Per run, after the warm-up: the first pass where the stats hold several (a replay with
--repeat: its frame numbers start again at 0 with each new context, and the first pass has met
every state the trace has), else the first F of the frames (default 0.1, at least 100):
  * resident memory (rss_kb): at the end of the warm-up and at the end (medians of 50 frames),
    the growth between them, and the least-squares slope per 1,000 frames;
  * Vulkan objects alive (vk_objects): the most during the warm-up, the most after it, at the
    end; where the count grows, the kinds that grew (vk_by_kind);
  * draws per frame: the most during the warm-up and after it (memory that grows only when a
    frame larger than any before arrives is the working set of the largest frame, not a leak);
  * for replays, at the end of each pass: resident memory, the C heap in use (heap_kb) and the
    free memory malloc keeps (heap_free_kb), and resident memory less that free memory (a leak
    grows the heap in use pass after pass; fragmentation grows only what malloc keeps free);
  * frame cost (total_ms, recording to presented): the median after the warm-up, the slowest
    frame, and how many frames took more than 3x the median, apart from those that compiled
    pipelines (pipelines_created > 0: a new state's first draw, a new context's first frames),
    which are listed on their own. A replay's frames differ in content (a menu, then the game):
    its frames after the first pass are also compared with the median of the same frame over
    those passes, which separates a stall from a frame whose content costs more.
Criteria (printed per run): memory growth after the warm-up at most 1 % of the resident size or
2 MiB, whichever is larger; no Vulkan object count above the warm-up's most; no frame over 3x the
median that did not compile a pipeline. Prints a Markdown table and the slow frames; exits 0 (a
report, not a test).
"""
import argparse
import collections
import re
import statistics
import sys

FIELD = re.compile(
    r" (frame|total_ms|rss_kb|vk_objects|pipelines_created|draws|heap_kb|heap_free_kb)=([-0-9.]+)")
KINDS = re.compile(r" vk_by_kind=(\S+)")


Row = collections.namedtuple("Row", "frame ms rss objects pipelines kinds draws heap heap_free")


def parse_kinds(text):  # "buffer:9,memory:35,..." (or "none")
    kinds = {}
    for item in text.split(","):
        name, _, count = item.partition(":")
        if count.isdigit():
            kinds[name] = int(count)
    return kinds


def read_stats(path):
    rows = []
    try:
        with open(path, encoding="utf-8", errors="replace") as stats:
            for line in stats:
                if " frame=" not in line:
                    continue
                fields = dict(FIELD.findall(" " + line))
                if {"frame", "total_ms", "rss_kb", "vk_objects"} <= fields.keys():
                    kinds = KINDS.search(line)
                    rows.append(Row(int(fields["frame"]), float(fields["total_ms"]),
                                    int(fields["rss_kb"]), int(fields["vk_objects"]),
                                    int(fields.get("pipelines_created", 0)),
                                    parse_kinds(kinds.group(1)) if kinds else {},
                                    int(fields.get("draws", 0)), int(fields.get("heap_kb", 0)),
                                    int(fields.get("heap_free_kb", 0))))
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


def same_frame_stalls(rows, pass_starts):
    """Frames after the first pass over 3x the median of the same frame in those passes."""
    starts = [0] + pass_starts
    length = min(b - a for a, b in zip(starts, starts[1:] + [len(rows)]))
    later = starts[1:]
    if len(later) < 2 or length == 0:
        return "too few passes to compare frames with themselves"
    stalls, worst = [], (0.0, 0)
    for f in range(length):
        times = [rows[s + f].ms for s in later]
        median = statistics.median(times)
        for s in later:
            row = rows[s + f]
            ratio = row.ms / median if median > 0 else 0.0
            if row.pipelines == 0 and ratio > worst[0]:
                worst = (ratio, s + f)
            if ratio > 3 and row.pipelines == 0:
                stalls.append((s + f, row.ms, median))
    shown = ", ".join(f"{i} ({ms:.1f} ms against {m:.1f})" for i, ms, m in stalls[:20])
    return (f"frames over 3x the median of the same frame in passes 2-{len(starts)} (not "
            f"compiling): {len(stalls)}{': ' + shown if stalls else ''}; the most, "
            f"{worst[0]:.2f}x (frame {worst[1]})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--frames", type=int, default=0, help="frames each run was meant to have")
    parser.add_argument("--warmup-fraction", type=float, default=0.1)
    parser.add_argument("runs", nargs="+", help="LABEL=STATS_FILE")
    args = parser.parse_args()

    print("| run | frames | warm-up | RSS after warm-up | RSS at end | growth | slope /1000 frames "
          "| most draws per frame (warm-up / after) | Vulkan objects (warm-up's most / most after / end) | median ms "
          "| slowest ms (x median) | frames > 3x median (not compiling) | compiling | verdict |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    slow_lists = []
    growth_notes = []
    pass_notes = []
    same_frame_notes = []
    for run in args.runs:
        label, _, path = run.partition("=")
        rows = read_stats(path)
        if len(rows) < 200:
            print(f"| {label} | {len(rows)} | | | | | | | | | | | | too few frames |")
            continue
        # A new pass (context) starts where the frame number drops.
        pass_starts = [i for i in range(1, len(rows)) if rows[i].frame < rows[i - 1].frame]
        passes = len(pass_starts) + 1
        if pass_starts:
            warmup = pass_starts[0]
        else:
            warmup = max(100, int(len(rows) * args.warmup_fraction))
        after = rows[warmup:]
        rss = [r.rss for r in after]
        rss_start = statistics.median(r.rss for r in rows[max(0, warmup - 50):warmup])
        rss_end = statistics.median(rss[-50:])
        growth = rss_end - rss_start
        objects_start = max(r.objects for r in rows[:warmup])
        objects_max = max(r.objects for r in after)
        objects_end = after[-1].objects
        times = [r.ms for r in after]
        median = statistics.median(times)
        slowest = max(range(len(times)), key=lambda i: times[i])
        slow = [(warmup + i, r.ms) for i, r in enumerate(after)
                if median > 0 and r.ms > 3 * median and r.pipelines == 0]
        compiling = [(warmup + i, r.ms) for i, r in enumerate(after)
                     if median > 0 and r.ms > 3 * median and r.pipelines > 0]
        memory_ok = growth <= max(0.01 * rss_start, 2048)
        objects_ok = objects_max <= objects_start
        if not objects_ok:
            most = {}
            for r in rows[:warmup]:
                for kind, count in r.kinds.items():
                    most[kind] = max(most.get(kind, 0), count)
            grown = {}
            for r in after:
                for kind, count in r.kinds.items():
                    if count > most.get(kind, 0):
                        grown[kind] = max(grown.get(kind, 0), count)
            growth_notes.append((label, ", ".join(
                f"{kind} {most.get(kind, 0)} -> {count}" for kind, count in sorted(grown.items()))))
        verdict = ", ".join(
            ["memory flat" if memory_ok else "MEMORY GROWS",
             "objects flat" if objects_ok else "OBJECTS GROW",
             "no slow frame" if not slow else f"{len(slow)} SLOW FRAMES"])
        short = "" if not args.frames or len(rows) >= args.frames else f" (of {args.frames})"
        warmup_text = f"pass 1 of {passes}" if pass_starts else f"{warmup} frames"
        draws_text = f"{max(r.draws for r in rows[:warmup])} / {max(r.draws for r in after)}"
        if pass_starts:
            ends = [rows[s - 1] for s in pass_starts] + [rows[-1]]
            pass_notes.append((label, "; ".join(
                f"{e.rss / 1024:.1f} / {e.heap / 1024:.1f} / {e.heap_free / 1024:.1f} / "
                f"{(e.rss - e.heap_free) / 1024:.1f}" for e in ends)))
            same_frame_notes.append((label, same_frame_stalls(rows, pass_starts)))
        print(f"| {label} | {len(rows)}{short} | {warmup_text} | {rss_start / 1024:.1f} MiB "
              f"| {rss_end / 1024:.1f} MiB "
              f"| {growth / 1024:+.2f} MiB ({100 * growth / rss_start:+.2f} %) "
              f"| {slope_per_1000(rss):+.1f} KiB | {draws_text} "
              f"| {objects_start} / {objects_max} / {objects_end} "
              f"| {median:.2f} | {times[slowest]:.2f} ({times[slowest] / median if median else 0:.1f}x, "
              f"frame {warmup + slowest}) | {len(slow)} | {len(compiling)} | {verdict} |")
        if slow:
            slow_lists.append((label, median, "frames over 3x the median", slow))
        if compiling:
            slow_lists.append((label, median, "frames over 3x the median that compiled pipelines",
                               compiling))
    for label, median, what, slow in slow_lists:
        shown = ", ".join(f"{f} ({t:.1f} ms)" for f, t in slow[:20])
        more = f" and {len(slow) - 20} more" if len(slow) > 20 else ""
        print(f"\n{label}: {what} ({median:.2f} ms): {shown}{more}")
    for label, grown in growth_notes:
        print(f"\n{label}: Vulkan objects past the warm-up's most: {grown}")
    for label, ends in pass_notes:
        print(f"\n{label}: at the end of each pass, MiB (resident / heap in use / "
              f"free heap kept by malloc / resident less that): {ends}")
    for label, note in same_frame_notes:
        print(f"\n{label}: {note}")


if __name__ == "__main__":
    main()
