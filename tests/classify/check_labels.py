#!/usr/bin/env python3
"""check_labels.py: compares the classes that labelled GL programs mean (tests/classify/programs,
printed as `LABEL <frame> <class> <key>` lines on stdout) with the classes glpt logs for their
draws (GLPT_CLASSIFY_LOG: one JSON object a line, {"frame": F, "class": C, "calls": K, "id": I}).

Usage:
  check_labels.py --program BIN --libgl LIBGL [--min-accuracy 0.99] [--report FILE] [--keep DIR]
  check_labels.py --programs BIN1 BIN2 ... --libgl LIBGL [same options]
  check_labels.py --labels LABELS.txt --log LOG.jsonl [--min-accuracy ...] [--report FILE]
  check_labels.py --labels-only [--count-shim LIB] --programs BIN1 ...
      (run on the system libGL, without glpt: check the labels alone; with --count-shim, the
      count_draws library preloaded, also that every frame has one label per drawing command)

Program modes run each BIN with LD_PRELOAD=LIBGL GLPT_CLASSIFY_LOG=<temporary file>
GLPT_MODE=raster GLPT_QUIET=1 (an LD_PRELOAD already set, such as scripts/sanitize.sh's sanitizer
runtimes, stays after LIBGL; an empty LIBGL runs it on the system libGL, without preload) and
take the labels from its stdout. The offline mode (--labels, --log) reads both from files: it
is how the checker itself is tested (check_labels_selftest.py).

Comparison, frame by frame: each log entry stands for `calls` consecutive drawing commands, so
it is expanded into `calls` copies and zipped, in order, with that frame's labels. If the counts
differ, every label of the frame counts as wrong (and the frame is reported). Accuracy = labels
whose class matches / all labels. Identity: one key must map to one id over all the frames it
appears in, and two different log entries of one frame must never share an id. Log entries in a
frame without any label are reported as unexpected draws.

Exit status: 0 pass; 1 aggregate accuracy < --min-accuracy, an identity error or unexpected
draws; 2 harness error (a program failed or crashed, wrote no log, or printed no or malformed
labels; a malformed log; bad arguments).
"""

import argparse
import collections
import json
import os
import shutil
import subprocess
import sys
import tempfile

CLASSES = ("static", "moving", "deforming", "blended", "particles", "multipass", "decal",
           "overlay", "sky", "shadow", "viewmodel")
MISMATCHES_SHOWN = 10


class HarnessError(Exception):
    """The comparison cannot be made (not a classification failure)."""


Entry = collections.namedtuple("Entry", "cls calls id line")
Mismatch = collections.namedtuple("Mismatch", "frame key expected got")


def parse_labels(text, source):
    """LABEL lines of a program's stdout -> {frame: [(class, key), ...]} in order."""
    frames = collections.OrderedDict()
    keys_seen = collections.defaultdict(set)
    for number, line in enumerate(text.splitlines(), 1):
        if not line.startswith("LABEL "):
            continue
        fields = line.split()
        where = f"{source}:{number}"
        if len(fields) != 4:
            raise HarnessError(f"{where}: malformed label line: {line!r}")
        _, frame_text, cls, key = fields
        try:
            frame = int(frame_text)
        except ValueError:
            raise HarnessError(f"{where}: frame is not an integer: {line!r}") from None
        if frame < 0:
            raise HarnessError(f"{where}: negative frame: {line!r}")
        if cls not in CLASSES:
            raise HarnessError(f"{where}: unknown class {cls!r}")
        if key in keys_seen[frame]:
            raise HarnessError(f"{where}: key {key!r} labelled twice in frame {frame}")
        keys_seen[frame].add(key)
        frames.setdefault(frame, []).append((cls, key))
    return frames


def _integer(value):
    return isinstance(value, int) and not isinstance(value, bool)


