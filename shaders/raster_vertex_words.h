// The draw's vertex buffer as vec4s (GLPT_RASTER_BINDING_EDGES) and the per-vertex materials in
// it (glMaterial between glBegin and glEnd; RasterPushConstants::materials): read by
// raster_ff.vert, which lights each vertex with its own, and by the G-buffer variant of
// raster_ff.frag, which hands the triangle's to the trace pass. The including shader declares
// `push` (RasterPushConstants) first.
#ifndef GLPT_SHADERS_RASTER_VERTEX_WORDS_H
#define GLPT_SHADERS_RASTER_VERTEX_WORDS_H

layout(std430, set = 0, binding = GLPT_RASTER_BINDING_EDGES) readonly buffer VertexWords {
  vec4 vertex_words[];
};

// Vertex `index`'s material for `face` (0: front, 1: back) of a draw with per-vertex materials
// (push.materials.z != 0).
RasterMaterial vertex_material(uint index, uint face) {
  uint at = push.materials.x + index * push.materials.y + face * uint(GLPT_RASTER_MATERIAL_VEC4S);
  RasterMaterial m;
  m.ambient = vertex_words[at];
  m.diffuse = vertex_words[at + 1u];
  m.specular = vertex_words[at + 2u];
  m.emission = vertex_words[at + 3u];
  m.shininess = vertex_words[at + 4u];
  return m;
}

#endif  // GLPT_SHADERS_RASTER_VERTEX_WORDS_H
