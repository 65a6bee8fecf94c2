#!/usr/bin/env python3
"""Writes the hand-made seeds of the GL call fuzzer into gl_corpus/ (seed-*).

Each seed is a GL program in the fuzzer's input format (gl_call_fuzz.cpp): a byte for the
drawable, then commands, each a little-endian u16 (the pseudo-commands first, then the commands of
gen_gl_fuzz_calls.py's table in its order) and its arguments, every value written as a literal
(selector 15) so that it decodes to exactly the value given here. The seeds must be written again
when the command table changes (a command added to the selection shifts the indices):

  tests/fuzz/make_gl_seeds.py --gl-xml /usr/share/khronos-api/gl.xml
"""

import argparse
import os
import struct
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import gen_gl_fuzz_calls as gen  # noqa: E402

PSEUDO = ["fill_bytes", "fill_reals", "swap", "resize", "rebind"]  # gl_call_fuzz.cpp's kPseudo*
LITERAL = 15

# A few enums the seeds use (gl.xml's values).
E = dict(
    GL_TRIANGLES=0x0004, GL_QUADS=0x0007, GL_LINES=0x0001, GL_POINTS=0x0000,
    GL_COLOR_BUFFER_BIT=0x4000, GL_DEPTH_BUFFER_BIT=0x0100, GL_COMPILE=0x1300,
    GL_COMPILE_AND_EXECUTE=0x1301, GL_TEXTURE_2D=0x0DE1, GL_RGBA=0x1908, GL_RGB=0x1907,
    GL_UNSIGNED_BYTE=0x1401, GL_FLOAT=0x1406, GL_UNSIGNED_SHORT=0x1403,
    GL_TEXTURE_MIN_FILTER=0x2801, GL_NEAREST=0x2600, GL_VERTEX_ARRAY=0x8074,
    GL_COLOR_ARRAY=0x8076, GL_ARRAY_BUFFER=0x8892, GL_ELEMENT_ARRAY_BUFFER=0x8893,
    GL_STATIC_DRAW=0x88E4, GL_LIGHTING=0x0B50, GL_LIGHT0=0x4000, GL_POSITION=0x1203,
    GL_DIFFUSE=0x1201, GL_FRONT_AND_BACK=0x0408, GL_AMBIENT_AND_DIFFUSE=0x1602,
    GL_DEPTH_TEST=0x0B71, GL_FOG=0x0B60, GL_FOG_MODE=0x0B65, GL_LINEAR=0x2601,
    GL_MODELVIEW=0x1700, GL_PROJECTION=0x1701, GL_SELECT=0x1C02, GL_RENDER=0x1C00,
    GL_FEEDBACK=0x1C01, GL_3D_COLOR=0x0602, GL_UNPACK_ALIGNMENT=0x0CF5,
    GL_COLOR_INDEX=0x1900, GL_BLEND=0x0BE2, GL_SRC_ALPHA=0x0302, GL_ONE_MINUS_SRC_ALPHA=0x0303,
    GL_TEXTURE_ENV=0x2300, GL_TEXTURE_ENV_MODE=0x2200, GL_MODULATE=0x2100,
    GL_STENCIL_TEST=0x0B90, GL_ALWAYS=0x0207, GL_KEEP=0x1E00, GL_REPLACE=0x1E01,
    GL_MAP1_VERTEX_3=0x0D97, GL_MAP1_COLOR_4=0x0D90, GL_LINE=0x1B01,
    GL_SAMPLES_PASSED=0x8914, GL_QUERY_RESULT=0x8866, GL_MAX_TEXTURE_SIZE=0x0D33,
)