def parse_log(text, source):
    """GLPT_CLASSIFY_LOG contents -> {frame: [Entry, ...]} in file order."""
    frames = collections.OrderedDict()
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        where = f"{source}:{number}"
        try:
            obj = json.loads(line)
        except ValueError as error:
            raise HarnessError(f"{where}: not JSON ({error}): {line[:200]!r}") from None
        if not isinstance(obj, dict):
            raise HarnessError(f"{where}: not a JSON object: {line[:200]!r}")
        missing = [name for name in ("frame", "class", "calls", "id") if name not in obj]
        if missing:
            raise HarnessError(f"{where}: missing {', '.join(missing)}: {line[:200]!r}")
        frame, cls, calls, ident = obj["frame"], obj["class"], obj["calls"], obj["id"]
        if not _integer(frame) or frame < 0:
            raise HarnessError(f"{where}: frame must be an integer >= 0: {line[:200]!r}")
        if not isinstance(cls, str):
            raise HarnessError(f"{where}: class must be a string: {line[:200]!r}")
        if not _integer(calls) or calls < 1:
            raise HarnessError(f"{where}: calls must be an integer >= 1: {line[:200]!r}")
        if not _integer(ident) or ident < 0:
            raise HarnessError(f"{where}: id must be an unsigned integer: {line[:200]!r}")
        frames.setdefault(frame, []).append(Entry(cls, calls, ident, number))
    return frames


class Result:
    def __init__(self, name):
        self.name = name
        self.commands = 0
        self.right = 0
        self.mismatches = []        # Mismatch, in frame order
        self.count_mismatches = []  # (frame, labels, logged calls)
        self.id_errors = []         # strings
        self.unexpected = []        # (frame, logged calls) for frames without labels
        self.confusion = collections.Counter()  # (expected, got) -> count
        self.harness_error = None

    @property
    def accuracy(self):
        return self.right / self.commands if self.commands else 0.0

    def failed(self):
        return bool(self.harness_error or self.id_errors or self.unexpected
                    or self.right != self.commands)


def compare(name, labels, log):
    """Compares parsed labels with a parsed log; returns a Result."""
    result = Result(name)
    result.commands = sum(len(v) for v in labels.values())
    ids_of_key = collections.defaultdict(collections.OrderedDict)  # key -> {id: first frame}
    for frame in sorted(set(labels) | set(log)):
        frame_labels = labels.get(frame, [])
        entries = log.get(frame, [])
        owner = {}
        for index, entry in enumerate(entries):
            if entry.id in owner:
                other = entries[owner[entry.id]]
                result.id_errors.append(
                    f"frame {frame}: two log entries share id {entry.id} (log lines "
                    f"{other.line} and {entry.line})")
            else:
                owner[entry.id] = index
        expanded = [entry for entry in entries for _ in range(entry.calls)]
        if not frame_labels:
            result.unexpected.append((frame, len(expanded)))
            continue
        if len(expanded) != len(frame_labels):
            result.count_mismatches.append((frame, len(frame_labels), len(expanded)))
            got = f"(frame has {len(frame_labels)} labels, log {len(expanded)} calls)"
            for cls, key in frame_labels:
                result.mismatches.append(Mismatch(frame, key, cls, got))
                result.confusion[(cls, "<count>")] += 1
            continue
        for (cls, key), entry in zip(frame_labels, expanded):
            result.confusion[(cls, entry.cls)] += 1
            if entry.cls == cls:
                result.right += 1
            else:
                result.mismatches.append(Mismatch(frame, key, cls, entry.cls))
            ids_of_key[key].setdefault(entry.id, frame)
    for key, ids in ids_of_key.items():
        if len(ids) > 1:
            changes = ", ".join(f"id {ident} from frame {frame}" for ident, frame in ids.items())
            result.id_errors.append(f"key {key}: {changes}")
    return result


def read_text(path, what):
    try:
        with open(path, encoding="utf-8", errors="replace") as file:
            return file.read()
    except OSError as error:
        raise HarnessError(f"cannot read {what} {path}: {error.strerror}") from None


