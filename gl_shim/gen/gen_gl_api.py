#!/usr/bin/env python3
"""Generates glpt's GL API surface from the Khronos registry (gl.xml, glx.xml).

One table drives everything mechanical about the API, so adding a GL entry point is a matter of
implementing it, never of writing boilerplate:

  gl_enums.h           #define GL_* for every enum of the selected versions and extensions
  glx_enums.h          #define GLX_* likewise from glx.xml
  gl_commands.hpp      CommandId (one per exported command) and the command name table
  gl_impl_decls.hpp    the implementation prototypes: namespace glpt::impl { RET glFoo(Context&, ...); }
  gl_entry_points.cpp  the exported extern "C" entry points, display-list record and replay, and
                       the name -> entry point table behind glXGetProcAddress

An implementation is simply a definition of glpt::impl::glFoo in any gl_shim source file. The
entry points reference the implementations weakly: a command nobody implemented yet resolves to
null, and its entry point records GL_INVALID_OPERATION once and counts the call instead of
crashing. Extension commands that the registry marks as aliases of core commands (glActiveTextureARB
-> glActiveTexture) call the core implementation.

Every entry point also does, from the table:
  - nothing at all without a current context (GL leaves this undefined; never crash);
  - GL_INVALID_OPERATION between glBegin and glEnd for commands the spec does not allow there;
  - recording into the display list being compiled, for the commands the spec compiles.

Display-list recording is table-driven too. A compiled command's scalar arguments are stored as
they are; its pointer arguments are copied with a length that comes from:
  - the registry (len="3", a count parameter, or COMPSIZE(pname) through
    glpt::pname_value_count, display_lists/param_counts.cpp);
  - CUSTOM_ARRAY_COUNTS: a hand-written C++ expression for the element count;
  - CLIENT_IMAGES: an image in client memory laid out by the unpack modes (glTexImage*,
    glTexSubImage*, glDrawPixels, glBitmap, glPolygonStipple). GL 1.5 5.4 compiles these with the
    image unpacked at compile time, with the pixel store modes current then. Recording calls the
    hand-written glpt::copy_client_image (pixels/list_images.hpp), which stores the image in the
    same format and type laid out with the default unpack modes (alignment 1, no skips, no byte
    swapping, MSB-first bitmaps: Mesa's display lists do the same); replay runs the command with
    those default modes in effect (glpt::DefaultUnpackModes) and restores the context's own. A
    table entry may name a condition under which the command is executed at once and never
    compiled (proxy texture targets, GL 1.5 3.8.11).
  - HAND_COMPILED: hand-written code that dereferences the client data itself (vertex array
    draws, whose arrays GL 1.5 5.4 reads at compile time: arrays/array_lists.hpp; evaluator
    maps, whose control points it reads: evaluators/evaluator_lists.hpp), recording
    records of its own that HAND_REPLAYED functions replay.
Any other pointer argument (output pointers) makes a command "not compilable": it is counted
and not recorded.
"""

import collections

import argparse
import re
import sys
import xml.etree.ElementTree as ET

# ----------------------------------------------------------------------------------------------
# The selection: which parts of the registry glpt exports.

GL_FEATURES = ["GL_VERSION_1_0", "GL_VERSION_1_1", "GL_VERSION_1_2", "GL_VERSION_1_3",
               "GL_VERSION_1_4", "GL_VERSION_1_5"]

# Extension entry points old GL 1.x programs look up by name.
GL_EXTENSIONS = [
    "GL_ARB_multitexture", "GL_ARB_transpose_matrix", "GL_ARB_window_pos",
    "GL_ARB_point_parameters", "GL_ARB_vertex_buffer_object", "GL_ARB_texture_compression",
    "GL_ARB_multisample", "GL_ARB_occlusion_query",
    "GL_EXT_texture_object", "GL_EXT_vertex_array", "GL_EXT_blend_color", "GL_EXT_blend_minmax",
    "GL_EXT_blend_func_separate", "GL_EXT_blend_equation_separate", "GL_EXT_polygon_offset",
    "GL_EXT_texture3D", "GL_EXT_subtexture", "GL_EXT_copy_texture", "GL_EXT_compiled_vertex_array",
    "GL_EXT_draw_range_elements", "GL_EXT_multi_draw_arrays", "GL_EXT_fog_coord",
    "GL_EXT_secondary_color", "GL_EXT_point_parameters", "GL_EXT_stencil_two_side",
    "GL_EXT_framebuffer_object", "GL_EXT_framebuffer_blit",
]
# Enums only (these extensions add no commands, or only enums matter).
GL_ENUM_ONLY_EXTENSIONS = [
    "GL_ARB_imaging",
    "GL_EXT_bgra", "GL_EXT_abgr", "GL_EXT_packed_pixels", "GL_EXT_rescale_normal",
    "GL_EXT_separate_specular_color", "GL_SGIS_texture_edge_clamp",
    "GL_EXT_texture_env_combine", "GL_ARB_texture_env_combine", "GL_ARB_texture_env_add",
    "GL_EXT_texture_filter_anisotropic", "GL_SGIS_generate_mipmap", "GL_ARB_texture_cube_map",
    "GL_EXT_texture_lod_bias", "GL_ARB_texture_border_clamp", "GL_ARB_texture_mirrored_repeat",
    "GL_NV_texgen_reflection", "GL_EXT_stencil_wrap", "GL_ARB_depth_texture",
    "GL_ARB_texture_rectangle", "GL_EXT_texture_env_dot3", "GL_ARB_texture_env_dot3",
    "GL_EXT_packed_depth_stencil", "GL_ARB_point_sprite", "GL_EXT_texture_compression_s3tc",
]

# Single enums of later versions that glpt answers because state dumpers ask every context for
# them (apitrace's glretrace -D sizes its per-texture-unit loop with these GL 2.0 limits).
GL_TOOL_QUERY_ENUMS = [
    "GL_MAX_TEXTURE_COORDS", "GL_MAX_TEXTURE_IMAGE_UNITS", "GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS",
]
# GL 2.0's spellings of ARB_point_sprite, and the sprite origin GL 2.0 added to it (programs of the
# time set it through glPointParameteri; Mesa accepts it in every compatibility context).
GL_2_0_POINT_SPRITE_ENUMS = [
    "GL_POINT_SPRITE", "GL_COORD_REPLACE", "GL_POINT_SPRITE_COORD_ORIGIN", "GL_LOWER_LEFT",
    "GL_UPPER_LEFT",
]

