#!/usr/bin/env python3
"""Unit tests of check_labels.py: its offline mode (--labels, --log) on hand-made labels and
logs, and its program mode on small fake programs (Python scripts that print labels and write
$GLPT_CLASSIFY_LOG themselves), so the checker is tested without glpt or a display.

Every test that expects a pass has a sibling that changes one thing and expects the failure.
"""

import contextlib
import io
import json
import os
import stat
import subprocess
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import check_labels  # noqa: E402

# Two frames of a small program: a sky, two static crates drawn as two consecutive blocks that
# glpt may merge, a moving fan, a HUD.
LABELS = """\
some other output line
LABEL 0 sky sky
LABEL 0 static crate0
LABEL 0 static crate1
LABEL 0 static fan
LABEL 0 overlay hud
LABEL 1 sky sky
LABEL 1 static crate0
LABEL 1 static crate1
LABEL 1 moving fan
LABEL 1 overlay hud
"""


def entry(frame, cls, ident, calls=1):
    return {"frame": frame, "class": cls, "calls": calls, "id": ident}


def good_log():
    """The log glpt should write for LABELS (crates merged into one entry of 2 calls)."""
    return [entry(0, "sky", 1), entry(0, "static", 2, calls=2), entry(0, "static", 3),
            entry(0, "overlay", 4),
            entry(1, "sky", 1), entry(1, "static", 2, calls=2), entry(1, "moving", 3),
            entry(1, "overlay", 4)]


class OfflineTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def write(self, name, text):
        path = os.path.join(self.tmp.name, name)
        with open(path, "w", encoding="utf-8") as out:
            out.write(text)
        return path

    def run_offline(self, log_entries, labels=LABELS, extra=(), raw_log=None):
        """Runs check_labels.main in the offline mode; returns (exit status, stdout)."""
        labels_path = self.write("prog.labels.txt", labels)
        log_text = raw_log if raw_log is not None else "".join(
            json.dumps(e) + "\n" for e in log_entries)
        log_path = self.write("prog.jsonl", log_text)
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = check_labels.main(["--labels", labels_path, "--log", log_path, *extra])
        return status, out.getvalue()

    def test_correct_log_passes(self):
        status, out = self.run_offline(good_log())
        self.assertEqual(status, 0, out)
        self.assertIn("100.00%", out)

    def test_unmerged_log_passes_too(self):
        log = [e for e in good_log() if e["calls"] == 1]
        for frame in (0, 1):
            index = next(i for i, e in enumerate(log) if e["frame"] == frame and e["id"] == 1)
            log[index + 1:index + 1] = [entry(frame, "static", 20), entry(frame, "static", 21)]
        status, out = self.run_offline(log)
        self.assertEqual(status, 0, out)

    def test_swapped_class_fails(self):
        log = good_log()
        log[6]["class"] = "static"  # frame 1 fan: moving expected
        status, out = self.run_offline(log)
        self.assertEqual(status, 1, out)
        self.assertIn("moving", out)
        self.assertRegex(out, r"1\s+fan\s+moving\s+static")
        self.assertIn("moving -> static: 1", out)
        self.assertRegex(out, r"\nmoving\s+1\s+0\s+0.00%")  # per-class recall
        self.assertRegex(out, r"\nstatic\s+5\s+5\s+100.00%")

    def test_two_swapped_classes_in_one_frame_fail(self):
        log = good_log()
        log[4]["class"], log[7]["class"] = "overlay", "sky"
        status, out = self.run_offline(log)
        self.assertEqual(status, 1, out)
        self.assertIn("80.00%", out)  # 8 of 10 right

    def test_id_change_across_frames_fails(self):
        log = good_log()
        log[6]["id"] = 30  # the fan gets a new id in frame 1
        status, out = self.run_offline(log)
        self.assertEqual(status, 1, out)
        self.assertIn("key fan: id 3 from frame 0, id 30 from frame 1", out)
        self.assertIn("100.00%", out)  # the classes are all right: identity alone fails it

    def test_shared_id_within_a_frame_fails(self):
        log = good_log()
        log[7]["id"] = 3  # the HUD takes the fan's id in frame 1
        status, out = self.run_offline(log)
        self.assertEqual(status, 1, out)
        self.assertIn("frame 1: two log entries share id 3", out)

    def test_count_mismatch_fails_the_whole_frame(self):
        log = good_log()
        log[5]["calls"] = 1  # frame 1 covers 4 calls, 5 labels
        status, out = self.run_offline(log, extra=["--min-accuracy", "0.5"])
        self.assertEqual(status, 0, out)  # 5 of 10 right: enough for 0.5 ...
        self.assertIn("50.00%", out)
        self.assertIn("frame 1: 5 labels but the log covers 4 calls", out)
        status, out = self.run_offline(log)  # ... not for the default 0.99
        self.assertEqual(status, 1, out)

    def test_extra_entry_fails(self):
        log = good_log() + [entry(1, "overlay", 9)]
        status, out = self.run_offline(log)
        self.assertEqual(status, 1, out)
        self.assertIn("frame 1: 5 labels but the log covers 6 calls", out)

    def test_entries_in_an_unlabelled_frame_fail(self):
        log = good_log() + [entry(2, "static", 2)]
        status, out = self.run_offline(log, extra=["--min-accuracy", "0"])
        self.assertEqual(status, 1, out)
        self.assertIn("frame 2: 1 logged calls in a frame without labels", out)

    def test_accuracy_threshold(self):
        labels = "".join(f"LABEL {f} static k{i}\n" for f in range(4) for i in range(50))
        log = [entry(f, "static", i) for f in range(4) for i in range(50)]
        log[77]["class"] = "moving"  # 199 of 200 right: 99.5 %
        status, out = self.run_offline(log, labels=labels)
        self.assertEqual(status, 0, out)
        self.assertIn("99.50%", out)
        status, out = self.run_offline(log, labels=labels, extra=["--min-accuracy", "0.996"])
        self.assertEqual(status, 1, out)

    def test_unknown_class_in_the_log_is_a_mismatch(self):
        log = good_log()
        log[0]["class"] = "skybox"
        status, out = self.run_offline(log)
        self.assertEqual(status, 1, out)
        self.assertIn("sky -> skybox: 1", out)

    def test_missing_log_is_a_harness_error(self):
        labels_path = self.write("prog.labels.txt", LABELS)
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            status = check_labels.main(["--labels", labels_path, "--log",
                                        os.path.join(self.tmp.name, "absent.jsonl")])
        self.assertEqual(status, 2, out.getvalue())

    def test_malformed_log_is_a_harness_error(self):
        for bad in ('{"frame": 0, "class": "sky", "calls": 1}\n',           # no id
                    '{"frame": 0, "class": "sky", "calls": 0, "id": 1}\n',  # no calls
                    '{"frame": 0, "class": "sky", "calls": 1, "id": -1}\n',
                    '{"frame": true, "class": "sky", "calls": 1, "id": 1}\n',
                    'frame 0 sky\n'):
            status, out = self.run_offline(None, raw_log=bad)
            self.assertEqual(status, 2, (bad, out))
        status, out = self.run_offline(None, raw_log="".join(json.dumps(e) + "\n"
                                                               for e in good_log()) + "\n")
        self.assertEqual(status, 0, out)  # a trailing blank line is fine

    def test_malformed_labels_are_a_harness_error(self):
        for bad in ("LABEL 0 static a\nLABEL 0 static a\n",  # key twice in a frame
                    "LABEL 0 statik a\n",                      # unknown class
                    "LABEL x static a\n",
                    "LABEL 0 static a b\n",
                    "no labels at all\n"):
            status, out = self.run_offline([entry(0, "static", 1)], labels=bad)
            self.assertEqual(status, 2, (bad, out))

    def test_report_file_lists_every_mismatch(self):
        labels = "".join(f"LABEL 0 static k{i}\n" for i in range(30))
        log = [entry(0, "moving", i) for i in range(30)]
        report = os.path.join(self.tmp.name, "report.txt")
        status, out = self.run_offline(log, labels=labels, extra=["--report", report])
        self.assertEqual(status, 1)
        self.assertIn("first 10", out)
        self.assertNotIn("k29", out)
        with open(report, encoding="utf-8") as file:
            text = file.read()
        self.assertIn("k29", text)
        self.assertIn("static -> moving: 30", text)