def parse_counts(text, source):
    """count_draws output -> {frame: drawing commands}."""
    counts = {}
    for number, line in enumerate(text.splitlines(), 1):
        fields = line.split()
        if len(fields) == 3 and fields[0] == "COUNT":
            counts[int(fields[1])] = int(fields[2])
        elif line.strip():
            raise HarnessError(f"{source}:{number}: {line}")
    return counts


def run_program(binary, libgl, keep, timeout, labels_only, count_shim=None):
    """Runs one program; returns (labels, log or None). With labels_only and count_shim, checks
    the labels' count per frame against the drawing commands count_draws counted."""
    name = os.path.basename(binary)
    env = dict(os.environ)
    env.pop("GLPT_CLASSIFY_LOG", None)
    inherited = env.get("LD_PRELOAD", "")  # e.g. the sanitizer runtimes (scripts/sanitize.sh)

    def preload(library):
        env["LD_PRELOAD"] = library + (":" + inherited if inherited else "")

    tmp = tempfile.mkdtemp(prefix="glpt-classify-")
    try:
        log_path = os.path.join(tmp, "classify.jsonl")
        count_path = os.path.join(tmp, "counts.txt")
        if labels_only and count_shim:
            preload(count_shim)
            env["CLASSIFY_COUNT_LOG"] = count_path
        if not labels_only:
            if libgl:
                preload(libgl)
            env["GLPT_CLASSIFY_LOG"] = log_path
            env["GLPT_MODE"] = "raster"
            env["GLPT_QUIET"] = "1"
        try:
            proc = subprocess.run([binary], env=env, stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, timeout=timeout, check=False)
        except subprocess.TimeoutExpired:
            raise HarnessError(f"{name}: did not finish in {timeout} s") from None
        except OSError as error:
            raise HarnessError(f"{name}: cannot run: {error.strerror}") from None
        stdout = proc.stdout.decode("utf-8", errors="replace")
        stderr = proc.stderr.decode("utf-8", errors="replace")
        if keep:
            os.makedirs(keep, exist_ok=True)
            with open(os.path.join(keep, name + ".labels.txt"), "w", encoding="utf-8") as out:
                out.write(stdout)
            with open(os.path.join(keep, name + ".stderr.txt"), "w", encoding="utf-8") as out:
                out.write(stderr)
            if os.path.exists(log_path):
                shutil.copyfile(log_path, os.path.join(keep, name + ".jsonl"))
        if proc.returncode != 0:
            how = (f"was killed by signal {-proc.returncode}" if proc.returncode < 0
                   else f"exited with status {proc.returncode}")
            tail = "\n".join(stderr.strip().splitlines()[-5:])
            raise HarnessError(f"{name}: {how}" + (f"; stderr:\n{tail}" if tail else ""))
        labels = parse_labels(stdout, name + " stdout")
        if not labels:
            raise HarnessError(f"{name}: printed no labels")
        if labels_only:
            if count_shim:
                if not os.path.exists(count_path):
                    raise HarnessError(f"{name}: count_draws wrote no counts")
                counts = parse_counts(read_text(count_path, "counts"), name + " counts")
                wrong = [f"frame {f}: {len(labels.get(f, []))} labels, {counts.get(f, 0)} "
                         f"drawing commands" for f in sorted(set(counts) | set(labels))
                         if len(labels.get(f, [])) != counts.get(f, 0)]
                if wrong:
                    raise HarnessError(f"{name}: labels do not match the drawing commands: "
                                       + "; ".join(wrong[:5]))
            return labels, None
        if not os.path.exists(log_path):
            raise HarnessError(f"{name}: wrote no classification log (GLPT_CLASSIFY_LOG)")
        return labels, parse_log(read_text(log_path, "log"), name + " log")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def check_labels_only(name, labels):
    """Checks of a program's labels alone: a Result whose commands are all counted right."""
    result = Result(name)
    result.commands = result.right = sum(len(v) for v in labels.values())
    # Frames may go unlabelled (a frame that draws nothing); count_draws checks each frame's
    # labels against its drawing commands, so an unlabelled frame drew nothing.
    frames = sorted(labels)
    if not frames or frames[0] != 0 or len(frames) < 4:
        result.harness_error = (f"{name}: labelled frames {frames} (want frame 0 and at least 4 "
                                "labelled frames)")
    return result