# What glGetString(GL_EXTENSIONS) advertises: the extensions GL 1.1-1.5 made core (programs of
# the time test for them rather than for the version) and GL 1.x-era ones glpt implements
# besides. Every command an advertised extension adds must be implemented (checked by
# tests/unit/extensions_test.cpp through advertised_extension_commands()). Not advertised:
# GL_EXT_polygon_offset (its bias differs from glPolygonOffset's), GL_ARB_imaging (only its
# GL 1.4 blend subset is implemented).
ADVERTISED_GL_EXTENSIONS = [
    "GL_ARB_depth_texture", "GL_ARB_multisample", "GL_ARB_multitexture", "GL_ARB_occlusion_query",
    "GL_ARB_point_parameters", "GL_ARB_point_sprite",
    "GL_ARB_shadow", "GL_ARB_texture_border_clamp", "GL_ARB_texture_compression",
    "GL_ARB_texture_cube_map", "GL_ARB_texture_env_add", "GL_ARB_texture_env_combine",
    "GL_ARB_texture_env_crossbar", "GL_ARB_texture_env_dot3", "GL_ARB_texture_mirrored_repeat",
    "GL_ARB_texture_non_power_of_two",
    "GL_ARB_texture_rectangle",
    "GL_ARB_transpose_matrix", "GL_ARB_vertex_buffer_object", "GL_ARB_window_pos",
    "GL_EXT_bgra", "GL_EXT_blend_color", "GL_EXT_blend_equation_separate",
    "GL_EXT_blend_func_separate", "GL_EXT_blend_logic_op",
    "GL_EXT_blend_minmax", "GL_EXT_blend_subtract", "GL_EXT_compiled_vertex_array",
    "GL_EXT_copy_texture", "GL_EXT_draw_range_elements", "GL_EXT_fog_coord",
    "GL_EXT_framebuffer_blit", "GL_EXT_framebuffer_object",
    "GL_EXT_multi_draw_arrays", "GL_EXT_packed_depth_stencil", "GL_EXT_packed_pixels",
    "GL_EXT_point_parameters",
    "GL_EXT_rescale_normal", "GL_EXT_secondary_color", "GL_EXT_separate_specular_color",
    "GL_EXT_shadow_funcs", "GL_EXT_stencil_two_side", "GL_EXT_stencil_wrap", "GL_EXT_subtexture", "GL_EXT_texture",
    "GL_EXT_texture3D", "GL_EXT_texture_compression_s3tc", "GL_EXT_texture_env_add",
    "GL_EXT_texture_env_combine",
    "GL_EXT_texture_env_dot3", "GL_EXT_texture_filter_anisotropic", "GL_EXT_texture_lod_bias",
    "GL_EXT_texture_object",
    "GL_EXT_texture_rectangle",
    "GL_EXT_vertex_array", "GL_NV_blend_square", "GL_NV_texgen_reflection",
    "GL_NV_texture_rectangle",
    "GL_SGIS_generate_mipmap", "GL_SGIS_texture_edge_clamp", "GL_SGIS_texture_lod",
]

# Advertised extensions that gl.xml does not list; they add enums only (Mesa advertises them).
UNREGISTERED_ADVERTISED_EXTENSIONS = {"GL_EXT_texture_rectangle"}

GLX_FEATURES = ["GLX_VERSION_1_0", "GLX_VERSION_1_1", "GLX_VERSION_1_2", "GLX_VERSION_1_3",
                "GLX_VERSION_1_4"]
GLX_EXTENSIONS = ["GLX_ARB_create_context", "GLX_ARB_create_context_profile",
                  "GLX_ARB_get_proc_address", "GLX_EXT_visual_info", "GLX_ARB_multisample",
                  "GLX_EXT_swap_control", "GLX_MESA_swap_control", "GLX_SGI_swap_control",
                  "GLX_ARB_framebuffer_sRGB", "GLX_EXT_framebuffer_sRGB",
                  "GLX_ARB_fbconfig_float", "GLX_EXT_texture_from_pixmap"]

# GL 1.5 spec, section 5.4: commands executed immediately even while a display list is compiled.
NOT_COMPILED = {
    "glIsList", "glGenLists", "glDeleteLists", "glNewList", "glEndList",
    "glFeedbackBuffer", "glSelectBuffer", "glRenderMode",
    "glColorPointer", "glEdgeFlagPointer", "glIndexPointer", "glNormalPointer",
    "glTexCoordPointer", "glVertexPointer", "glInterleavedArrays", "glFogCoordPointer",
    "glSecondaryColorPointer", "glEnableClientState", "glDisableClientState",
    "glClientActiveTexture", "glPushClientAttrib", "glPopClientAttrib",
    "glReadPixels", "glPixelStoref", "glPixelStorei",
    "glGenTextures", "glDeleteTextures", "glAreTexturesResident", "glIsTexture",
    "glFlush", "glFinish",
    "glBindBuffer", "glDeleteBuffers", "glGenBuffers", "glIsBuffer", "glBufferData",
    "glBufferSubData", "glMapBuffer", "glUnmapBuffer",
    "glGenQueries", "glDeleteQueries", "glIsQuery",
    "glLockArraysEXT", "glUnlockArraysEXT",
    # EXT_framebuffer_object (GL 3.0 5.4 lists its commands among those not compiled).
    "glBindFramebufferEXT", "glDeleteFramebuffersEXT", "glGenFramebuffersEXT",
    "glCheckFramebufferStatusEXT", "glFramebufferTexture1DEXT", "glFramebufferTexture2DEXT",
    "glFramebufferTexture3DEXT", "glFramebufferRenderbufferEXT", "glGenerateMipmapEXT",
    "glBindRenderbufferEXT", "glDeleteRenderbuffersEXT", "glGenRenderbuffersEXT",
    "glRenderbufferStorageEXT",
    "glBindFramebuffer", "glDeleteFramebuffers", "glGenFramebuffers", "glCheckFramebufferStatus",
    "glFramebufferTexture1D", "glFramebufferTexture2D", "glFramebufferTexture3D",
    "glFramebufferRenderbuffer", "glGenerateMipmap", "glBindRenderbuffer",
    "glDeleteRenderbuffers", "glGenRenderbuffers", "glRenderbufferStorage",
}
NOT_COMPILED_PREFIXES = ("glGet", "glIs")

