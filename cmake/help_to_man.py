#!/usr/bin/env python3
"""Writes glpt's man pages from the same text as its --help (run at build time).

    help_to_man.py --glpt BUILD/replay/glpt --replay BUILD/replay/glpt-replay \
                   --version 0.1 --out-dir DIR

glpt.1 comes from `glpt --help`, glpt-CMD.1 from `glpt help CMD` for every command that
`glpt --help` lists, glpt-replay.1 from `glpt-replay --help`. The help texts follow one layout,
which this turns into man(7) markup:

    usage: LINE                      -> SYNOPSIS
    paragraphs at column 0           -> DESCRIPTION (a blank line starts a new paragraph)
    "word(s): rest" at column 0      -> a section (options, commands, exit status, example)
    other lines ending with ':'      -> a subsection
    "  -x, --flag ARG  text"         -> an item; deeper-indented lines continue its text
    other indented lines             -> kept as they are (examples)
"""
import argparse
import datetime
import os
import re
import subprocess
import sys

SECTION = re.compile(r"^([a-z][a-z ]{0,20}):(?:\s+(.*))?$")
ITEM = re.compile(r"^( {1,8})(\S.*?)(?: {2,}(\S.*))?$")


def roff(text):
    """Escapes text for a man page line (backslashes, hyphens, leading dots/quotes)."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    if text.startswith((".", "'")):
        text = "\\&" + text
    return text


def convert(help_text, name, summary, version, see_also):
    lines = help_text.rstrip("\n").split("\n")
    out = []
    date = datetime.date.fromtimestamp(
        int(os.environ.get("SOURCE_DATE_EPOCH", "0")) or 1764547200).isoformat()
    out.append('.TH "%s" 1 "%s" "glpt %s" "glpt manual"' % (name.upper(), date, version))
    out.append(".SH NAME")
    out.append(roff("%s - %s" % (name, summary)))
    i = 0
    if lines and lines[0].startswith("usage: "):
        out.append(".SH SYNOPSIS")
        out.append(".nf")
        out.append(roff(lines[0][len("usage: "):]))
        out.append(".fi")
        i = 1
    out.append(".SH DESCRIPTION")
    in_item = None  # set while an item's text may continue
    in_item_start = 0  # the item's indentation
    verbatim = False
    paragraph_open = False

    def end_verbatim():
        nonlocal verbatim
        if verbatim:
            out.append(".fi")
            out.append(".PP")
            verbatim = False

    for line in lines[i:]:
        if not line.strip():
            end_verbatim()
            in_item = None
            if paragraph_open:
                out.append(".PP")
                paragraph_open = False
            continue
        if not line.startswith(" "):
            end_verbatim()
            in_item = None
            section = SECTION.match(line)
            if section:
                out.append(".SH " + roff(section.group(1).upper()))
                if section.group(2):
                    # "example: glpt run ..." is a command line; other rests are prose.
                    if section.group(1).startswith("example"):
                        out.append(".nf")
                        out.append(roff(section.group(2)))
                        out.append(".fi")
                    else:
                        out.append(roff(section.group(2)))
                        paragraph_open = True
                continue
            if line.endswith(":"):
                out.append(".SS " + roff(line[:-1]))
                continue
            out.append(roff(line))
            paragraph_open = True
            continue
        indent = len(line) - len(line.lstrip(" "))
        if in_item is not None and indent > in_item_start:
            out.append(roff(line.strip()))  # continues the item's text
            continue
        item = ITEM.match(line)
        if item and (item.group(2).startswith("-") or item.group(3)):
            end_verbatim()
            out.append(".TP")
            out.append("\\fB" + roff(item.group(2)) + "\\fR")
            if item.group(3):
                out.append(roff(item.group(3)))
            in_item, in_item_start = True, indent
            continue
        if not verbatim:
            out.append(".nf")
            verbatim = True
        out.append(roff(line.strip()))
    end_verbatim()
    if see_also:
        out.append(".SH SEE ALSO")
        out.append(",\n".join("\\fB%s\\fR(1)" % roff(page) for page in see_also))
    return "\n".join(out) + "\n"


def run(argv):
    result = subprocess.run(argv, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("help_to_man: %s failed (%d): %s" % (" ".join(argv), result.returncode,
                                                       result.stderr))
    return result.stdout


def commands(top_help):
    """(name, summary) of each command in `glpt --help`'s "commands:" list."""
    found, listing = [], False
    for line in top_help.split("\n"):
        if line == "commands:":
            listing = True
        elif listing and not line.strip():
            break
        elif listing:
            m = re.match(r"^  ([a-z]+) +(\S.*)$", line)
            if m and m.group(1) != "help":  # "help CMD" is glpt's own, on glpt.1
                found.append((m.group(1), m.group(2)))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--glpt", required=True)
    parser.add_argument("--replay", required=True)
    parser.add_argument("--version", required=True)
    parser.add_argument("--out-dir", required=True)
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    top = run([args.glpt, "--help"])
    subcommands = commands(top)
    if not subcommands:
        sys.exit("help_to_man: `glpt --help` lists no commands")
    pages = {"glpt": (top, "path-traced OpenGL 1.x, as a drop-in libGL.so.1")}
    for name, summary in subcommands:
        # `glpt replay` is glpt-replay: its page is glpt-replay's own, from its full help.
        if name != "replay":
            pages["glpt-" + name] = (run([args.glpt, "help", name]), summary)
    pages["glpt-replay"] = (run([args.replay, "--help"]),
                            "replay an apitrace trace headless through glpt (glpt replay)")
    names = sorted(pages)
    for name, (text, summary) in pages.items():
        see_also = [n for n in names if n != name]
        with open(os.path.join(args.out_dir, name + ".1"), "w") as f:
            f.write(convert(text, name, summary, args.version, see_also))


if __name__ == "__main__":
    main()
