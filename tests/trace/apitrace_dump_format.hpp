// Prints glpt's trace model in the text format of `apitrace dump -v --color=never
// --thread-ids=yes` (apitrace 11.1), so the reader's output can be compared with what apitrace's
// own parser makes of the same file. Test code: it is the adapter between the two formats, not
// an oracle; the expected text comes from apitrace.
#pragma once

#include <ostream>
#include <string>

#include "replay/trace/trace_model.hpp"
#include "replay/trace/trace_reader.hpp"

namespace glpt::trace::testing {

void dump_value(std::ostream& os, const Value& value);
void dump_call(std::ostream& os, const Call& call);
// The property comments apitrace prints before the calls.
void dump_properties(std::ostream& os, const TraceReader& reader);

// Reads a whole trace into apitrace's dump text; `error` gets the reader's error if any.
std::string dump_trace(TraceReader& reader, std::string& error);

}  // namespace glpt::trace::testing