# GL 1.5 spec, section 2.6.3: the only commands allowed between glBegin and glEnd.
ALLOWED_IN_BEGIN_END_PREFIXES = (
    "glVertex", "glColor", "glSecondaryColor", "glIndex", "glNormal", "glFogCoord",
    "glTexCoord", "glMultiTexCoord", "glVertexAttrib", "glEvalCoord", "glEvalPoint",
    "glArrayElement", "glMaterial", "glEdgeFlag", "glCallList", "glEnd",
)
# ... but not these, whose names merely start like the above.
NOT_ALLOWED_IN_BEGIN_END = {
    "glEndList", "glColorMaterial", "glColorMask", "glColorPointer", "glColorTable", "glColorSubTable",
    "glColorTableParameterfv", "glColorTableParameteriv", "glIndexMask", "glIndexPointer",
    "glNormalPointer", "glTexCoordPointer", "glVertexPointer", "glEdgeFlagPointer",
    "glFogCoordPointer", "glSecondaryColorPointer", "glVertexPointerEXT", "glColorPointerEXT",
    "glIndexPointerEXT", "glNormalPointerEXT", "glTexCoordPointerEXT", "glEdgeFlagPointerEXT",
    "glFogCoordPointerEXT", "glSecondaryColorPointerEXT", "glColorPointerListIBM",
}

# Pointer parameters whose element count depends on the value of `pname`: recorded with
# glpt::pname_value_count(CommandId, pname), written by hand in display_lists/param_counts.cpp.
PNAME_COUNT_FAMILIES = re.compile(
    r"^gl(Light|LightModel|Material|Fog|TexEnv|TexGen|TexParameter|PointParameter|"
    r"ColorTableParameter|ConvolutionParameter)[fdix]v(ARB|EXT)?$")

# Pointer parameters with a hand-written size: (command, parameter) -> (element type, count).
CUSTOM_ARRAY_COUNTS = {
    ("glCallLists", "lists"): ("GLubyte", "glpt::call_lists_bytes(n, type)"),
    # Only a map size GL accepts is read (an invalid one is an error when the list runs).
    ("glPixelMapfv", "values"): ("GLfloat", "glpt::pixel_map_values_to_record(mapsize)"),
    ("glPixelMapuiv", "values"): ("GLuint", "glpt::pixel_map_values_to_record(mapsize)"),
    ("glPixelMapusv", "values"): ("GLushort", "glpt::pixel_map_values_to_record(mapsize)"),
    # Compressed images are stored as the bytes they are.
    ("glCompressedTexImage1D", "data"): ("GLubyte", "glpt::clamp_count(imageSize)"),
    ("glCompressedTexImage2D", "data"): ("GLubyte", "glpt::clamp_count(imageSize)"),
    ("glCompressedTexImage3D", "data"): ("GLubyte", "glpt::clamp_count(imageSize)"),
    ("glCompressedTexSubImage1D", "data"): ("GLubyte", "glpt::clamp_count(imageSize)"),
    ("glCompressedTexSubImage2D", "data"): ("GLubyte", "glpt::clamp_count(imageSize)"),
    ("glCompressedTexSubImage3D", "data"): ("GLubyte", "glpt::clamp_count(imageSize)"),
}

# Images in client memory read through the unpack modes (see the docstring), by core command
# name: the pointer parameter, whether IMAGE_HEIGHT / SKIP_IMAGES apply (3-D), the C++
# expressions of width, height, depth, format and type, and a condition for executing the command
# at once instead of compiling it (or None).
ClientImage = collections.namedtuple(
    "ClientImage", "data three_d width height depth format type immediate_if")
_PROXY = "glpt::is_proxy_texture_target(target)"
CLIENT_IMAGES = {
    "glTexImage1D": ClientImage("pixels", False, "width", "1", "1", "format", "type", _PROXY),
    "glTexImage2D": ClientImage("pixels", False, "width", "height", "1", "format", "type", _PROXY),
    "glTexImage3D": ClientImage("pixels", True, "width", "height", "depth", "format", "type",
                                _PROXY),
    "glTexSubImage1D": ClientImage("pixels", False, "width", "1", "1", "format", "type", None),
    "glTexSubImage2D": ClientImage("pixels", False, "width", "height", "1", "format", "type",
                                   None),
    "glTexSubImage3D": ClientImage("pixels", True, "width", "height", "depth", "format", "type",
                                   None),
    "glDrawPixels": ClientImage("pixels", False, "width", "height", "1", "format", "type", None),
    "glBitmap": ClientImage("bitmap", False, "width", "height", "1", "GL_COLOR_INDEX",
                            "GL_BITMAP", None),
    "glPolygonStipple": ClientImage("mask", False, "32", "32", "1", "GL_COLOR_INDEX", "GL_BITMAP",
                                    None),
}

# Commands the registry does not mark as aliases (EXT_texture_object's have GLX opcodes of their
# own) but that are the core command in every implementation, Mesa's included.
EXTRA_ALIASES = {
    "glGenTexturesEXT": "glGenTextures",
    "glDeleteTexturesEXT": "glDeleteTextures",
    "glIsTextureEXT": "glIsTexture",
    "glAreTexturesResidentEXT": "glAreTexturesResident",
}
# Parameter types an alias may differ in and still share the core implementation: typedefs of
# the same C type, and internal formats declared GLenum by EXT_texture3D but GLint by GL 1.2
# (every valid value converts exactly).
EQUIVALENT_TYPES = {"GLclampf": "GLfloat", "GLclampd": "GLdouble", "GLsizeiptrARB": "GLsizeiptr",
                    "GLintptrARB": "GLintptr", "GLenum": "GLint"}

