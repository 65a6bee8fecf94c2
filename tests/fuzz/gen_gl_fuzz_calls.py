#!/usr/bin/env python3
"""Generates the GL call fuzzer's command table (gl_call_fuzz.cpp) from the Khronos registry.

The same selection as the library's own entry points (gl_shim/gen/gen_gl_api.py, imported): one
thunk per exported GL command, aliases included (they are entry points of their own), which draws
each argument from the fuzzer's byte stream through a glpt::fuzz::Decoder and calls the exported
entry point. How an argument is drawn is decided here from the registry, and from the tables below
where the registry cannot say what memory a pointer must cover:

  enum / bitfield with a registry group  d.enumerant(group) / d.bits(group): a member of the group
                                         (the enums glpt exports), now and then any enum or raw
  GLboolean                              d.boolean()
  float / double                         d.real<T>(): small values, NaN, +-Inf, -0, 1e38, raw
  integers                               d.integer<T>(); by role (ROLES below) a count, extent,
                                         texture size, stride or pixel-store value, bounded so
                                         that no valid call reads or writes past the fuzzer's
                                         memory (invalid values are drawn as well: GL must reject
                                         them before touching memory, and ASan reports it if not)
  const pointer                          d.input(): the fuzz-owned input memory
  pointer written by GL                  d.output(): the fuzz-owned output memory
  pointer roles (POINTER_ROLES)          client arrays, indices, multi-draw arrays

Commands that read client vertex arrays are guarded (GUARDS): the thunk skips, and counts, a
draw whose valid indices would reach past the fuzzer's array memory (an application bug in any
GL, not glpt's). So are list calls compiled into lists, which could ask for exponential work.

Usage: gen_gl_fuzz_calls.py --gl-xml gl.xml --out FILE.inc
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "gl_shim", "gen"))
import gen_gl_api as api  # noqa: E402

# Integer parameters by name -> the decoder's method. Counts and sizes that say how much memory a
# pointer covers are bounded (d.count: mostly 0..64, rarely up to 4096, or negative).
COUNT_NAMES = {"n", "count", "size", "range", "mapsize", "primcount", "drawcount", "order",
               "uorder", "vorder", "imageSize", "un", "vn"}
EXTENT_NAMES = {"width", "height", "depth"}
STRIDE_NAMES = {"stride", "ustride", "vstride"}
# Texture image commands: their sizes have a GL maximum, so sizes past it are drawn too (GL must
# answer GL_INVALID_VALUE before reading the image); glDrawPixels, glReadPixels and glBitmap have
# no maximum, so only sizes the fuzzer's memory covers are valid ones.
TEXTURE_SIZE_PREFIXES = ("glTexImage", "glTexSubImage", "glCopyTexImage", "glCopyTexSubImage",
                         "glCompressedTex")

# (command core name, parameter) -> decoder expression, where the rules above are not enough.
ROLES = {
    # Unpack/pack modes decide how far an image reaches: row lengths, skips and image heights
    # have no GL maximum, so only small ones (and invalid negative ones) are drawn.
    ("glPixelStorei", "param"): "d.pixel_store<GLint>()",
    ("glPixelStoref", "param"): "d.pixel_store<GLfloat>()",
    # The range of glDrawRangeElements and the first vertex of glDrawArrays are checked by the
    # guards; small values make most draws pass them.
    ("glDrawArrays", "first"): "d.count()",
    ("glDrawRangeElements", "start"): "d.count()",
    ("glDrawRangeElements", "end"): "d.count()",
    ("glArrayElement", "i"): "d.count()",
    ("glLockArrays", "first"): "d.count()",
    # Evaluator maps read stride * order values.
    ("glMap1f", "stride"): "d.stride()",
    ("glMap1d", "stride"): "d.stride()",
    # Each list a glCallLists names may call further lists (64 deep): few names a call keep
    # the work an input can ask for bounded (see GUARDS).
    ("glCallLists", "n"): "d.list_count()",
    # glSelectBuffer / glFeedbackBuffer keep the pointer and write up to size values later.
    ("glSelectBuffer", "size"): "d.count()",
    ("glFeedbackBuffer", "size"): "d.count()",
}

# Pointer parameters that are not plain input or output memory.
POINTER_ROLES = {
    # Client arrays: an address in the fuzzer's array memory, or an offset into the buffer object
    # bound to GL_ARRAY_BUFFER when one is.
    **{(c, "pointer"): "d.array_pointer()" for c in (
        "glVertexPointer", "glNormalPointer", "glColorPointer", "glIndexPointer",
        "glTexCoordPointer", "glEdgeFlagPointer", "glFogCoordPointer", "glSecondaryColorPointer",
        "glInterleavedArrays")},
    # Indices: the fuzzer's index memory (every value small), or an offset into the buffer
    # object bound to GL_ELEMENT_ARRAY_BUFFER.
    ("glDrawElements", "indices"): "d.index_pointer()",
    ("glDrawRangeElements", "indices"): "d.index_pointer()",
    ("glMultiDrawElements", "indices"): "d.index_pointers()",
    ("glMultiDrawElements", "count"): "d.small_ints()",
    ("glMultiDrawArrays", "first"): "d.small_ints()",
    ("glMultiDrawArrays", "count"): "d.small_ints()",
}

# Draws that read client arrays: skipped (and counted) when a valid draw would read past the
# fuzzer's array memory.
GUARDS = {
    "glDrawArrays": "d.client_vertices_fit(first, count)",
    "glArrayElement": "d.client_vertices_fit(i, 1)",
    "glDrawElements": "d.client_indices_fit()",
    "glDrawRangeElements": "d.client_indices_fit() && d.client_range_fits(start, end)",
    "glMultiDrawElements": "d.client_indices_fit()",
    # ({last}: the last parameter, drawcount or EXT's primcount.)
    "glMultiDrawArrays": "d.client_multi_draw_fits(first, count, {last})",
    # Display lists that call lists: a list calling itself twice asks for 2^64 calls (GL nests
    # 64 deep), a hang in any GL. While a list is compiled, at most one list call goes into it,
    # so nested lists are chains, never trees.
    # Evaluator meshes: glpt evaluates up to 2^24 points per mesh, as GL allows (seconds of work,
    # tens of seconds under the sanitizers): spans past 64K points are legal and merely slow.
    "glEvalMesh1": "d.mesh_fits(i1, i2, 0, 0)",
    "glEvalMesh2": "d.mesh_fits(i1, i2, j1, j2)",
    "glCallList": "d.list_calls_fit(1)",
    "glCallLists": "d.list_calls_fit(n)",
}

FLOATS = {"GLfloat", "GLclampf", "GLdouble", "GLclampd"}


def core(name):
    return api.core_name(name)


def scalar_expr(cmd, p, groups):
    role = ROLES.get((core(cmd.name), p.name))
    if role:
        return role
    t = p.ptype
    group = p.group if p.group in groups else None
    if t == "GLenum" or (t == "GLint" and group is not None and p.group != "CheckedInt32"):
        return f"static_cast<{t}>(d.enumerant({groups.get(group, -1)}))"
    if t == "GLbitfield":
        return f"d.bits({groups.get(group, -1)})"
    if t == "GLboolean":
        return "d.boolean()"
    if t in FLOATS:
        return f"d.real<{t}>()"
    if p.name in EXTENT_NAMES:
        if core(cmd.name).startswith(TEXTURE_SIZE_PREFIXES):
            return "d.texture_size()"
        return "d.extent()"
    if p.name in STRIDE_NAMES:
        return "d.stride()"
    if p.name in COUNT_NAMES or t == "GLsizeiptr" or t == "GLsizeiptrARB":
        return f"static_cast<{t}>(d.count())"
    return f"d.integer<{t}>()"


def pointer_expr(cmd, p):
    role = POINTER_ROLES.get((core(cmd.name), p.name))
    base = role or ("d.input()" if p.ctype.startswith("const") else "d.output()")
    return f"static_cast<{p.ctype}>({base})"


def parse_param_groups(root):
    """command -> [group of each parameter or None] (gen_gl_api's Param has no group)."""
    out = {}
    for cmd in root.find("commands").findall("command"):
        out[cmd.find("proto").find("name").text] = [p.get("group") for p in cmd.findall("param")]
    return out


def enum_groups(root, exported_enums):
    """group -> sorted values of the exported enums in it."""
    exported = set(exported_enums)
    groups = {}
    for enums in root.iter("enums"):
        for e in enums.findall("enum"):
            if e.get("name") not in exported or e.get("api") not in (None, "gl"):
                continue
            for g in (e.get("group") or "").split(","):
                if g:
                    groups.setdefault(g, set()).add(int(e.get("value"), 0) & 0xFFFFFFFF)
    return {g: sorted(v) for g, v in sorted(groups.items())}


def selection(gl):
    """The exported commands in the order of gl_commands.hpp, and the exported enums."""
    commands = api.parse_commands(gl)
    names, enum_names = api.collect(gl, "gl", api.GL_FEATURES, api.GL_EXTENSIONS,
                                    api.GL_ENUM_ONLY_EXTENSIONS)
    for n in list(names):
        a = api.alias_of(commands[n])
        if a and a in commands and a not in names:
            names.append(a)
    return commands, names, enum_names


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--gl-xml", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    gl = ET.parse(args.gl_xml).getroot()
    commands, names, enum_names = selection(gl)
    param_groups = parse_param_groups(gl)
    values = api.parse_enums(gl, "gl")
    groups = enum_groups(gl, enum_names)
    group_index = {g: i for i, g in enumerate(groups)}

    out = [api.HEADER.replace("gl_shim/gen/gen_gl_api.py", "tests/fuzz/gen_gl_fuzz_calls.py"),
           "// Included by tests/fuzz/gl_call_fuzz.cpp inside namespace glpt::fuzz.\n\n"]
    all_values = sorted({int(values[n], 0) & 0xFFFFFFFF for n in enum_names if n in values})
    out.append("inline constexpr uint32_t kAllEnums[] = {\n")
    out.append(",".join(f"0x{v:X}u" for v in all_values) + "};\n")
    for g, vals in groups.items():
        out.append(f"inline constexpr uint32_t kGroup{g}[] = {{" + ",".join(f"0x{v:X}u" for v in vals) + "};\n")
    out.append("// The enum groups of gl.xml, by the index the thunks pass (-1: any enum).\n")
    out.append("inline constexpr std::span<const uint32_t> kGroups[] = {\n")
    out.append(",\n".join(f"  kGroup{g}" for g in groups) + "};\n\n")

    for name in names:
        cmd = commands[name]
        for p, g in zip(cmd.params, param_groups[name]):
            p.group = g
        lines = [f"void call_{name}(Decoder&{' d' if cmd.params or not cmd.returns_void else ''}) {{"]
        for p in cmd.params:
            expr = pointer_expr(cmd, p) if p.is_pointer else scalar_expr(cmd, p, group_index)
            ctype = p.ctype if p.is_pointer else p.ctype.replace("const ", "")
            lines.append(f"  {ctype} {p.name} = {expr};")
        guard = GUARDS.get(core(name))
        if guard:
            guard = guard.replace("{last}", cmd.params[-1].name)
            lines.append(f"  if (!({guard})) return d.skip_unsafe_draw();")
        call = f"{name}({', '.join(p.name for p in cmd.params)})"
        lines.append(f"  d.returned({call});" if not cmd.returns_void else f"  {call};")
        lines.append("}")
        out.append("\n".join(lines) + "\n")
    out.append("\ninline constexpr Command kGlCommands[] = {\n")
    out.append(",\n".join(f'  {{"{n}", call_{n}}}' for n in names) + "};\n")
    with open(args.out, "w") as f:
        f.write("".join(out))


if __name__ == "__main__":
    main()
