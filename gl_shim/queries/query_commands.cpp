// glGenQueries, glDeleteQueries, glIsQuery, glBeginQuery, glEndQuery, glGetQueryiv,
// glGetQueryObjectiv, glGetQueryObjectuiv (GL 1.5 4.1.6, 6.1.12; the ARB_occlusion_query names
// share these). Errors, their order and the values are Mesa 25's (queryobj.c, checked with
// OSMesa: tests/unit/mesa_reference/mesa_query_probe.c). Where Mesa answers for later GL versions
// (GL_QUERY_TARGET, GL_QUERY_RESULT_NO_WAIT, other targets), glpt answers as GL 1.5:
// GL_INVALID_ENUM.
#include <algorithm>
#include <limits>

#include "gl/gl_enums.h"
#include "gl_shim/context.hpp"
#include "gl_shim/dispatch.hpp"
#include "gl_shim/gl_impl_decls.hpp"
#include "gl_shim/queries/query_objects.hpp"
#include "gl_shim/state/out_of_memory.hpp"

namespace glpt {

uint64_t QueryState::active_id() const {
  const auto it = objects.find(active);
  return active != 0 && it != objects.end() ? it->second.id : 0;
}

void count_query_samples(QueryState& queries, const std::vector<rt::QuerySamples>& samples) {
  for (const rt::QuerySamples& s : samples) {
    const auto run = queries.counting.find(s.id);
    if (run == queries.counting.end()) continue;
    const auto object = queries.objects.find(run->second);
    if (object == queries.objects.end() || object->second.id != s.id) continue;  // restarted
    uint64_t& total = object->second.samples;
    total = s.samples > std::numeric_limits<uint64_t>::max() - total
                ? std::numeric_limits<uint64_t>::max()  // saturates (ARB_occlusion_query)
                : total + s.samples;
  }
  // Everything recorded before this execution has been counted: queries that ended then are known.
  for (auto it = queries.counting.begin(); it != queries.counting.end();) {
    const auto object = queries.objects.find(it->second);
    const bool current = object != queries.objects.end() && object->second.id == it->first;
    if (current && !object->second.ended) {
      ++it;  // still active: later records count into it too
      continue;
    }
    if (current) object->second.known = true;
    it = queries.counting.erase(it);
  }
}

namespace {

bool valid_target(GLenum target) { return target == GL_SAMPLES_PASSED; }

// Records the end of the active query (glEndQuery, or deleting it).
void end_active_query(Context& ctx) {
  QueryObject& q = ctx.queries.objects.at(ctx.queries.active);
  ctx.recorder.add(rec::EndQuery{q.id});  // when this fails, the query stays active
  q.ended = true;
  ctx.queries.active = 0;
}

// Makes the result of `q` known: executes the record that holds the rest of its commands. Without
// a renderer (no drawable) nothing can count its samples; it is then known with those it has, as
// Mesa reports a query it could not create.
void make_known(Context& ctx, QueryObject& q) {
  if (q.known) return;
  execute_record(ctx);
  if (q.known) return;
  q.known = true;
  ctx.queries.counting.erase(q.id);
}

// The query object `id` names for glGetQueryObject*; null (GL_INVALID_OPERATION) if there is
// none, it was never begun, or it is active.
QueryObject* inactive_query(Context& ctx, GLuint id) {
  QueryState& queries = ctx.queries;
  const auto it = id == 0 ? queries.objects.end() : queries.objects.find(id);
  if (it == queries.objects.end() || !it->second.begun || id == queries.active) {
    record_error(ctx, GL_INVALID_OPERATION);
    return nullptr;
  }
  return &it->second;
}

// GL_QUERY_RESULT or GL_QUERY_RESULT_AVAILABLE of `id`; false after an error.
bool query_object_value(Context& ctx, GLuint id, GLenum pname, uint64_t& value) {
  QueryObject* q = inactive_query(ctx, id);
  if (q == nullptr) return false;
  switch (pname) {
    case GL_QUERY_RESULT:
      make_known(ctx, *q);
      value = q->samples;
      return true;
    case GL_QUERY_RESULT_AVAILABLE:
      if (!q->known && q->polled) make_known(ctx, *q);
      q->polled = true;
      value = q->known ? 1 : 0;
      return true;
    default:
      record_error(ctx, GL_INVALID_ENUM);
      return false;
  }
}

}  // namespace

namespace impl {

void glGenQueries(Context& ctx, GLsizei n, GLuint* ids) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (ids == nullptr || n == 0) return;
  QueryState& queries = ctx.queries;
  // Mesa's _mesa_HashFindFreeKeyBlock: after the largest name, else the first run of n free
  // names from 1; when there is none, nothing is generated (and no error).
  constexpr GLuint kLargestName = 0xFFFFFFFEu;
  GLuint first = 0;
  if (queries.highest_name <= kLargestName - GLuint(n)) {
    first = queries.highest_name + 1;
  } else {
    GLuint run = 0;
    for (GLuint name = 1; name != kLargestName && run < GLuint(n); ++name) {
      run = queries.objects.count(name) != 0 ? 0 : run + 1;
      if (run == 1) first = name;
    }
    if (run < GLuint(n)) return;
  }
  or_out_of_memory(ctx, [&] {
    for (GLsizei i = 0; i < n; ++i) {
      const GLuint name = first + GLuint(i);
      queries.objects.emplace(name, QueryObject{});
      queries.highest_name = std::max(queries.highest_name, name);
      ids[i] = name;
    }
  });
}

void glDeleteQueries(Context& ctx, GLsizei n, const GLuint* ids) {
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE);
  if (ids == nullptr) return;
  QueryState& queries = ctx.queries;
  or_out_of_memory(ctx, [&] {
    for (GLsizei i = 0; i < n; ++i) {
      if (ids[i] == 0) continue;
      const auto it = queries.objects.find(ids[i]);
      if (it == queries.objects.end()) continue;  // silently ignored
      // An active query ends first (Mesa; later GL versions say so); its samples are dropped.
      if (ids[i] == queries.active) end_active_query(ctx);
      queries.objects.erase(it);
    }
  });
}