# Commands whose client data GL 1.5 5.4 dereferences when they are compiled (vertex arrays,
# evaluator control points),
# recorded and replayed by hand-written code. While a list is being compiled, the entry point of
# a command named here (by core name) calls the function given, glpt::f(Context&, ListStream&,
# <the command's arguments>), which records what it needs under any CommandId; HAND_REPLAYED
# names the function that replays records of a CommandId, glpt::g(Context&, const
# ListStream::Reader&). GL_COMPILE_AND_EXECUTE then executes the command as usual. Both are
# declared in the headers of HAND_COMPILED_HEADERS.
HAND_COMPILED = {
    "glArrayElement": "glpt::compile_array_element",
    "glDrawArrays": "glpt::compile_draw_arrays",
    "glDrawElements": "glpt::compile_draw_elements",
    "glDrawRangeElements": "glpt::compile_draw_range_elements",
    "glMultiDrawArrays": "glpt::compile_multi_draw_arrays",
    "glMultiDrawElements": "glpt::compile_multi_draw_elements",
    "glMap1f": "glpt::compile_map1f",
    "glMap1d": "glpt::compile_map1d",
    "glMap2f": "glpt::compile_map2f",
    "glMap2d": "glpt::compile_map2d",
}
HAND_REPLAYED = {
    "glArrayElement": "glpt::replay_array_element",
    "glDrawArrays": "glpt::replay_array_primitive",
    "glMap1f": "glpt::replay_map1",
    "glMap2f": "glpt::replay_map2",
}
HAND_COMPILED_HEADERS = ["gl_shim/arrays/array_lists.hpp", "gl_shim/evaluators/evaluator_lists.hpp"]

# Scalar parameter commands that Mesa's display lists compile as their vector form with the
# value followed by zeros (dlist.c save_TexParameterf & co.): compiled, they are that vector
# command, so e.g. a compiled glTexParameterf(GL_TEXTURE_BORDER_COLOR, v) sets the colour
# (v, 0, 0, 0) without the GL_INVALID_ENUM the scalar form raises when executed at once.
# Core name -> (vector command, element type of its array, array length).
COMPILED_AS_VECTOR = {
    "glFogf": ("glFogfv", "GLfloat", 4),
    "glFogi": ("glFogiv", "GLint", 4),
    "glLightf": ("glLightfv", "GLfloat", 4),
    "glLighti": ("glLightiv", "GLint", 4),
    "glLightModelf": ("glLightModelfv", "GLfloat", 4),
    "glLightModeli": ("glLightModeliv", "GLint", 4),
    "glTexEnvf": ("glTexEnvfv", "GLfloat", 4),
    "glTexEnvi": ("glTexEnvfv", "GLfloat", 4),
    "glTexGenf": ("glTexGenfv", "GLfloat", 4),
    "glTexGend": ("glTexGenfv", "GLfloat", 4),
    "glTexGeni": ("glTexGeniv", "GLint", 4),
    "glTexParameterf": ("glTexParameterfv", "GLfloat", 4),
    "glTexParameteri": ("glTexParameterfv", "GLfloat", 4),
    "glPointParameterf": ("glPointParameterfv", "GLfloat", 3),
    "glPointParameteri": ("glPointParameterfv", "GLfloat", 3),
}

GL_SCALAR_TYPES = {
    "GLenum", "GLboolean", "GLbitfield", "GLbyte", "GLshort", "GLint", "GLubyte", "GLushort",
    "GLuint", "GLsizei", "GLfloat", "GLclampf", "GLdouble", "GLclampd", "GLintptr",
    "GLsizeiptr", "GLintptrARB", "GLsizeiptrARB", "GLhalfNV", "GLchar", "GLcharARB", "GLint64",
    "GLuint64", "GLfixed", "GLhandleARB",
}


class Param:
    def __init__(self, ctype, name, ptype, length):
        self.ctype = ctype.strip()  # full C type, e.g. "const GLfloat *"
        self.name = name
        self.ptype = ptype          # the GL base type, e.g. "GLfloat" (None for void)
        self.length = length        # the registry's len attribute or None

    @property
    def is_pointer(self):
        return "*" in self.ctype

    def decl(self):
        sep = "" if self.ctype.endswith("*") else " "
        return f"{self.ctype}{sep}{self.name}"


class Command:
    def __init__(self, name, ret, params, alias):
        self.name = name
        self.ret = ret.strip()
        self.params = params
        self.alias = alias

    @property
    def returns_void(self):
        return self.ret == "void"


def c_type_of(elem):
    """The C type of a <proto> or <param>: all text except the <name> element."""
    parts = [elem.text or ""]
    for child in elem:
        if child.tag == "name":
            parts.append(child.tail or "")
            continue
        parts.append((child.text or "") + (child.tail or ""))
    return re.sub(r"\s+", " ", "".join(parts)).replace(" *", " *").strip()


def parse_commands(root):
    commands = {}
    for cmd in root.find("commands").findall("command"):
        proto = cmd.find("proto")
        name = proto.find("name").text
        ret = c_type_of(proto)
        params = []
        for p in cmd.findall("param"):
            ptype_el = p.find("ptype")
            params.append(Param(c_type_of(p), p.find("name").text,
                                ptype_el.text if ptype_el is not None else None,
                                p.get("len")))
        alias_el = cmd.find("alias")
        commands[name] = Command(name, ret, params, alias_el.get("name") if alias_el is not None else None)
    return commands


def parse_enums(root, api):
    values = {}
    for enums in root.iter("enums"):
        for e in enums.findall("enum"):
            if e.get("api") not in (None, api):
                continue
            values.setdefault(e.get("name"), e.get("value"))
    return values


