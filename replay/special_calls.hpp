// The GL commands replayed by hand: those whose outputs the replay needs (generated names,
// mapped memory) or must keep alive (selection and feedback buffers), and argument shapes the
// generated conversions do not cover. The generated table (gen/gen_replay_dispatch.py, HAND)
// points at these.
#pragma once

#include "replay/call_context.hpp"

namespace glpt::replay::hand {

// glGen*: generate as many names, and map the recorded ones to them.
void glGenTextures(CallContext& c);
void glGenTexturesEXT(CallContext& c);
void glGenBuffers(CallContext& c);
void glGenBuffersARB(CallContext& c);
void glGenQueries(CallContext& c);
void glGenQueriesARB(CallContext& c);
void glGenFramebuffers(CallContext& c);
void glGenFramebuffersEXT(CallContext& c);
void glGenRenderbuffers(CallContext& c);
void glGenRenderbuffersEXT(CallContext& c);
void glGenLists(CallContext& c);
// Read into scratch memory: the values are not needed, but the read is a flush point of the
// frame record and must happen where the program did it.
void glReadPixels(CallContext& c);
// The buffer lives in the context's replay state until the next call replaces it.
void glFeedbackBuffer(CallContext& c);
void glSelectBuffer(CallContext& c);
// Mapped ranges are remembered for the tracer's fake memcpy calls (replay_memcpy).
void glMapBuffer(CallContext& c);
void glMapBufferARB(CallContext& c);
void glUnmapBuffer(CallContext& c);
void glUnmapBufferARB(CallContext& c);
// An array of index blobs (or offsets into the element buffer).
void glMultiDrawElements(CallContext& c);
void glMultiDrawElementsEXT(CallContext& c);

}  // namespace glpt::replay::hand

namespace glpt::replay {

// apitrace's fake `memcpy(dest, src, n)`: writes a blob into a range mapped by glMapBuffer,
// found by the address the mapping had when recording. Returns false if `dest` is in no mapping.
bool replay_memcpy(const trace::Call& call, ReplayContextState& state);

}  // namespace glpt::replay
