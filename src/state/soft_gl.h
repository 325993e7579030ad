// The loader of our own GL: resolves "glBegin" & co. to entry points that act on
// state::Context::current(), so ffc::gl::load(proc_address) binds the dispatch to it.
#pragma once

namespace ffc::state {
void* proc_address(const char* name);
}
