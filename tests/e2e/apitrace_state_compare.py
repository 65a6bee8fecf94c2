#!/usr/bin/env python3
"""Compares two apitrace state dumps (glretrace -D CALL --dump-format=json): REFERENCE from real
Mesa, TEST from glpt, for the GL 1.x state.

  apitrace_state_compare.py MESA.json GLPT.json --known KNOWN.txt [--images DIR] [--gl-xml gl.xml]

What is compared:
  parameters  every value both dumps hold must be equal (numbers within 1e-5, relative to their
              size: the dumps print 7-8 significant digits); a GL 1.0-1.5 enum that only Mesa's
              dump holds means glpt set an error for its query, and fails; a key only glpt's dump
              holds fails too. Texture units at or beyond glpt's GL_MAX_TEXTURE_UNITS are skipped
              (Mesa has more) and so are keys of later GL versions that Mesa alone answers.
  textures    the texel images of every bound texture, byte for byte (apitrace encodes them the
              same way for both).
  framebuffer colour images are written to DIR (mesa_NAME.png, glpt_NAME.png) for the caller's
              image comparison; depth (PFM) must agree within two steps of the 24-bit buffer
              (measured on statetour: 3.8 % of the pixels differ by one or two steps where
              polygon offset and a depth range meet interpolated depth); stencil exactly.
KNOWN.txt: lines `REGEX  reason`; a parameter whose slash-joined key (e.g.
`GL_TEXTURE1/GL_TEXTURE_ENV/GL_RGB_SCALE`) matches a REGEX may differ or be missing. Exit 0 when
everything else agrees, 1 with one line per difference otherwise, 2 on bad input.
"""
import argparse
import base64
import json
import math
import os
import re
import struct
import sys
import xml.etree.ElementTree as ET


def load_dump(path):
    with open(path) as f:
        # apitrace writes base64 images with raw line breaks inside strings.
        return json.load(f, strict=False)


def flatten(node, prefix=""):
    for key, value in node.items():
        if isinstance(value, dict):
            yield from flatten(value, prefix + key + "/")
        else:
            yield prefix + key, value


def gl1_enums(gl_xml):
    names = set()
    for feature in ET.parse(gl_xml).getroot().findall("feature"):
        if feature.get("api") == "gl" and feature.get("number") in ("1.0", "1.1", "1.2", "1.3",
                                                                   "1.4", "1.5"):
            for require in feature.findall("require"):
                names.update(e.get("name") for e in require.findall("enum"))
    return names


def equal(a, b):
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(equal(x, y) for x, y in zip(a, b))
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return math.isclose(a, b, rel_tol=1e-5, abs_tol=1e-5)
    return a == b


def read_pfm(data):
    # "PF\n" or "Pf\n", "W H\n", "scale\n", then floats (little-endian when scale < 0; apitrace
    # writes 1 and native little-endian floats).
    header, rest = data.split(b"\n", 1)
    dims, rest = rest.split(b"\n", 1)
    _, rest = rest.split(b"\n", 1)
    width, height = map(int, dims.split())
    channels = 3 if header == b"PF" else 1
    count = width * height * channels
    return struct.unpack("<%df" % count, rest[: 4 * count])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("mesa")
    ap.add_argument("glpt")
    ap.add_argument("--known", required=True)
    ap.add_argument("--images", help="directory for the colour images of both framebuffers")
    ap.add_argument("--gl-xml", default="/usr/share/khronos-api/gl.xml")
    args = ap.parse_args()
    try:
        mesa, glpt = load_dump(args.mesa), load_dump(args.glpt)
        known = []
        with open(args.known) as f:
            for line in f:
                line = line.strip()
                if line and not line.startswith("#"):
                    known.append(re.compile(line.split()[0]))
        core = gl1_enums(args.gl_xml)
    except (OSError, ValueError, ET.ParseError) as e:
        print(f"apitrace_state_compare: {e}", file=sys.stderr)
        return 2

    problems = []
    m = dict(flatten(mesa.get("parameters", {})))
    g = dict(flatten(glpt.get("parameters", {})))
    if not g:
        problems.append("glpt's dump has no parameters")
    units = g.get("GL_MAX_TEXTURE_UNITS", 0)

    def skipped(key):
        unit = re.match(r"GL_TEXTURE(\d+)/", key)
        return bool(unit and int(unit.group(1)) >= units)

    def is_known(key):
        return any(k.search(key) for k in known)

    compared = 0
    for key, value in m.items():
        if skipped(key) or is_known(key):
            continue
        if key in g:
            compared += 1
            if not equal(value, g[key]):
                problems.append(f"{key}: Mesa {json.dumps(value)[:120]}, glpt {json.dumps(g[key])[:120]}")
        elif key.split("/")[-1] in core:
            problems.append(f"{key}: missing from glpt's dump (Mesa {json.dumps(value)[:80]})")
    for key in g:
        if key not in m and not skipped(key) and not is_known(key):
            problems.append(f"{key}: only in glpt's dump ({json.dumps(g[key])[:80]})")

    mt, gt = mesa.get("textures", {}), glpt.get("textures", {})
    for name in sorted(set(mt) | set(gt)):
        if name not in mt or name not in gt:
            problems.append(f"texture {name}: only in {'Mesa' if name in mt else 'glpt'}'s dump")
        elif mt[name] != gt[name]:
            problems.append(f"texture {name}: texels or attributes differ")

    mf, gf = mesa.get("framebuffer", {}), glpt.get("framebuffer", {})
    for name in sorted(set(mf) | set(gf)):
        if name not in mf or name not in gf:
            problems.append(f"framebuffer {name}: only in {'Mesa' if name in mf else 'glpt'}'s dump")
            continue
        a, b = (base64.b64decode(x["__data__"]) for x in (mf[name], gf[name]))
        if mf[name]["__format__"] == "GL_DEPTH_COMPONENT":
            da, db = read_pfm(a), read_pfm(b)
            worst = max((abs(x - y) for x, y in zip(da, db)), default=0.0)
            if len(da) != len(db) or worst > 2.0 / 0xFFFFFF:
                problems.append(f"framebuffer {name}: depth differs by up to {worst:.3g}")
        elif mf[name]["__format__"] == "GL_STENCIL_INDEX":
            if a != b:
                problems.append(f"framebuffer {name}: stencil differs")
        elif args.images:
            for who, data in (("mesa", a), ("glpt", b)):
                with open(os.path.join(args.images, f"{who}_{name}.png"), "wb") as f:
                    f.write(data)

    for p in problems:
        print(p)
    print(f"apitrace_state_compare: {compared} parameters compared, {len(mt)} texture images, "
          f"{len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
