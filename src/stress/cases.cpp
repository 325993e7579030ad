// The stress catalogue: stiff and extreme inputs to the fixed-function pipeline, each a small GL
// program, with what OpenGL 2.1 (compatibility profile) says about it and what Mesa 22.3
// (llvmpipe, through OSMesa) does. Section numbers are OpenGL 2.1's. Facts about Mesa quote its
// source: src/mesa/math/m_matrix.c (the float inverse of the modelview), src/mesa/main/light.c
// (light constants), src/mesa/main/state.c (the rescale factor), src/mesa/main/ffvertex_prog.c
// (the fixed-function vertex program llvmpipe runs).
//
// One file per group (stress/cases_<group>.cpp), built from the parts in stress/case_kit.h; this
// one puts the groups in the catalogue's order.
#include "stress/case_kit.h"

namespace ffc::stress {

const std::vector<Case>& catalogue() {
  static const std::vector<Case> cases = [] {
    std::vector<Case> out;
    kit::add_scale(out);
    kit::add_normals(out);
    kit::add_material(out);
    kit::add_spot(out);
    kit::add_attenuation(out);
    kit::add_positions_w(out);
    kit::add_viewer(out);
    kit::add_meshes(out);
    kit::add_viewports(out);
    kit::add_arrays(out);
    return out;
  }();
  return cases;
}

}  // namespace ffc::stress
