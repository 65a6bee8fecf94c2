// Occlusion query objects (GL 1.5 4.1.6 and 6.1.12; ARB_occlusion_query's commands are the same).
//
// Query objects belong to one context: GL 1.5 shares only display lists, texture objects and
// buffer objects (appendix D), ARB_occlusion_query resolves "Are query objects shareable between
// multiple contexts? No", and Mesa keeps them in the context (another context of the share group
// does not see them and generates the same names again; checked against OSMesa).
//
// glBeginQuery and glEndQuery go into the frame record (rec::BeginQuery, rec::EndQuery) under an
// id unique to that glBeginQuery; the renderer counts the samples of the commands between them
// when it executes the record, and count_query_samples hands them back. A query's result is
// therefore known once every record holding its commands has been executed: GL_QUERY_RESULT
// executes the record then (as glReadPixels does), GL_QUERY_RESULT_AVAILABLE answers false the
// first time it is asked about a result that is not known yet (Mesa's llvmpipe answers false
// until its rasterizer has finished, which it only starts then) and executes the record when
// asked again, so polling ends without the program drawing more (ARB_occlusion_query: the
// first poll flushes).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "gl_shim/gl_types.h"
#include "rt_core/renderer.hpp"

namespace glpt {

class Context;

// Mesa 25's GL_QUERY_COUNTER_BITS for GL_SAMPLES_PASSED on llvmpipe (and glpt counts in 64 bits).
inline constexpr GLint kQueryCounterBits = 64;

struct QueryObject {
  // A name is a query object for glIsQuery and glGetQueryObject* once glBeginQuery used it
  // (Mesa's EverBound); glGenQueries only reserves it.
  bool begun = false;
  uint64_t id = 0;       // the record id of its last glBeginQuery
  uint64_t samples = 0;  // counted so far for that glBeginQuery
  bool ended = false;    // its glEndQuery (or glDeleteQueries) was recorded
  bool known = true;     // every record with its commands was executed: the result is available
  bool polled = false;   // GL_QUERY_RESULT_AVAILABLE answered false for it once
};

struct QueryState {
  std::unordered_map<GLuint, QueryObject> objects;  // generated names and query objects
  // Mesa hands out names after the largest one ever used (by glGenQueries or glBeginQuery), and
  // searches from 1 only when that would pass 2^32 - 2.
  GLuint highest_name = 0;
  GLuint active = 0;  // the GL_SAMPLES_PASSED query between glBeginQuery and glEndQuery, or 0
  uint64_t next_id = 1;
  // Record ids whose samples may still arrive, and the name they count for.
  std::unordered_map<uint64_t, GLuint> counting;

  // The record id of the active query (what a new record starts counting into), or 0.
  uint64_t active_id() const;
};

// A record was executed (`samples`: what the renderer counted, empty if it could not execute):
// adds the samples to their queries; queries ended before it are known from now on.
void count_query_samples(QueryState& queries, const std::vector<rt::QuerySamples>& samples);

}  // namespace glpt