def collect(root, api, feature_names, extension_names, enum_only_extensions=()):
    """Commands and enums required by the selected features and extensions, in registry order."""
    commands, enums = [], []
    seen_c, seen_e = set(), set()

    def take(require):
        if require.get("api") not in (None, api):
            return
        for c in require.findall("command"):
            if c.get("name") not in seen_c:
                seen_c.add(c.get("name"))
                commands.append(c.get("name"))
        for e in require.findall("enum"):
            if e.get("name") not in seen_e:
                seen_e.add(e.get("name"))
                enums.append(e.get("name"))

    for feature in root.findall("feature"):
        if feature.get("name") in feature_names:
            for req in feature.findall("require"):
                take(req)
    wanted = set(extension_names) | set(enum_only_extensions)
    found = set()
    for ext in root.iter("extension"):
        if ext.get("name") in wanted:
            found.add(ext.get("name"))
            for req in ext.findall("require"):
                if ext.get("name") in enum_only_extensions:
                    for e in req.findall("enum"):
                        if e.get("name") not in seen_e:
                            seen_e.add(e.get("name"))
                            enums.append(e.get("name"))
                else:
                    take(req)
    missing = wanted - found
    if missing:
        sys.exit(f"gen_gl_api: extensions not in the registry: {sorted(missing)}")
    return commands, enums


# ----------------------------------------------------------------------------------------------
# Display-list recording plan for one command.

def literal_count(length):
    return int(length) if length is not None and length.isdigit() else None


def record_plan(cmd):
    """How a compiled command stores its pointer arguments, or None if it cannot be compiled.

    Returns a dict: pointer parameter -> a C++ expression for its element count, or
    "client image" for the image of a CLIENT_IMAGES command; or the string "hand" for a
    HAND_COMPILED command.
    """
    if core_name(cmd.name) in HAND_COMPILED:
        return "hand"
    plan = {}
    param_names = {p.name for p in cmd.params}
    image = CLIENT_IMAGES.get(core_name(cmd.name))
    for p in cmd.params:
        if image is not None and p.name == image.data:
            plan[p.name] = "client image"
            continue
        if not p.is_pointer:
            if p.ptype not in GL_SCALAR_TYPES:
                return None
            continue
        custom = CUSTOM_ARRAY_COUNTS.get((core_name(cmd.name), p.name))
        if custom:
            plan[p.name] = custom[1]
            continue
        if p.ptype is None or p.ptype not in GL_SCALAR_TYPES or not p.ctype.startswith("const"):
            return None  # void* data or output pointers: custom code (images, arrays)
        n = literal_count(p.length)
        if n is not None:
            plan[p.name] = str(n)
        elif p.length == "COMPSIZE(pname)" and PNAME_COUNT_FAMILIES.match(cmd.name):
            plan[p.name] = f"glpt::pname_value_count(glpt::CommandId::{cmd.name}, pname)"
        elif p.length in param_names:
            plan[p.name] = f"glpt::clamp_count({p.length})"
        else:
            return None
    return plan


def core_name(name):
    """glGenBuffersARB -> glGenBuffers: extension commands follow the rules of their core twin."""
    return re.sub(r"(ARB|EXT)$", "", name)


def compiled(name):
    core = core_name(name)
    return core not in NOT_COMPILED and not core.startswith(NOT_COMPILED_PREFIXES)


def allowed_in_begin_end(name):
    return name.startswith(ALLOWED_IN_BEGIN_END_PREFIXES) and name not in NOT_ALLOWED_IN_BEGIN_END


# ----------------------------------------------------------------------------------------------
# Emitters.

HEADER = "// Generated by gl_shim/gen/gen_gl_api.py from the Khronos registry. Do not edit.\n"


def emit_enums(path, names, values, guard):
    with open(path, "w") as f:
        f.write(HEADER + f"#pragma once\n// {guard}\n")
        for n in names:
            if n in values:
                f.write(f"#define {n} {values[n]}\n")


def emit_commands_header(path, names):
    with open(path, "w") as f:
        f.write(HEADER + "#pragma once\n#include <cstdint>\n\nnamespace glpt {\n\n")
        f.write("enum class CommandId : uint16_t {\n")
        for n in names:
            f.write(f"  {n},\n")
        f.write("  kCount\n};\n\n")
        f.write("inline constexpr const char* kCommandNames[] = {\n")
        for n in names:
            f.write(f'    "{n}",\n')
        f.write("};\n\n")
        f.write("inline const char* command_name(CommandId id) {\n"
                "  return kCommandNames[static_cast<uint16_t>(id)];\n}\n\n}  // namespace glpt\n")


def equivalent_type(ctype):
    return " ".join(EQUIVALENT_TYPES.get(word, word) for word in ctype.split())


def alias_of(cmd):
    return cmd.alias or EXTRA_ALIASES.get(cmd.name)


def impl_name(cmd, commands):
    """The implementation a command uses: its own, or that of the core command it aliases."""
    alias = alias_of(cmd)
    if alias and alias in commands:
        target = commands[alias]
        if ([equivalent_type(p.ctype) for p in target.params] ==
                [equivalent_type(p.ctype) for p in cmd.params] and target.ret == cmd.ret):
            return alias
    return cmd.name


def impl_signature(cmd, name):
    params = ", ".join(["Context& ctx"] + [p.decl() for p in cmd.params])
    return f"{cmd.ret} {name}({params})"


def unique_impls(names, commands):
    """Each implementation once, in command order (aliases share their core command's)."""
    done = set()
    for n in names:
        target = impl_name(commands[n], commands)
        if target not in done:
            done.add(target)
            yield target


def emit_entry_decls(path, names, commands):
    """The exported entry points' prototypes: for their definitions (the front end builds with
    -Wmissing-declarations) and for tests that call them."""
    with open(path, "w") as f:
        f.write(HEADER + '#pragma once\n#include "gl_shim/gl_types.h"\n\nextern "C" {\n\n')
        for n in names:
            cmd = commands[n]
            params = ", ".join(p.decl() for p in cmd.params) or "void"
            f.write(f"GLPT_EXPORT {cmd.ret} {n}({params});\n")
        f.write('\n}  // extern "C"\n')


def emit_impl_decls(path, names, commands):
    with open(path, "w") as f:
        f.write(HEADER + "#pragma once\n#include \"gl_shim/gl_types.h\"\n\n")
        f.write("namespace glpt {\nclass Context;\nnamespace impl {\n\n")
        for target in unique_impls(names, commands):
            f.write(impl_signature(commands[target], target) + ";\n")
        f.write("\n}  // namespace impl\n}  // namespace glpt\n")


