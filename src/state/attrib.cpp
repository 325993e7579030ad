// glPushAttrib / glPopAttrib and glPushClientAttrib / glPopClientAttrib (GL 2.1 section 6.1.14):
// the groups of table 6.x that this context models, kept on stacks 16 deep as Mesa's
// (GL_STACK_OVERFLOW and GL_STACK_UNDERFLOW past either end, nothing changed). A push keeps a
// copy of every modelled value; a pop restores the groups its push named.
#include "state/context.h"

namespace ffc::state {

namespace {
// The client arrays that enable.cpp records by name: the client's group, not the server's.
bool client_array(GLenum name) {
  return name == GL_TEXTURE_COORD_ARRAY || name == GL_INDEX_ARRAY || name == GL_EDGE_FLAG_ARRAY ||
         name == GL_FOG_COORD_ARRAY || name == GL_SECONDARY_COLOR_ARRAY;
}
}  // namespace

struct Context::AttribEntry {
  GLbitfield mask;
  FragmentState frag;
  bool lighting, normalize, rescale_normal, color_material, depth_test, cull_face, fog, offset_fill;
  std::map<GLenum, bool> other_enables;
  GLenum shade_model, front_face, cull_mode, depth_func, cm_face, cm_mode, matrix_mode;
  lighting::LightParams lights[8];
  lighting::MaterialParams materials[2];
  glm::dvec3 color_indexes[2];
  lighting::ModelParams model;
  float line_width, point_size;
  GLenum fog_mode, fog_coord_src;
  float fog_density, fog_start, fog_end, fog_index;
  glm::vec4 fog_color;
  float offset_factor, offset_units;
  GLenum polygon_mode[2];
  glm::ivec4 viewport;
  glm::dvec2 depth_range;
  glm::vec4 clear_color;
  double clear_depth;
  glm::dvec3 normal;
  glm::dvec4 color, flushed_color;
  RasterPosition raster_pos;
  glm::vec4 texcoord;  // with the edge flag: GL_CURRENT_BIT
  bool edge_flag;
  std::map<GLenum, GLenum> hints;  // GL_HINT_BIT
  GLuint list_base;                // GL_LIST_BIT
};

struct Context::ClientAttribEntry {
  GLbitfield mask;
  GLint pack_alignment, unpack_alignment;
  std::map<GLenum, GLint> pixel_store;
  ClientArray vertex_array, normal_array, color_array, texcoord_array;
  std::map<GLenum, bool> other_enables;
};

void Context::PushAttrib(GLbitfield mask) {
  if (!outside_begin_end()) return;
  if (attrib_stack_.size() >= kMaxAttribStackDepth) return error(GL_STACK_OVERFLOW);
  flush_current();  // the current values as they stand
  auto e = std::make_shared<AttribEntry>();
  e->mask = mask;
  e->frag = frag_;
  e->lighting = lighting_, e->normalize = normalize_, e->rescale_normal = rescale_normal_;
  e->color_material = color_material_, e->depth_test = depth_test_, e->cull_face = cull_face_;
  e->fog = fog_, e->offset_fill = offset_fill_;
  e->other_enables = other_enables_;
  e->shade_model = shade_model_, e->front_face = front_face_, e->cull_mode = cull_mode_;
  e->depth_func = depth_func_, e->cm_face = cm_face_, e->cm_mode = cm_mode_, e->matrix_mode = matrix_mode_;
  for (int i = 0; i < 8; ++i) e->lights[i] = lights_[i];
  e->materials[0] = materials_[0], e->materials[1] = materials_[1];
  e->color_indexes[0] = color_indexes_[0], e->color_indexes[1] = color_indexes_[1];
  e->model = model_;
  e->line_width = line_width_, e->point_size = point_size_;
  e->fog_mode = fog_mode_, e->fog_coord_src = fog_coord_src_, e->fog_density = fog_density_;
  e->fog_start = fog_start_, e->fog_end = fog_end_, e->fog_index = fog_index_, e->fog_color = fog_color_;
  e->offset_factor = offset_factor_, e->offset_units = offset_units_;
  e->polygon_mode[0] = polygon_mode_[0], e->polygon_mode[1] = polygon_mode_[1];
  e->viewport = viewport_, e->depth_range = depth_range_;
  e->clear_color = clear_color_, e->clear_depth = clear_depth_;
  e->normal = normal_, e->color = color_, e->flushed_color = flushed_color_;
  e->raster_pos = raster_pos_;
  e->texcoord = texcoord_, e->edge_flag = edge_flag_, e->hints = hints_, e->list_base = lists_.base;
  attrib_stack_.push_back(std::move(e));
}

void Context::PopAttrib() {
  if (!outside_begin_end()) return;
  if (attrib_stack_.empty()) return error(GL_STACK_UNDERFLOW);
  flush_current();
  const std::shared_ptr<AttribEntry> e = attrib_stack_.back();
  attrib_stack_.pop_back();
  const GLbitfield m = e->mask;
  // Capabilities recorded by name (enable.cpp): the ones of `names` back as they were pushed.
  auto restore_enables = [&](std::initializer_list<GLenum> names) {
    for (GLenum n : names) {
      const auto it = e->other_enables.find(n);
      if (it != e->other_enables.end()) other_enables_[n] = it->second;
      else other_enables_.erase(n);
    }
  };
  if (m & GL_CURRENT_BIT) {
    normal_ = e->normal, color_ = e->color, flushed_color_ = e->flushed_color;
    raster_pos_ = e->raster_pos;
    texcoord_ = e->texcoord, edge_flag_ = e->edge_flag;
  }
  if (m & GL_HINT_BIT) hints_ = e->hints;
  if (m & GL_LIST_BIT) lists_.base = e->list_base;
  if (m & GL_ENABLE_BIT) {
    const bool was_color_material = color_material_;
    lighting_ = e->lighting, normalize_ = e->normalize, rescale_normal_ = e->rescale_normal;
    color_material_ = e->color_material, depth_test_ = e->depth_test, cull_face_ = e->cull_face;
    fog_ = e->fog, offset_fill_ = e->offset_fill;
    // The lights' switches are not restored here (measured on Mesa 22.3: its enable group leaves
    // GL_LIGHT0..7 as they are; GL_LIGHTING_BIT restores them). Colour material switched back on
    // takes the current colour, as glEnable does.
    if (color_material_ && !was_color_material) update_color_material();
    frag_.scissor_test = e->frag.scissor_test, frag_.alpha_test = e->frag.alpha_test, frag_.blend = e->frag.blend;
    frag_.line_stipple = e->frag.line_stipple;
    std::map<GLenum, bool> kept;  // the client arrays' switches stay
    for (const auto& [name, on] : other_enables_)
      if (client_array(name)) kept[name] = on;
    for (const auto& [name, on] : e->other_enables)
      if (!client_array(name)) kept[name] = on;
    other_enables_ = kept;
  }
  if (m & GL_COLOR_BUFFER_BIT) {
    const FragmentState now = frag_;
    frag_ = e->frag;  // all but the scissor's, the depth buffer's and the line's
    frag_.scissor_test = now.scissor_test, frag_.scissor_box = now.scissor_box, frag_.depth_mask = now.depth_mask;
    frag_.line_stipple = now.line_stipple, frag_.stipple_factor = now.stipple_factor;
    frag_.stipple_pattern = now.stipple_pattern;
    clear_color_ = e->clear_color;
    restore_enables({GL_DITHER, GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP});
  }
  if (m & GL_DEPTH_BUFFER_BIT) {
    depth_test_ = e->depth_test, depth_func_ = e->depth_func, clear_depth_ = e->clear_depth;
    frag_.depth_mask = e->frag.depth_mask;
  }
  if (m & GL_FOG_BIT) {
    fog_ = e->fog, fog_mode_ = e->fog_mode, fog_coord_src_ = e->fog_coord_src, fog_density_ = e->fog_density;
    fog_start_ = e->fog_start, fog_end_ = e->fog_end, fog_index_ = e->fog_index, fog_color_ = e->fog_color;
  }
  if (m & GL_LIGHTING_BIT) {
    lighting_ = e->lighting, color_material_ = e->color_material, shade_model_ = e->shade_model;
    cm_face_ = e->cm_face, cm_mode_ = e->cm_mode;
    for (int i = 0; i < 8; ++i) lights_[i] = e->lights[i];
    materials_[0] = e->materials[0], materials_[1] = e->materials[1];
    note_materials_flushed();  // Mesa's pop writes its materials directly
    color_indexes_[0] = e->color_indexes[0], color_indexes_[1] = e->color_indexes[1];
    model_ = e->model;
  }
  if (m & GL_LINE_BIT) {
    line_width_ = e->line_width;
    frag_.line_stipple = e->frag.line_stipple;
    frag_.stipple_factor = e->frag.stipple_factor, frag_.stipple_pattern = e->frag.stipple_pattern;
    restore_enables({GL_LINE_SMOOTH});
  }
  if (m & GL_POINT_BIT) {
    point_size_ = e->point_size;
    restore_enables({GL_POINT_SMOOTH, GL_POINT_SPRITE});
  }
  if (m & GL_POLYGON_BIT) {
    cull_face_ = e->cull_face, cull_mode_ = e->cull_mode, front_face_ = e->front_face;
    offset_fill_ = e->offset_fill, offset_factor_ = e->offset_factor, offset_units_ = e->offset_units;
    polygon_mode_[0] = e->polygon_mode[0], polygon_mode_[1] = e->polygon_mode[1];
    restore_enables({GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT});
  }
  if (m & GL_SCISSOR_BIT) frag_.scissor_test = e->frag.scissor_test, frag_.scissor_box = e->frag.scissor_box;
  if (m & GL_TRANSFORM_BIT) {
    matrix_mode_ = e->matrix_mode, normalize_ = e->normalize, rescale_normal_ = e->rescale_normal;
    restore_enables({GL_CLIP_PLANE0, GL_CLIP_PLANE1, GL_CLIP_PLANE2, GL_CLIP_PLANE3, GL_CLIP_PLANE4, GL_CLIP_PLANE5});
  }
  if (m & GL_VIEWPORT_BIT) viewport_ = e->viewport, depth_range_ = e->depth_range;
  // Mesa restores the materials last, as they were pushed, whatever colour material says.
  constants_dirty_ = true;  // lights, materials or enables may have changed
}

void Context::PushClientAttrib(GLbitfield mask) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (client_attrib_stack_.size() >= kMaxAttribStackDepth) return error(GL_STACK_OVERFLOW);
  auto e = std::make_shared<ClientAttribEntry>();
  e->mask = mask;
  e->pack_alignment = pack_alignment_, e->unpack_alignment = unpack_alignment_, e->pixel_store = pixel_store_;
  e->vertex_array = vertex_array_, e->normal_array = normal_array_, e->color_array = color_array_;
  e->texcoord_array = texcoord_array_;
  e->other_enables = other_enables_;
  client_attrib_stack_.push_back(std::move(e));
}

void Context::PopClientAttrib() {
  if (!outside_begin_end_keeping_vertices()) return;
  if (client_attrib_stack_.empty()) return error(GL_STACK_UNDERFLOW);
  const std::shared_ptr<ClientAttribEntry> e = client_attrib_stack_.back();
  client_attrib_stack_.pop_back();
  if (e->mask & GL_CLIENT_PIXEL_STORE_BIT)
    pack_alignment_ = e->pack_alignment, unpack_alignment_ = e->unpack_alignment, pixel_store_ = e->pixel_store;
  if (e->mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
    vertex_array_ = e->vertex_array, normal_array_ = e->normal_array, color_array_ = e->color_array;
    texcoord_array_ = e->texcoord_array;
    for (GLenum n : {GLenum(GL_TEXTURE_COORD_ARRAY), GLenum(GL_INDEX_ARRAY), GLenum(GL_EDGE_FLAG_ARRAY),
                     GLenum(GL_FOG_COORD_ARRAY), GLenum(GL_SECONDARY_COLOR_ARRAY)}) {
      const auto it = e->other_enables.find(n);
      if (it != e->other_enables.end()) other_enables_[n] = it->second;
      else other_enables_.erase(n);
    }
  }
}

}  // namespace ffc::state