class Seed:
    def __init__(self, names, command_params, config=0):
        self.names = names
        self.params = command_params
        self.out = bytearray([config])

    def pseudo(self, name, payload=b""):
        self.out += struct.pack("<H", PSEUDO.index(name)) + payload
        return self

    def fill_bytes(self, offset, data):
        return self.pseudo("fill_bytes", struct.pack("<HB", offset, len(data)) + bytes(data))

    def fill_floats(self, offset, values):
        payload = struct.pack("<HB", offset, len(values))
        for v in values:
            payload += bytes([LITERAL]) + struct.pack("<f", v)
        return self.pseudo("fill_reals", payload)

    def call(self, name, *args):
        """args: one per parameter; pointers as the byte the decoder reads (offset / 8)."""
        index = len(PSEUDO) + self.names.index(name)
        self.out += struct.pack("<H", index)
        params = self.params[name]
        assert len(params) == len(args), (name, len(params), len(args))
        for (kind, _), value in zip(params, args):
            if kind == "pointer":
                self.out += bytes([value])
            elif kind == "array_pointer":  # a selector byte (8: the usual choice), the offset
                self.out += bytes([8, value])
            elif kind == "boolean":
                self.out += bytes([LITERAL, value])
            elif kind == "float":
                self.out += bytes([LITERAL]) + struct.pack("<f", value)
            elif kind == "double":
                self.out += bytes([LITERAL]) + struct.pack("<d", value)
            else:
                self.out += bytes([LITERAL]) + struct.pack("<I", value & 0xFFFFFFFF)
        return self


def param_kinds(gl):
    """name -> [(kind, parameter name)] as the generated thunks decode them."""
    commands, names, enum_names = gen.selection(gl)
    param_groups = gen.parse_param_groups(gl)
    groups = {g: i for i, g in enumerate(gen.enum_groups(gl, enum_names))}
    kinds = {}
    for name in names:
        cmd = commands[name]
        out = []
        for p, g in zip(cmd.params, param_groups[name]):
            p.group = g
            expr = gen.pointer_expr(cmd, p) if p.is_pointer else gen.scalar_expr(cmd, p, groups)
            if "array_pointer" in expr:
                kind = "array_pointer"
            elif p.is_pointer:
                kind = "pointer"
            elif "boolean" in expr:
                kind = "boolean"
            elif "GLdouble" in expr or "GLclampd" in expr:
                kind = "double"
            elif "real<" in expr or "pixel_store<GLfloat>" in expr:
                kind = "float"
            else:
                kind = "u32"
            out.append((kind, p.name))
        kinds[name] = out
    return names, kinds