def emit_compile_function(w, n, cmd, plan):
    """compile_<n>: records one call into the list being compiled, and executes it too where GL
    does (GL_COMPILE_AND_EXECUTE, or a client image that is not compiled). The entry point
    tail-calls it, so nothing of the call needs keeping across it."""
    params = ", ".join(["glpt::Context& ctx", "glpt::ListStream& glpt_list"] +
                       [p.decl() for p in cmd.params])
    execute = f"glpt::exec_{n}({', '.join(['ctx'] + [p.name for p in cmd.params])})"
    ret_default = "" if cmd.returns_void else " {}"
    w(f"[[gnu::cold, gnu::noinline]] static {cmd.ret} compile_{n}({params}) {{\n")
    image = CLIENT_IMAGES.get(core_name(n)) if "client image" in plan.values() else None
    if image is not None and image.immediate_if:
        w(f"  if ({image.immediate_if}) return {execute};\n")
    if image is not None:
        w(f"  const glpt::ClientImageCopy image_copy = glpt::copy_client_image("
          f"ctx.framebuffer.unpack, glpt::ImageShape{{{image.width}, {image.height}, "
          f"{image.depth}, {image.format}, {image.type}}}, "
          f"{'true' if image.three_d else 'false'}, {image.data});\n")
    w(f"  glpt::ListStream::Writer rec_writer(glpt_list, glpt::CommandId::{n}, "
      f"sizeof(glpt::Rec_{n}));\n")
    w(f"  glpt::Rec_{n} rec{{}};\n")
    for p in cmd.params:
        if plan.get(p.name) == "client image":
            w(f"  rec.{p.name}_present = image_copy.present;\n")
            w(f"  rec.{p.name}_bytes = uint32_t(image_copy.bytes.size());\n")
            w(f"  rec.{p.name}_offset = rec_writer.append_array("
              f"image_copy.bytes.data(), rec.{p.name}_bytes);\n")
        elif p.is_pointer:
            w(f"  rec.{p.name}_count = {plan[p.name]};\n")
            elem = CUSTOM_ARRAY_COUNTS.get((core_name(cmd.name), p.name), (p.ptype,))[0]
            w(f"  rec.{p.name}_offset = rec_writer.append_array("
              f"static_cast<const {elem}*>({p.name}), rec.{p.name}_count);\n")
        else:
            w(f"  rec.{p.name} = {p.name};\n")
    w("  rec_writer.set_record(rec);\n")
    w(f"  if (!ctx.list_executes_while_compiling()) return{ret_default};\n")
    w(f"  return {execute};\n}}\n\n")