def table(results):
    width = max([len("program"), len("TOTAL")] + [len(r.name) for r in results])
    lines = [f"{'program':<{width}}  {'commands':>8}  {'right':>6}  {'accuracy':>8}  "
             f"{'id errors':>9}  status"]
    for r in results:
        status = "ERROR" if r.harness_error else ("FAIL" if r.failed() else "ok")
        accuracy = "-" if r.harness_error else f"{100.0 * r.accuracy:.2f}%"
        lines.append(f"{r.name:<{width}}  {r.commands:>8}  {r.right:>6}  {accuracy:>8}  "
                     f"{len(r.id_errors):>9}  {status}")
    commands = sum(r.commands for r in results if not r.harness_error)
    right = sum(r.right for r in results if not r.harness_error)
    ids = sum(len(r.id_errors) for r in results)
    accuracy = f"{100.0 * right / commands:.2f}%" if commands else "-"
    lines.append(f"{'TOTAL':<{width}}  {commands:>8}  {right:>6}  {accuracy:>8}  {ids:>9}")
    return lines


def details(results, limit):
    """Per-program problems: harness errors, count mismatches, mismatches, id errors."""
    lines = []
    for r in results:
        if not r.failed():
            continue
        lines.append("")
        lines.append(f"== {r.name}")
        if r.harness_error:
            lines.append(f"  harness error: {r.harness_error}")
            continue
        for frame, labelled, logged in r.count_mismatches[:limit]:
            lines.append(f"  frame {frame}: {labelled} labels but the log covers {logged} calls "
                         f"(all of the frame's labels count as wrong)")
        for frame, logged in r.unexpected[:limit]:
            lines.append(f"  frame {frame}: {logged} logged calls in a frame without labels")
        shown = r.mismatches[:limit]
        if shown:
            more = len(r.mismatches) - len(shown)
            lines.append(f"  mismatches ({len(r.mismatches)}"
                         + (f", first {len(shown)}" if more > 0 else "") + "):")
            lines.append(f"    {'frame':>5}  {'key':<24} {'expected':<10} got")
            for m in shown:
                lines.append(f"    {m.frame:>5}  {m.key:<24} {m.expected:<10} {m.got}")
        for error in r.id_errors[:limit]:
            lines.append(f"  id error: {error}")
        if len(r.id_errors) > limit:
            lines.append(f"  ... {len(r.id_errors) - limit} more id errors")
    return lines


def per_class(results):
    """Labels and right answers per expected class (recall), over all programs compared."""
    labels, right = collections.Counter(), collections.Counter()
    for r in results:
        for (expected, got), n in r.confusion.items():
            labels[expected] += n
            if expected == got:
                right[expected] += n
    if not labels:
        return []
    lines = ["", f"{'class':<10}  {'labels':>6}  {'right':>6}  {'recall':>8}"]
    for cls in CLASSES:
        if labels[cls]:
            lines.append(f"{cls:<10}  {labels[cls]:>6}  {right[cls]:>6}  "
                         f"{100.0 * right[cls] / labels[cls]:>7.2f}%")
    return lines