GLboolean glIsQuery(Context& ctx, GLuint id) {
  const auto it = id == 0 ? ctx.queries.objects.end() : ctx.queries.objects.find(id);
  return it != ctx.queries.objects.end() && it->second.begun ? 1 : 0;
}

void glBeginQuery(Context& ctx, GLenum target, GLuint id) {
  if (!valid_target(target)) return record_error(ctx, GL_INVALID_ENUM);
  QueryState& queries = ctx.queries;
  if (queries.active != 0 || id == 0) return record_error(ctx, GL_INVALID_OPERATION);
  or_out_of_memory(ctx, [&] {
    // A name glGenQueries did not return becomes a query object here (compatibility contexts).
    // Each step that allocates leaves nothing half done when it fails (a stray `counting` entry
    // is dropped by the next count_query_samples).
    QueryObject& q = queries.objects[id];
    queries.highest_name = std::max(queries.highest_name, id);
    const uint64_t run = queries.next_id;
    queries.counting.emplace(run, id);
    // Also ends the batch of primitives before it, and Mesa's bitmap cache (its bitmaps are
    // drawn before the query begins: bitmap_cache.hpp).
    ctx.recorder.add(rec::BeginQuery{run});
    ++queries.next_id;
    q = QueryObject{};
    q.begun = true;
    q.id = run;
    q.known = false;
    queries.active = id;
  });
}

void glEndQuery(Context& ctx, GLenum target) {
  if (!valid_target(target)) return record_error(ctx, GL_INVALID_ENUM);
  if (ctx.queries.active == 0) return record_error(ctx, GL_INVALID_OPERATION);
  or_out_of_memory(ctx, [&] { end_active_query(ctx); });
}

void glGetQueryiv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  if (!valid_target(target)) return record_error(ctx, GL_INVALID_ENUM);
  GLint value = 0;
  switch (pname) {
    case GL_QUERY_COUNTER_BITS:
      value = kQueryCounterBits;
      break;
    case GL_CURRENT_QUERY:
      value = GLint(ctx.queries.active);
      break;
    default:
      return record_error(ctx, GL_INVALID_ENUM);
  }
  if (params != nullptr) *params = value;
}

void glGetQueryObjectiv(Context& ctx, GLuint id, GLenum pname, GLint* params) {
  uint64_t value = 0;
  if (!query_object_value(ctx, id, pname, value)) return;
  // Mesa saturates what does not fit.
  if (params != nullptr) *params = GLint(std::min<uint64_t>(value, 0x7FFFFFFF));
}

void glGetQueryObjectuiv(Context& ctx, GLuint id, GLenum pname, GLuint* params) {
  uint64_t value = 0;
  if (!query_object_value(ctx, id, pname, value)) return;
  if (params != nullptr) *params = GLuint(std::min<uint64_t>(value, 0xFFFFFFFF));
}

}  // namespace impl
}  // namespace glpt
