#include "report/sweep.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>

#include "gl/dispatch.h"
#include "mesh/icosphere.h"
#include "mesh/normals.h"
#include "report/ideal.h"
#include "report/metrics.h"
#include "scene/scene.h"

namespace ffc::report {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

const std::vector<std::string>& lighting_names() {
  static const std::vector<std::string> n = {"seed", "specular"};
  return n;
}

Lighting lighting(const std::string& name, int size) {
  if (name != "seed" && name != "specular")
    throw std::invalid_argument("unknown lighting setup '" + name + "' (seed or specular)");
  if (size <= 0) throw std::invalid_argument("picture size must be positive");
  // The built-in icosphere scene is seed 004: its camera, light and material, without the object.
  scene::Description d = scene::describe(scene::builtin("icosphere"));
  d.objects.clear();
  d.name = name;
  d.width = d.height = size;
  d.background = {0, 0, 0, 0};
  if (name == "specular") {
    // The cube lab's light and material (scene::describe for "cube"), on the sphere.
    scene::Light& l0 = d.lights[0];
    l0 = scene::default_light(0);
    l0.enabled = true;
    l0.position = {3, 4, 5, 1};
    l0.space = scene::Space::World;
    l0.ambient = {.1f, .1f, .1f, 1};
    l0.diffuse = l0.specular = {1, 1, 1, 1};
    d.front = scene::Material();
    d.front.ambient = d.front.diffuse = {1, 0, 0, 1};
    d.front.specular = {1, 1, 1, 1};
    d.front.shininess = 10;
  }
  return {name, d};
}

const std::vector<Shading>& shadings() {
  using mesh::NormalSource;
  static const std::vector<Shading> s = {{"flat", scene::Shade::Flat, NormalSource::Face},
                                         {"smooth-average", scene::Shade::Smooth, NormalSource::Average},
                                         {"smooth-area", scene::Shade::Smooth, NormalSource::Area},
                                         {"smooth-angle", scene::Shade::Smooth, NormalSource::Angle},
                                         {"smooth-max", scene::Shade::Smooth, NormalSource::Max},
                                         {"smooth-sphere", scene::Shade::Smooth, NormalSource::Sphere}};
  return s;
}

const Shading& shading(const std::string& name) {
  for (const Shading& s : shadings())
    if (s.name == name) return s;
  std::string all;
  for (const Shading& s : shadings()) all += (all.empty() ? "" : ", ") + s.name;
  throw std::invalid_argument("unknown shading '" + name + "' (" + all + ")");
}

DepthMesh::DepthMesh(int depth) : depth_(depth), mesh_(mesh::make_icosphere(depth)) {}

const mesh::DrawArrays& DepthMesh::arrays(const Shading& s) {
  for (const auto& [name, a] : arrays_)
    if (name == s.name) return *a;
  arrays_.emplace_back(s.name, std::make_unique<mesh::DrawArrays>(mesh::draw_arrays(mesh::layout(mesh_, s.normals))));
  return *arrays_.back().second;
}

double DepthMesh::normals_ms(const Shading& s, int runs) {
  std::vector<double> t;
  for (int r = 0; r < std::max(1, runs); ++r) {
    if (s.normals == mesh::NormalSource::Face || s.normals == mesh::NormalSource::Average) {
      mesh::Mesh m = mesh_;  // the copy is not timed
      const auto t0 = Clock::now();
      if (s.normals == mesh::NormalSource::Average)
        mesh::update_normals(m);  // what make_icosphere did: face normals, then OpenMesh's average
      else
        m.update_face_normals();
      t.push_back(ms_since(t0));
    } else {
      const auto t0 = Clock::now();
      const std::vector<mesh::Vec3> n = mesh::vertex_normals(mesh_, s.normals);
      t.push_back(ms_since(t0));
      if (n.size() != mesh_.n_vertices()) throw std::logic_error("vertex_normals: wrong count");
    }
  }
  return median(t);
}

scene::Description describe(const Lighting& l, int depth, const Shading& s) {
  scene::Description d = l.scene;
  d.shade = s.shade;
  scene::Object o;
  o.kind = scene::Object::Kind::Icosphere;
  o.depth = depth;
  o.normals = s.normals;
  o.draw = scene::DrawPath::Auto;
  d.objects.push_back(o);
  return d;
}

image::Image frame(const Lighting& l, const Shading& s, const mesh::DrawArrays& a, backends::Backend& b) {
  image::Image out;
  frame(l, s, a, b, out);
  return out;
}

void frame(const Lighting& l, const Shading& s, const mesh::DrawArrays& a, backends::Backend& b, image::Image& out) {
  scene::Description state = l.scene;
  state.shade = s.shade;
  state.objects.clear();
  scene::draw(state);  // clear, camera, lights, materials, shade model: the object left out
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, a.positions.data());
  glNormalPointer(GL_FLOAT, 0, a.normals.data());
  if (a.indexed())
    glDrawElements(GL_TRIANGLES, GLsizei(a.indices.size()), GL_UNSIGNED_INT, a.indices.data());
  else
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(a.vertex_count()));
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  b.read_into(out);
}

