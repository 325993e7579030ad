// Fog (glFog, GL 2.1 section 3.10) and polygon offset (glPolygonOffset, section 3.5.5): their
// state, errors and glGet values as Mesa 22.3's fog.c, polygon.c and get.c give them, and what
// the rasterizer is handed (raster::State), as the state tracker and llvmpipe derive it.
#include <algorithm>
#include <cmath>

#include "state/context.h"

namespace ffc::state {

// Each parameter flushes stored vertices only when it changes (Mesa's fog.c); the fog colour is
// compared clamped with the values given, as Mesa compares it, so an out-of-range colour always
// flushes.
void Context::Fogfv(GLenum pname, const GLfloat* params) {
  if (!outside_begin_end_keeping_vertices()) return;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum m = GLenum(GLint(params[0]));
      if (m != GL_LINEAR && m != GL_EXP && m != GL_EXP2) return error(GL_INVALID_ENUM);
      assign(fog_mode_, m);
      break;
    }
    case GL_FOG_DENSITY:
      if (params[0] < 0) return error(GL_INVALID_VALUE);
      assign(fog_density_, params[0]);
      break;
    case GL_FOG_START: assign(fog_start_, params[0]); break;
    case GL_FOG_END: assign(fog_end_, params[0]); break;
    case GL_FOG_INDEX: assign(fog_index_, params[0]); break;
    case GL_FOG_COLOR:
      if (!changes(fog_color_ != glm::vec4(params[0], params[1], params[2], params[3]))) return;
      for (int k = 0; k < 4; ++k) fog_color_[k] = std::clamp(params[k], 0.0f, 1.0f);
      break;
    case GL_FOG_COORD_SRC: {
      const GLenum src = GLenum(GLint(params[0]));
      if (src != GL_FOG_COORD && src != GL_FRAGMENT_DEPTH) return error(GL_INVALID_ENUM);
      assign(fog_coord_src_, src);
      break;
    }
    default: return error(GL_INVALID_ENUM);
  }
}

void Context::PolygonOffset(GLfloat factor, GLfloat units) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (changes(offset_factor_ != factor || offset_units_ != units)) offset_factor_ = factor, offset_units_ = units;
}

int Context::fog_values(GLenum pname, GLdouble* out, int& normalized) {
  normalized = kRound;
  switch (pname) {
    case GL_FOG_MODE: out[0] = fog_mode_; return 1;
    case GL_FOG_DENSITY: out[0] = fog_density_; return 1;
    case GL_FOG_START: out[0] = fog_start_; return 1;
    case GL_FOG_END: out[0] = fog_end_; return 1;
    case GL_FOG_INDEX: out[0] = fog_index_; return 1;
    case GL_FOG_HINT: out[0] = GL_DONT_CARE; return 1;  // glHint is not modelled: its default
    case GL_FOG_COORD_SRC: out[0] = fog_coord_src_; return 1;
    case GL_FOG_COLOR:
      for (int k = 0; k < 4; ++k) out[k] = fog_color_[k];
      normalized = kFromFloat;  // a colour: [-1, 1] onto the integers
      return 4;
    case GL_POLYGON_OFFSET_FACTOR: out[0] = offset_factor_; return 1;
    case GL_POLYGON_OFFSET_UNITS: out[0] = offset_units_; return 1;
    default: return 0;
  }
}

void Context::fog_raster_state(raster::State& rs) const {
  rs.fog = fog_;
  rs.fog_mode = fog_mode_;
  // prog_statevars.c STATE_FOG_PARAMS_OPTIMIZED: linear fog as one multiply-add, exp and exp2 as
  // powers of two.
  const float scale = fog_end_ == fog_start_ ? 1.0f : -1.0f / (fog_end_ - fog_start_);
  rs.fog_params[0] = scale;
  rs.fog_params[1] = fog_end_ * -scale;
  rs.fog_params[2] = float(fog_density_ * 1.442695040888963407359924681001892137);  // 1 / ln 2
  rs.fog_params[3] = float(fog_density_ * 1.201122408786449815);                     // 1 / sqrt(ln 2)
  for (int k = 0; k < 3; ++k) rs.fog_color[k] = fog_color_[k];
  rs.offset_fill = offset_fill_;
  rs.offset_factor = offset_factor_;
  // llvmpipe (lp_state_setup.c lp_make_setup_variant_key): the units times twice the minimum
  // resolvable difference of the 24-bit buffer, 1 / (2^24 - 1) (u_format.h
  // util_get_depth_format_mrd), computed in double and kept as a float.
  rs.offset_units = float(double(offset_units_) * (1.0 / 16777215.0) * 2);
}

}  // namespace ffc::state