def emit_entry_points(path, names, commands, gl_root):
    out = []
    w = out.append
    w(HEADER)
    w('#include <algorithm>\n#include <cstring>\n\n'
      '#include "gl_shim/context.hpp"\n#include "gl_shim/display_lists/list_stream.hpp"\n'
      '#include "gl_shim/dispatch.hpp"\n#include "gl_shim/gl_entry_decls.h"\n'
      '#include "gl_shim/geometry/attributes.hpp"\n'
      '#include "gl_shim/pixels/list_images.hpp"\n'
      '#include "gl/gl_enums.h"\n')
    for header in HAND_COMPILED_HEADERS:
        w(f'#include "{header}"\n')
    w("\n")
    # Weak references to the implementations.
    w("namespace glpt::impl {\n")
    for target in unique_impls(names, commands):
        w(f"[[gnu::weak]] {impl_signature(commands[target], target)};\n")
    w("}  // namespace glpt::impl\n\n")

    # exec_*: validation + implementation (or the unimplemented fallback). Used by the entry
    # points and by display-list replay alike.
    w("namespace glpt {\nnamespace {\n\n")
    for n in names:
        cmd = commands[n]
        target = impl_name(cmd, commands)
        args = ", ".join(["ctx"] + [p.name for p in cmd.params])
        params = ", ".join(["Context& ctx"] + [p.decl() for p in cmd.params])
        w(f"inline {cmd.ret} exec_{n}({params}) {{\n")
        # Vertex attributes, called per vertex by immediate-mode programs: the setter inline
        # here, not through the out-of-line impl:: copy (two calls fewer per glNormal3f /
        # glVertex3f pair).
        if (inline_body := attribute_family_body(n, commands)) is not None:
            w(inline_body + "}\n\n")
            continue
        ret_default = "" if cmd.returns_void else " {}"
        if not allowed_in_begin_end(n):
            w(f"  if (ctx.inside_begin_end()) {{\n    record_error(ctx, GL_INVALID_OPERATION);\n"
              f"    return{ret_default};\n  }}\n")
        w(f"  if (impl::{target} == nullptr) {{\n    unimplemented(ctx, CommandId::{n});\n"
          f"    return{ret_default};\n  }}\n")
        w(f"  return impl::{target}({args});\n}}\n\n")

    # Display-list record structs and replay.
    plans = {}
    for n in names:
        if compiled(n):
            plans[n] = record_plan(commands[n])
    for n, plan in plans.items():
        if plan is None or plan == "hand":
            continue
        cmd = commands[n]
        w(f"struct Rec_{n} {{\n")
        for p in cmd.params:
            if plan.get(p.name) == "client image":
                w(f"  uint32_t {p.name}_offset;\n  uint32_t {p.name}_bytes;\n"
                  f"  bool {p.name}_present;\n")
            elif p.is_pointer:
                w(f"  uint32_t {p.name}_offset;\n  uint32_t {p.name}_count;\n")
            else:
                w(f"  {p.ctype} {p.name};\n")
        if not cmd.params:
            w("  uint8_t unused;\n")
        w("};\n\n")
    w("}  // namespace\n\n")

    w("void replay_list(Context& ctx, const ListStream& list) {\n"
      "  for (ListStream::Reader r(list); !r.done(); r.next()) {\n"
      "    switch (r.command()) {\n")
    for n, replay in HAND_REPLAYED.items():
        if n in names:
            w(f"      case CommandId::{n}:\n        {replay}(ctx, r);\n        break;\n")
    for n, plan in plans.items():
        if plan is None or plan == "hand":
            continue
        cmd = commands[n]
        w(f"      case CommandId::{n}: {{\n")
        if cmd.params:
            w(f"        const auto rec = r.record<Rec_{n}>();\n")
        if "client image" in plan.values():
            w("        const DefaultUnpackModes unpack_defaults(ctx);  // the image's own layout\n")
        args = []
        for p in cmd.params:
            if plan.get(p.name) == "client image":
                elem = p.ptype or "void"
                args.append(f"rec.{p.name}_present ? r.payload<{elem}>(rec.{p.name}_offset) : nullptr")
            elif p.is_pointer:
                elem = CUSTOM_ARRAY_COUNTS.get((core_name(cmd.name), p.name), (p.ptype,))[0]
                args.append(f"r.payload<{elem}>(rec.{p.name}_offset)")
            else:
                args.append(f"rec.{p.name}")
        w(f"        exec_{n}({', '.join(['ctx'] + args)});\n        break;\n      }}\n")
    w("      default:\n        unimplemented(ctx, r.command());\n        break;\n")
    w("    }\n  }\n}\n\n}  // namespace glpt\n\n")

    # Exported entry points (declared in gl_entry_decls.h).
    w('extern "C" {\n\n')
    for n in names:
        cmd = commands[n]
        params = ", ".join(p.decl() for p in cmd.params) or "void"
        args = ", ".join(["*ctx"] + [p.name for p in cmd.params])
        ret_default = "" if cmd.returns_void else " {}"
        if compiled(n) and plans[n] not in (None, "hand"):
            emit_compile_function(w, n, cmd, plans[n])
        w(f"static inline {cmd.ret} entry_{n}({params}) {{\n")
        w("  glpt::Context* ctx = glpt::current_context();\n")
        w(f"  if (ctx == nullptr) return{ret_default};\n")
        as_vector = COMPILED_AS_VECTOR.get(core_name(n))
        if as_vector is not None and compiled(n):
            vector, elem, length = as_vector
            scalar = cmd.params[-1].name
            zeros = ", ".join(["0"] * (length - 1))
            w("  if (ctx->list_being_compiled() != nullptr) {\n")
            w(f"    const {elem} values[{length}] = {{static_cast<{elem}>({scalar}), {zeros}}};\n")
            w(f"    return ::{vector}({', '.join([p.name for p in cmd.params[:-1]] + ['values'])});\n")
            w("  }\n")
        if compiled(n):
            plan = plans[n]
            if plan is None:
                w("  if (ctx->list_being_compiled() != nullptr) {\n")
                w(f"    glpt::not_compilable(*ctx, glpt::CommandId::{n});\n")
            elif plan == "hand":
                w("  if (glpt::ListStream* glpt_list = ctx->list_being_compiled()) {\n")
                args_list = ", ".join(["*ctx", "*glpt_list"] + [p.name for p in cmd.params])
                w(f"    {HAND_COMPILED[core_name(n)]}({args_list});\n")
            else:
                # Recording into a list is out of line (compile_*, emitted before this entry
                # point, which also executes the call where GL does): the path every
                # immediate-mode call takes stays a few instructions.
                compile_args = ", ".join(["*ctx", "*glpt_list"] + [p.name for p in cmd.params])
                w("  if (glpt::ListStream* glpt_list = ctx->list_being_compiled()) [[unlikely]]\n")
                w(f"    return compile_{n}({compile_args});\n")
            if plan is None or plan == "hand":
                w(f"    if (!ctx->list_executes_while_compiling()) return{ret_default};\n  }}\n")
        if cmd.returns_void:
            w(f"  glpt::exec_{n}({args});\n}}\n\n")
        else:
            w(f"  return glpt::exec_{n}({args});\n}}\n\n")
        # No C++ exception leaves an entry point: allocation failure is GL_OUT_OF_MEMORY.
        call = ", ".join(p.name for p in cmd.params)
        w(f"GLPT_EXPORT {cmd.ret} {n}({params}) {{\n  try {{\n    return entry_{n}({call});\n"
          f"  }} catch (...) {{\n    glpt::exception_at_entry_point();\n    return{ret_default};\n"
          "  }\n}\n\n")
    w("}  // extern \"C\"\n\n")

    # Name table for glXGetProcAddress: sorted, with whether an implementation exists.
    w("namespace glpt {\n\nconst GlProcEntry* gl_proc_table(size_t* count) {\n")
    w("  static const GlProcEntry table[] = {\n")
    for n in sorted(names):
        target = impl_name(commands[n], commands)
        w(f'      {{"{n}", reinterpret_cast<GlProc>(&::{n}), '
          f'reinterpret_cast<GlProc>(&impl::{target}) != nullptr}},\n')
    w("  };\n  *count = sizeof(table) / sizeof(table[0]);\n  return table;\n}\n\n")

    # glGetString(GL_EXTENSIONS) and the commands it promises. Each name is followed by a space,
    # as in Mesa's string (piglit's glinfo prints the names up to each space).
    registry = {e.get("name"): e for e in gl_root.iter("extension")}
    promised = []
    for ext in ADVERTISED_GL_EXTENSIONS:
        if ext in UNREGISTERED_ADVERTISED_EXTENSIONS:
            continue  # no commands to promise
        if ext not in registry:
            sys.exit(f"gen_gl_api: advertised extension {ext} is not in gl.xml")
        for req in registry[ext].findall("require"):
            if req.get("api") not in (None, "gl"):
                continue
            for c in req.findall("command"):
                if c.get("name") not in names:
                    sys.exit(f"gen_gl_api: {ext} needs {c.get('name')}, which glpt does not export")
                if c.get("name") not in promised:
                    promised.append(c.get("name"))
    w("const char* gl_extensions_string() {\n  return\n")
    for ext in ADVERTISED_GL_EXTENSIONS:
        w(f'      "{ext} "\n')
    w("      ;\n}\n\n")
    w("const char* const* advertised_extension_commands(size_t* count) {\n"
      "  static const char* const names[] = {\n")
    for c in promised:
        w(f'      "{c}",\n')
    w("  };\n  *count = sizeof(names) / sizeof(names[0]);\n  return names;\n}\n\n"
      "}  // namespace glpt\n")
    with open(path, "w") as f:
        f.write("".join(out))