SweepResult run_sweep(const SweepOptions& o, const Progress& progress) {
  if (o.min_depth < 0 || o.max_depth > 12 || o.min_depth > o.max_depth)
    throw std::invalid_argument("depths " + std::to_string(o.min_depth) + ".." + std::to_string(o.max_depth) +
                                " are not within 0..12");
  if (o.frames < 1 || o.frames_deep < 1) throw std::invalid_argument("at least one timed frame per picture");
  const auto t_start = Clock::now();
  std::vector<Lighting> setups;
  for (const std::string& n : o.lightings) setups.push_back(lighting(n, o.size));
  std::vector<const Shading*> shade_list;
  if (o.shadings.empty())
    for (const Shading& s : shadings()) shade_list.push_back(&s);
  else
    for (const std::string& n : o.shadings) shade_list.push_back(&shading(n));
  std::vector<std::unique_ptr<backends::Backend>> backs;
  for (const std::string& n : o.backends) backs.push_back(backends::make(n));

  SweepResult r;
  for (const Lighting& l : setups) {
    r.ideals.emplace_back(l.name, ray_cast_sphere(l.scene));
    r.floors.emplace_back(l.name, rounding_floor(r.ideals.back().second));
  }

  const size_t per_depth = setups.size() * shade_list.size() * backs.size();
  const size_t pictures = size_t(o.max_depth - o.min_depth + 1) * per_depth;
  // Expected cost of a picture: its frames (the timed ones and the warm-up) times a fixed cost
  // plus one proportional to the triangles.
  auto cost = [&](int depth) {
    const int frames = (depth >= o.deep_depth ? o.frames_deep : o.frames) + 1;
    return size_t(frames) * ((size_t(20) << (2 * depth)) / 64 + 400);
  };
  size_t total = 0, done = 0, picture = 0;
  for (int depth = o.min_depth; depth <= o.max_depth; ++depth) total += cost(depth) * per_depth;
  for (int depth = o.min_depth; depth <= o.max_depth; ++depth) {
    DepthMesh dm(depth);
    const int frames = depth >= o.deep_depth ? o.frames_deep : o.frames;
    std::map<std::string, double> normals_ms;
    for (const Shading* s : shade_list) normals_ms[s->name] = dm.normals_ms(*s, frames);
    const bool keep = std::find(o.keep_depths.begin(), o.keep_depths.end(), depth) != o.keep_depths.end();
    for (size_t li = 0; li < setups.size(); ++li) {
      const Lighting& l = setups[li];
      const Ideal& ideal = r.ideals[li].second;
      for (const Shading* s : shade_list) {
        const mesh::DrawArrays& arrays = dm.arrays(*s);
        for (auto& b : backs) {
          // Per-fragment lighting is a smooth shading: flat pictures are left to the others.
          if (b->name() == "glsl-phong" && s->shade == scene::Shade::Flat) continue;
          ++picture;
          if (progress)
            progress(done, total,
                     "picture " + std::to_string(picture) + "/" + std::to_string(pictures) + ": depth " +
                         std::to_string(depth) + " " + l.name + " " + s->name + " " + b->name());
          b->begin(l.scene.width, l.scene.height);
          const image::Image picture = frame(l, *s, arrays, *b);  // warm-up: compiles, allocates
          std::vector<double> ms;
          double timed = 0;
          image::Image again;
          while (int(ms.size()) < frames || (timed < o.min_timed_ms && int(ms.size()) < o.max_frames)) {
            if (ms.empty()) frame(l, *s, arrays, *b, again);  // the reused picture's memory, untimed
            const auto t0 = Clock::now();
            frame(l, *s, arrays, *b, again);
            ms.push_back(ms_since(t0));
            timed += ms.back();
          }
          const ShadingError e = shading_error(picture, ideal);
          Row row;
          row.depth = depth;
          row.shading = s->name;
          row.shade_model = scene::to_string(s->shade);
          row.normals = mesh::to_string(s->normals);
          row.scene = l.name;
          row.backend = b->name();
          row.triangles = dm.triangles();
          row.vertices = dm.vertices();
          row.rmse = e.rmse;
          row.rmse_exact = e.rmse_exact;
          row.max_error = e.max_error;
          row.both_pixels = e.both;
          row.silhouette_pixels = e.silhouette;
          row.silhouette_share = e.silhouette_share;
          row.ms_per_frame = median(ms);
          row.frames = int(ms.size());
          row.normals_ms = normals_ms[s->name];
          r.rows.push_back(row);
          if (keep && b->name() == o.keep_backend &&
              std::find(o.keep_shadings.begin(), o.keep_shadings.end(), s->name) != o.keep_shadings.end())
            r.kept.push_back({l.name, s->name, depth, picture});
          done += cost(depth);
        }
      }
    }
  }
  if (progress) progress(done, total, "done");
  r.seconds = ms_since(t_start) / 1000;
  return r;
}

}  // namespace ffc::report