FAKE_PROGRAM = """\
#!{python}
# A fake labelled program: prints labels, writes the log glpt would write.
import json, os, sys
mode = {mode!r}
if "GLPT_CLASSIFY_LOG" in os.environ and (os.environ.get("GLPT_MODE") != "raster"
                                          or os.environ.get("GLPT_QUIET") != "1"):
    sys.exit(5)
if mode == "crash":
    print("LABEL 0 static a", flush=True)
    os.kill(os.getpid(), 11)
for f in range(2 if mode == "short" else 4):
    print(f"LABEL {{f}} static a")
    print(f"LABEL {{f}} {{'moving' if f else 'static'}} b")
if "CLASSIFY_COUNT_LOG" in os.environ:  # stands in for count_draws
    with open(os.environ["CLASSIFY_COUNT_LOG"], "w") as counts:
        for f in range(4):
            counts.write(f"COUNT {{f}} {{3 if mode == 'miscount' and f == 2 else 2}}\\n")
if mode in ("nolog", "short", "miscount"):
    sys.exit(0)
with open(os.environ["GLPT_CLASSIFY_LOG"], "w") as log:
    for f in range(4):
        got = "static" if mode == "wrong" else ("moving" if f else "static")
        log.write(json.dumps({{"frame": f, "class": "static", "calls": 1, "id": 1}}) + "\\n")
        log.write(json.dumps({{"frame": f, "class": got, "calls": 1, "id": 2}}) + "\\n")
"""


class ProgramModeTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)
        self.libgl = os.path.join(self.tmp.name, "libGL.so.1")
        # An empty file: only its existence is checked; '' below runs without preload.
        open(self.libgl, "w").close()

    def fake(self, mode):
        path = os.path.join(self.tmp.name, f"classify_fake_{mode}")
        with open(path, "w", encoding="utf-8") as out:
            out.write(FAKE_PROGRAM.format(python=sys.executable, mode=mode))
        os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
        return path

    def check(self, *args):
        """Runs check_labels.py as a command; returns (exit status, stdout)."""
        proc = subprocess.run([sys.executable, os.path.join(HERE, "check_labels.py"), *args],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              check=False)
        return proc.returncode, proc.stdout

    def test_right_program_passes_and_keep_keeps_its_files(self):
        keep = os.path.join(self.tmp.name, "kept")
        status, out = self.check("--libgl", "", "--program", self.fake("right"), "--keep", keep)
        self.assertEqual(status, 0, out)
        self.assertRegex(out, r"classify_fake_right\s+8\s+8\s+100.00%\s+0\s+ok")
        for suffix in (".labels.txt", ".jsonl", ".stderr.txt"):
            self.assertTrue(os.path.exists(os.path.join(keep, "classify_fake_right" + suffix)))

    def test_wrong_program_fails_in_the_aggregate(self):
        status, out = self.check("--libgl", "", "--programs", self.fake("right"),
                                 self.fake("wrong"))
        self.assertEqual(status, 1, out)
        self.assertRegex(out, r"classify_fake_wrong\s+8\s+5\s+62.50%\s+0\s+FAIL")
        self.assertRegex(out, r"TOTAL\s+16\s+13\s+81.25%")

    def test_crash_and_missing_log_are_harness_errors(self):
        for mode in ("crash", "nolog"):
            status, out = self.check("--libgl", "", "--programs", self.fake("right"),
                                     self.fake(mode))
            self.assertEqual(status, 2, out)
            self.assertIn("ERROR", out)
        status, out = self.check("--libgl", os.path.join(self.tmp.name, "absent.so"),
                                 "--program", self.fake("right"))
        self.assertEqual(status, 2, out)

    def test_labels_only_mode_needs_no_log_but_four_frames(self):
        status, out = self.check("--labels-only", "--programs", self.fake("nolog"))
        self.assertEqual(status, 0, out)
        status, out = self.check("--labels-only", "--programs", self.fake("nolog"),
                                 self.fake("short"))
        self.assertEqual(status, 2, out)
        self.assertIn("labelled frames [0, 1]", out)

    def test_labels_only_mode_with_counts(self):
        # The fake writes the counts itself: the "shim" is an empty file, which ld.so ignores.
        shim = os.path.join(self.tmp.name, "count_draws.so")
        open(shim, "w").close()
        status, out = self.check("--labels-only", "--count-shim", shim, "--programs",
                                 self.fake("nolog"))
        self.assertEqual(status, 0, out)
        status, out = self.check("--labels-only", "--count-shim", shim, "--programs",
                                 self.fake("miscount"))
        self.assertEqual(status, 2, out)
        self.assertIn("frame 2: 2 labels, 3 drawing commands", out)


if __name__ == "__main__":
    unittest.main()