def confusion(results):
    total = collections.Counter()
    for r in results:
        total.update(r.confusion)
    wrong = {pair: n for pair, n in total.items() if pair[0] != pair[1]}
    if not wrong:
        return []
    lines = ["", "confusions (expected -> got: count):"]
    for (expected, got), n in sorted(wrong.items(), key=lambda item: (-item[1], item[0])):
        lines.append(f"  {expected} -> {got}: {n}")
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Compare labelled programs' intended draw classes with GLPT_CLASSIFY_LOG.")
    parser.add_argument("--program", help="one labelled program to run")
    parser.add_argument("--programs", nargs="+", metavar="BIN", help="labelled programs to run")
    parser.add_argument("--libgl", help="glpt's libGL.so.1 to preload ('' = none)")
    parser.add_argument("--labels", help="offline mode: a program's stdout (LABEL lines)")
    parser.add_argument("--log", help="offline mode: the GLPT_CLASSIFY_LOG file")
    parser.add_argument("--labels-only", action="store_true",
                        help="run the programs without glpt and check their labels only")
    parser.add_argument("--count-shim", metavar="LIB",
                        help="with --labels-only: count_draws library to preload (checks that "
                             "every drawing command has one label)")
    parser.add_argument("--min-accuracy", type=float, default=0.99)
    parser.add_argument("--report", help="write the full report (every mismatch) to FILE")
    parser.add_argument("--keep", metavar="DIR", help="keep each program's labels, log, stderr")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per program")
    args = parser.parse_args(argv)

    binaries = ([args.program] if args.program else []) + (args.programs or [])
    offline = args.labels is not None or args.log is not None
    if offline == bool(binaries):
        parser.error("give either --labels and --log, or --program / --programs")
    if offline and (args.labels is None or args.log is None):
        parser.error("the offline mode needs both --labels and --log")
    if args.count_shim and not args.labels_only:
        parser.error("--count-shim goes with --labels-only")
    if args.count_shim and not os.path.isfile(args.count_shim):
        print(f"check_labels: count shim not found: {args.count_shim}", file=sys.stderr)
        return 2
    if binaries and not args.labels_only:
        if args.libgl is None:
            parser.error("--libgl is required to run programs (use --labels-only without glpt)")
        if args.libgl and not os.path.isfile(args.libgl):
            print(f"check_labels: LIBGL not found: {args.libgl}", file=sys.stderr)
            return 2

    results = []
    if offline:
        name = os.path.basename(args.labels)
        result = Result(name)
        try:
            labels = parse_labels(read_text(args.labels, "labels"), args.labels)
            if not labels:
                raise HarnessError(f"{args.labels}: no labels")
            log = parse_log(read_text(args.log, "log"), args.log)
            result = compare(name, labels, log)
        except HarnessError as error:
            result.harness_error = str(error)
        results.append(result)
    else:
        libgl = os.path.abspath(args.libgl) if args.libgl else ""
        for binary in binaries:
            name = os.path.basename(binary)
            try:
                labels, log = run_program(
                    binary, libgl, args.keep, args.timeout, args.labels_only,
                    os.path.abspath(args.count_shim) if args.count_shim else None)
                result = (check_labels_only(name, labels) if args.labels_only
                          else compare(name, labels, log))
            except HarnessError as error:
                result = Result(name)
                result.harness_error = str(error)
            results.append(result)

    summary = table(results)
    print("\n".join(summary + details(results, MISMATCHES_SHOWN) + per_class(results)
                    + confusion(results)))
    if args.report:
        with open(args.report, "w", encoding="utf-8") as out:
            out.write("\n".join(summary + details(results, 10 ** 9) + per_class(results)
                                 + confusion(results)) + "\n")

    if any(r.harness_error for r in results):
        print("check_labels: harness error", file=sys.stderr)
        return 2
    commands = sum(r.commands for r in results)
    right = sum(r.right for r in results)
    accuracy = right / commands if commands else 0.0
    status = 0
    if accuracy < args.min_accuracy:
        print(f"check_labels: accuracy {100.0 * accuracy:.2f}% < "
              f"{100.0 * args.min_accuracy:.2f}%", file=sys.stderr)
        status = 1
    if any(r.id_errors for r in results):
        print("check_labels: identity errors", file=sys.stderr)
        status = 1
    if any(r.unexpected for r in results):
        print("check_labels: logged draws in frames without labels", file=sys.stderr)
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
