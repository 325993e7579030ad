// The fixed functions after lighting that the generated programs carry when the key asks for them:
// fog (GL 2.1 section 3.10) and the alpha test (section 4.1.4). Both computed as Mesa computes
// them for llvmpipe, the way soft's rasterizer reproduces it: the fog coordinate per vertex (the
// eye-space |z|, as ffvertex_prog.c), interpolated with perspective, the factor per fragment
// from prog_statevars.c's optimized parameters; the alpha compared as an 8-bit value against
// the 8-bit reference (llvmpipe tests a unorm8 buffer's alpha at its precision).
#pragma once
#include <string>
#include <vector>

#include "backends/glsl/shader_gen.h"

namespace ffc::glsl {

// The key's fog and alpha-test fields from the state.
void feature_key(ProgramKey& k, const state::SinkState& s);

// The uniforms these features read (appended; zeros when s is null).
void feature_uniforms(const ProgramKey& k, const state::SinkState* s, std::vector<Uniform>& out);

// Vertex stage: `out float v_fog;` and its value, from `eye` (eye-space position) when the
// coordinate is the depth. Empty when fog is off.
std::string fog_vertex_declarations(const ProgramKey& k);
std::string fog_vertex_code(const ProgramKey& k);

// Fragment stage: the declarations (the uniforms too unless the stage declares every uniform
// already), and the code run on o_color after the colour sum.
std::string feature_fragment_declarations(const ProgramKey& k, bool uniforms);
std::string feature_fragment_code(const ProgramKey& k);

}  // namespace ffc::glsl