# ----------------------------------------------------------------------------------------------
# Attribute families: glColor3ub, glVertex2iv, glMultiTexCoord4d, glSecondaryColor3us,
# glFogCoordd, glEdgeFlagv, glIndexub, ... Each member converts its arguments as GL 1.5 spec
# table 2.9 says (evaluated as Mesa evaluates it, see state/normalized_values.hpp) and calls one
# hand-written function (geometry/attributes.hpp).

ATTRIBUTE_FAMILY = re.compile(
    r"^gl(Vertex|Normal|Color|TexCoord|MultiTexCoord|SecondaryColor|FogCoord|EdgeFlag|Index)"
    r"([1-4]?)(b|s|i|f|d|ub|us|ui|)(v?)$")


class Family:
    """How the members of one family convert and deliver their components."""

    def __init__(self, setter, width, conversion, sized=True, typed=True):
        self.setter = setter
        self.width = width            # components the setter takes (1: a scalar)
        self.conversion = conversion  # C++ function applied to each argument
        self.sized = sized            # names carry a component count (glColor3f vs glFogCoordf)
        self.typed = typed            # names carry a type suffix (glEdgeFlag has none)


FAMILIES = {
    "Vertex": Family("attribute_vertex", 4, "float_component"),
    "Normal": Family("attribute_normal", 3, "normalized_component"),
    "Color": Family("attribute_color", 4, "normalized_component"),
    "TexCoord": Family("attribute_tex_coord", 4, "float_component"),
    "MultiTexCoord": Family("attribute_multi_tex_coord", 4, "float_component"),
    "SecondaryColor": Family("attribute_secondary_color", 3, "normalized_component"),
    "FogCoord": Family("attribute_fog_coord", 1, "float_component", sized=False),
    "EdgeFlag": Family("attribute_edge_flag", 1, "0 != ", sized=False, typed=False),
    "Index": Family("attribute_index", 1, "float_component", sized=False),
}


def attribute_family_member(name):
    """(Family, family name, vector form) for a member of an attribute family, else None."""
    m = ATTRIBUTE_FAMILY.match(name)
    if not m:
        return None
    family = FAMILIES[m.group(1)]
    if bool(m.group(2)) != family.sized or bool(m.group(3)) != family.typed:
        return None
    return family, m.group(1), m.group(4) == "v"


def attribute_family_body(name, commands):
    """The statements of a generated attribute setter (the argument conversion and the family's
    canonical setter), or None when `name` is no family member implemented by its own name."""
    member = attribute_family_member(name)
    if not member or impl_name(commands[name], commands) != name:
        return None
    family, family_name, vector = member
    params = list(commands[name].params)
    lead = []
    if family_name == "MultiTexCoord":
        lead = [params[0].name]
        params = params[1:]
    conv = family.conversion
    if vector:
        count = int(ATTRIBUTE_FAMILY.match(name).group(2) or "1")
        comps = [f"{conv}({params[0].name}[{i}])" for i in range(count)]
    else:
        comps = [f"{conv}({p.name})" for p in params]
    if family.width == 1:
        value = comps[0]
    else:
        defaults = ["0.0f", "0.0f", "0.0f", "1.0f"]  # missing components: (0, 0, 0, 1)
        comps += defaults[len(comps):family.width]
        value = f"glm::vec{family.width}({', '.join(comps)})"
    body = f"  if ({params[0].name} == nullptr) return;\n" if vector else ""
    return body + f"  {family.setter}({', '.join(['ctx'] + lead + [value])});\n"


def emit_attribute_families(path, names, commands):
    out = [HEADER, '#include <glm/glm.hpp>\n\n#include "gl_shim/geometry/attributes.hpp"\n'
           '#include "gl_shim/gl_impl_decls.hpp"\n\nnamespace glpt::impl {\n\n']
    for n in names:
        body = attribute_family_body(n, commands)
        if body is None:
            continue
        out.append(impl_signature(commands[n], n) + " {\n" + body + "}\n\n")
    out.append("}  // namespace glpt::impl\n")
    with open(path, "w") as f:
        f.write("".join(out))


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--gl-xml", required=True)
    ap.add_argument("--glx-xml", required=True)
    ap.add_argument("--out", required=True,
                    help="directory for the generated front-end files (gl_shim/...)")
    ap.add_argument("--enums-out", required=True,
                    help="directory for gl_enums.h and glx_enums.h, shared with rt_core (gl/...)")
    args = ap.parse_args()

    gl = ET.parse(args.gl_xml).getroot()
    commands = parse_commands(gl)
    names, enum_names = collect(gl, "gl", GL_FEATURES, GL_EXTENSIONS, GL_ENUM_ONLY_EXTENSIONS)
    enum_names += [e for e in GL_TOOL_QUERY_ENUMS + GL_2_0_POINT_SPRITE_ENUMS if e not in enum_names]
    # Aliased core commands must exist for their aliases to use them.
    for n in list(names):
        a = alias_of(commands[n])
        if a and a in commands and a not in names:
            names.append(a)
    emit_enums(f"{args.enums_out}/gl_enums.h", enum_names, parse_enums(gl, "gl"), "GL 1.0-1.5 + extensions")
    emit_commands_header(f"{args.out}/gl_commands.hpp", names)
    emit_impl_decls(f"{args.out}/gl_impl_decls.hpp", names, commands)
    emit_entry_decls(f"{args.out}/gl_entry_decls.h", names, commands)
    emit_entry_points(f"{args.out}/gl_entry_points.cpp", names, commands, gl)
    emit_attribute_families(f"{args.out}/gl_attribute_families.cpp", names, commands)

    glx = ET.parse(args.glx_xml).getroot()
    _, glx_enums = collect(glx, "glx", GLX_FEATURES, GLX_EXTENSIONS)
    emit_enums(f"{args.enums_out}/glx_enums.h", glx_enums, parse_enums(glx, "glx"), "GLX 1.0-1.4 + extensions")


if __name__ == "__main__":
    main()