def seeds(names, kinds):
    def s(config=0):
        return Seed(names, kinds, config)

    out = {}
    # A lit, coloured triangle in a double-buffered frame, read back.
    out["seed-triangle"] = (
        s(config=1 | (15 << 1))
        .call("glClearColor", 0.2, 0.3, 0.4, 1.0).call("glClear", E["GL_COLOR_BUFFER_BIT"] | E["GL_DEPTH_BUFFER_BIT"])
        .call("glMatrixMode", E["GL_PROJECTION"]).call("glLoadIdentity")
        .call("glOrtho", -1.0, 1.0, -1.0, 1.0, -1.0, 1.0).call("glMatrixMode", E["GL_MODELVIEW"])
        .call("glBegin", E["GL_TRIANGLES"])
        .call("glColor3f", 1.0, 0.0, 0.0).call("glVertex3f", -1.0, -1.0, 0.0)
        .call("glColor3f", 0.0, 1.0, 0.0).call("glVertex3f", 1.0, -1.0, 0.0)
        .call("glColor3f", 0.0, 0.0, 1.0).call("glVertex3f", 0.0, 1.0, 0.0)
        .call("glEnd").pseudo("swap")
        .call("glReadPixels", 0, 0, 8, 8, E["GL_RGBA"], E["GL_FLOAT"], 0).call("glGetError"))
    # A display list compiled, then called twice, then replaced and deleted.
    out["seed-display-list"] = (
        s().call("glGenLists", 2).call("glNewList", 1, E["GL_COMPILE"])
        .call("glPushMatrix").call("glRotatef", 30.0, 0.0, 0.0, 1.0)
        .call("glBegin", E["GL_QUADS"]).call("glVertex2f", 0.0, 0.0).call("glVertex2f", 1.0, 0.0)
        .call("glVertex2f", 1.0, 1.0).call("glVertex2f", 0.0, 1.0).call("glEnd")
        .call("glPopMatrix").call("glEndList")
        .call("glNewList", 2, E["GL_COMPILE_AND_EXECUTE"]).call("glCallList", 1).call("glEndList")
        .call("glCallList", 2).call("glCallList", 1).call("glFinish")
        .call("glDeleteLists", 1, 2).call("glCallList", 1).call("glGetError"))
    # A 2x2 RGBA texture uploaded, a textured quad, the image read back.
    out["seed-texture"] = (
        s().fill_bytes(0, [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255])
        .call("glPixelStorei", E["GL_UNPACK_ALIGNMENT"], 1)
        .call("glBindTexture", E["GL_TEXTURE_2D"], 1)
        .call("glTexImage2D", E["GL_TEXTURE_2D"], 0, E["GL_RGBA"], 2, 2, 0, E["GL_RGBA"], E["GL_UNSIGNED_BYTE"], 0)
        .call("glTexParameteri", E["GL_TEXTURE_2D"], E["GL_TEXTURE_MIN_FILTER"], E["GL_NEAREST"])
        .call("glTexEnvi", E["GL_TEXTURE_ENV"], E["GL_TEXTURE_ENV_MODE"], E["GL_MODULATE"])
        .call("glEnable", E["GL_TEXTURE_2D"])
        .call("glBegin", E["GL_QUADS"])
        .call("glTexCoord2f", 0.0, 0.0).call("glVertex2f", -1.0, -1.0)
        .call("glTexCoord2f", 1.0, 0.0).call("glVertex2f", 1.0, -1.0)
        .call("glTexCoord2f", 1.0, 1.0).call("glVertex2f", 1.0, 1.0)
        .call("glTexCoord2f", 0.0, 1.0).call("glVertex2f", -1.0, 1.0)
        .call("glEnd").call("glFinish")
        .call("glGetTexImage", E["GL_TEXTURE_2D"], 0, E["GL_RGBA"], E["GL_FLOAT"], 0)
        .call("glTexSubImage2D", E["GL_TEXTURE_2D"], 0, 1, 1, 1, 1, E["GL_RGBA"], E["GL_UNSIGNED_BYTE"], 1)
        .call("glCopyTexImage2D", E["GL_TEXTURE_2D"], 0, E["GL_RGB"], 0, 0, 4, 4, 0))
    # Client vertex and colour arrays: glDrawArrays, glDrawElements (the fuzzer's index memory),
    # and both compiled into a display list.
    tri = [-1.0, -1.0, 0.0, 1.0, -1.0, 0.0, 0.0, 1.0, 0.0]
    col = [1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0]
    out["seed-vertex-arrays"] = (
        s().fill_floats(0, tri).fill_floats(64, col)
        .call("glEnableClientState", E["GL_VERTEX_ARRAY"]).call("glVertexPointer", 3, E["GL_FLOAT"], 0, 0)
        .call("glEnableClientState", E["GL_COLOR_ARRAY"]).call("glColorPointer", 4, E["GL_FLOAT"], 0, 8)
        .call("glDrawArrays", E["GL_TRIANGLES"], 0, 3)
        .call("glDrawElements", E["GL_TRIANGLES"], 3, E["GL_UNSIGNED_SHORT"], 0)
        .call("glNewList", 1, E["GL_COMPILE"]).call("glDrawArrays", E["GL_TRIANGLES"], 0, 3)
        .call("glArrayElement", 1).call("glEndList").call("glCallList", 1).call("glFinish"))
    # A vertex buffer object: data uploaded from the input memory, drawn from an offset.
    out["seed-buffer-object"] = (
        s().fill_floats(0, tri)
        .call("glGenBuffers", 1, 0).call("glBindBuffer", E["GL_ARRAY_BUFFER"], 1)
        .call("glBufferData", E["GL_ARRAY_BUFFER"], 36, 0, E["GL_STATIC_DRAW"])
        .call("glEnableClientState", E["GL_VERTEX_ARRAY"]).call("glVertexPointer", 3, E["GL_FLOAT"], 12, 0)
        .call("glDrawArrays", E["GL_TRIANGLES"], 0, 3).pseudo("swap")
        .call("glBufferSubData", E["GL_ARRAY_BUFFER"], 12, 12, 0)
        .call("glDrawArrays", E["GL_TRIANGLES"], 0, 3)
        .call("glDeleteBuffers", 1, 0).call("glDrawArrays", E["GL_TRIANGLES"], 0, 3).call("glFinish"))
    # Lighting, material, fog, depth and blending state around a draw; queries of it.
    out["seed-lighting"] = (
        s().fill_floats(0, [0.0, 0.0, 1.0, 0.0, 0.8, 0.2, 0.2, 1.0])
        .call("glEnable", E["GL_LIGHTING"]).call("glEnable", E["GL_LIGHT0"])
        .call("glLightfv", E["GL_LIGHT0"], E["GL_POSITION"], 0)
        .call("glMaterialfv", E["GL_FRONT_AND_BACK"], E["GL_AMBIENT_AND_DIFFUSE"], 2)
        .call("glEnable", E["GL_FOG"]).call("glFogi", E["GL_FOG_MODE"], E["GL_LINEAR"])
        .call("glEnable", E["GL_DEPTH_TEST"]).call("glEnable", E["GL_BLEND"])
        .call("glBlendFunc", E["GL_SRC_ALPHA"], E["GL_ONE_MINUS_SRC_ALPHA"])
        .call("glBegin", E["GL_TRIANGLES"]).call("glNormal3f", 0.0, 0.0, 1.0)
        .call("glVertex3f", -1.0, -1.0, 0.5).call("glVertex3f", 1.0, -1.0, 0.5).call("glVertex3f", 0.0, 1.0, 0.5)
        .call("glEnd").call("glGetLightfv", E["GL_LIGHT0"], E["GL_POSITION"], 0)
        .call("glGetIntegerv", E["GL_MAX_TEXTURE_SIZE"], 0).call("glFinish"))
    # Selection and feedback render modes.
    out["seed-render-modes"] = (
        s().call("glSelectBuffer", 64, 0).call("glRenderMode", E["GL_SELECT"])
        .call("glInitNames").call("glPushName", 7)
        .call("glBegin", E["GL_TRIANGLES"]).call("glVertex2f", 0.0, 0.0).call("glVertex2f", 0.5, 0.0)
        .call("glVertex2f", 0.0, 0.5).call("glEnd").call("glRenderMode", E["GL_RENDER"])
        .call("glFeedbackBuffer", 256, E["GL_3D_COLOR"], 64).call("glRenderMode", E["GL_FEEDBACK"])
        .call("glBegin", E["GL_LINES"]).call("glVertex2f", 0.0, 0.0).call("glVertex2f", 0.5, 0.5).call("glEnd")
        .call("glRenderMode", E["GL_RENDER"]))
    # Pixel commands: raster position, bitmap, draw and copy pixels, stencil.
    out["seed-pixels"] = (
        s().fill_bytes(0, [0xAA, 0x55] * 16)
        .call("glRasterPos2f", 0.0, 0.0).call("glBitmap", 8, 8, 0.0, 0.0, 8.0, 0.0, 0)
        .call("glDrawPixels", 4, 4, E["GL_RGBA"], E["GL_UNSIGNED_BYTE"], 0)
        .call("glEnable", E["GL_STENCIL_TEST"]).call("glStencilFunc", E["GL_ALWAYS"], 1, 0xFF)
        .call("glStencilOp", E["GL_KEEP"], E["GL_KEEP"], E["GL_REPLACE"])
        .call("glCopyPixels", 0, 0, 4, 4, 0x1800).call("glFlush"))
    # An evaluator curve and an occlusion query.
    out["seed-evaluator-query"] = (
        s().fill_floats(0, [-1.0, -1.0, 0.0, 0.0, 1.0, 0.0, 1.0, -1.0, 0.0])
        .call("glMap1f", E["GL_MAP1_VERTEX_3"], 0.0, 1.0, 3, 3, 0).call("glEnable", E["GL_MAP1_VERTEX_3"])
        .call("glGenQueries", 1, 0).call("glBeginQuery", E["GL_SAMPLES_PASSED"], 1)
        .call("glMapGrid1f", 8, 0.0, 1.0).call("glEvalMesh1", E["GL_LINE"], 0, 8)
        .call("glEndQuery", E["GL_SAMPLES_PASSED"]).call("glFinish")
        .call("glGetQueryObjectuiv", 1, E["GL_QUERY_RESULT"], 0))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--gl-xml", required=True)
    ap.add_argument("--out", default=os.path.join(HERE, "gl_corpus"))
    args = ap.parse_args()
    names, kinds = param_kinds(ET.parse(args.gl_xml).getroot())
    os.makedirs(args.out, exist_ok=True)
    for name, seed in seeds(names, kinds).items():
        with open(os.path.join(args.out, name), "wb") as f:
            f.write(seed.out)


if __name__ == "__main__":
    main()
