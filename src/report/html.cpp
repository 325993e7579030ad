// index.html of `ffcompat report`.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "report/paths.h"
#include "report/plot.h"
#include "report/report.h"

namespace ffc::report {

namespace {

std::string f(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string reach_html(const Reach& x) {
  if (std::isnan(x.triangles)) return "<i>not reached</i>";
  const std::string s = short_count(x.triangles);
  if (x.at_start) return "&le; " + s;
  if (x.extrapolated) return "<i>~" + s + " (extrapolated)</i>";
  return s;
}

// A path as the page shows it: relative to the folder ffcompat report ran in when it lies inside
// it, else its last two components, so that the page names no folder of the machine that made it.
std::string shown_path(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  if (!p.is_absolute()) return path;
  std::error_code ec;
  const fs::path rel = p.lexically_relative(fs::current_path(ec));
  if (!ec && !rel.empty() && *rel.begin() != "..") return rel.string();
  return p.has_parent_path() ? (p.parent_path().filename() / p.filename()).string() : p.filename().string();
}

const Row* find(const std::vector<Row>& rows, const std::string& scene, int depth, const std::string& shading,
                const std::string& backend) {
  for (const Row& r : rows)
    if (r.scene == scene && r.depth == depth && r.shading == shading && r.backend == backend) return &r;
  return nullptr;
}

template <class T>
std::vector<T> distinct(const std::vector<Row>& rows, T Row::*field) {
  std::vector<T> out;
  for (const Row& r : rows)
    if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
  return out;
}

const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 24px 32px; color: #222; max-width: 1320px; }
h1 { font-size: 24px; margin-bottom: 4px; }
h2 { font-size: 19px; margin-top: 34px; border-bottom: 1px solid #ccc; padding-bottom: 3px; }
h3 { font-size: 15px; margin: 20px 0 6px; }
p, li { line-height: 1.45; max-width: 1100px; }
.meta { color: #555; font-size: 13px; }
table { border-collapse: collapse; font-size: 13px; margin: 6px 0 14px; }
th, td { border: 1px solid #d4d4d4; padding: 3px 8px; text-align: right; }
th { background: #f1f1f1; font-weight: 600; }
td.l, th.l { text-align: left; }
tr:nth-child(even) td { background: #fafafa; }
.pics td, .pics th { text-align: center; vertical-align: top; background: white; }
.pics img { width: 210px; height: 210px; display: block; margin: 0 auto; }
.pics .cap { font-size: 12px; color: #444; margin-top: 3px; }
.thumb img { width: 96px; height: auto; display: block; }
.pass { color: #16794c; font-weight: 600; }
.fail { color: #b3261e; font-weight: 600; }
.chart { max-width: 100%; height: auto; border: 1px solid #e4e4e4; margin: 6px 0 12px; }
.swatch { display: inline-block; width: 12px; height: 12px; vertical-align: -1px; margin: 0 3px 0 10px; border: 1px solid #999; }
.headline { font-size: 16px; background: #f4f8fc; border-left: 4px solid #0072B2; padding: 8px 14px; }
details summary { cursor: pointer; font-weight: 600; margin: 8px 0; }
)";

}  // namespace

std::string html_page(const Report& r) {
  const SweepOptions& w = r.options.sweep;
  const std::vector<Row>& rows = r.sweep.rows;
  const auto scenes = distinct(rows, &Row::scene);
  const auto shadings = distinct(rows, &Row::shading);
  const auto backends = distinct(rows, &Row::backend);
  const auto depths = distinct(rows, &Row::depth);
  const std::string kb = w.keep_backend;
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<title>ffcompat report: flat vs smooth shading against the ideal sphere</title>\n<style>" << kStyle
    << "</style></head><body>\n";
  s << "<h1>ffcompat report: shading error against run time, GL_FLAT vs GL_SMOOTH</h1>\n";
  s << "<p class=\"meta\">" << rows.size() << " pictures: icosphere depths " << w.min_depth << "&ndash;" << w.max_depth
    << ", lighting setups";
  for (const auto& n : scenes) s << " <b>" << xml_escape(n) << "</b>";
  s << ", " << shadings.size() << " shadings, backends";
  for (const auto& b : backends) s << " <b>" << xml_escape(b) << "</b>";
  s << "; " << w.size << "&times;" << w.size << " pixels; median of " << w.frames << " timed frames (" << w.frames_deep
    << " from depth " << w.deep_depth;
  if (w.min_timed_ms > 0) s << "; fast pictures up to " << w.max_frames << ", until " << f("%g", w.min_timed_ms) << " ms are timed";
  s << ") after an untimed one. Sweep " << f("%.1f", r.sweep.seconds)
    << " s, regression checks " << f("%.1f", r.regression_seconds) << " s, total " << f("%.1f", r.seconds) << " s."
    << (r.options.quick ? " <b>Quick run</b> (ffcompat report --quick)." : "") << "</p>\n";

  s << "<p>Each picture is compared with the <b>ideal</b>: the exact unit sphere ray-cast through every pixel centre with "
       "the same camera (gluPerspective(45, 1, 1, 10), eye (0,0,4)), lit per pixel by the same lighting equation in "
       "double and converted to 8 bits as the renderers convert. That is what finer tessellation converges to. "
       "<b>rmse</b> and <b>max</b> are the shading error in 8-bit steps over the RGB channels of the pixels both "
       "cover; the <b>silhouette</b> (pixels only one of them covers: the inscribed polygon is smaller than the "
       "sphere) is counted apart. Rounding the ideal to 8 bits alone leaves an RMSE against its exact colours of ";
  for (size_t i = 0; i < r.sweep.floors.size(); ++i)
    s << (i ? ", " : "") << xml_escape(r.sweep.floors[i].first) << " " << f("%.3f", r.sweep.floors[i].second);
  s << " (measured in this run); the CSV's <code>rmse_exact</code> measures against the exact colours and so never drops below it, while "
       "<code>rmse</code> (against the ideal's 8 bits) reaches 0 when every pixel rounds alike.</p>\n";
  s << "<ul><li><b>seed</b>: seed 004's lighting: directional light 0 at its default (0,0,1,0) in eye space, ambient .2, "
       "diffuse 1, no specular; material ambient and diffuse (.8,.6,.4).</li>"
       "<li><b>specular</b>: the cube lab's: light 0 at (3,4,5,1) in the world, ambient .1, diffuse and specular 1; "
       "material red ambient and diffuse, white specular, shininess 10. Gouraud shading smears the highlight.</li>"
       "<li><b>flat</b>: face normals under GL_FLAT; <b>smooth-&lt;w&gt;</b>: GL_SMOOTH with vertex normals weighted "
       "by <i>average</i> (OpenMesh's unweighted mean of the face normals), <i>area</i>, <i>angle</i> or <i>max</i> "
       "(Max 1999), or the exact <i>sphere</i> normals.</li></ul>\n";

  // Headline.
  s << "<h2 id=\"headline\">Headline</h2>\n";
  for (const Headline& h : r.headlines) {
    s << "<p class=\"headline\"><b>" << xml_escape(h.scene) << "</b>: ";
    if (h.crossings.empty()) {
      s << "flat and smooth-average share no RMSE within this sweep.</p>\n";
      continue;
    }
    const Crossing& m = h.main;
    s << "to reach a shading RMSE of <b>" << f("%g", m.target_rmse) << "</b> steps, GL_FLAT needs <b>"
      << reach_html(m.flat) << "</b> triangles, GL_SMOOTH with averaged normals <b>" << reach_html(m.smooth)
      << "</b>: <b>" << ratio_text(m.ratio) << "&times;</b> as many";
    if (m.flat.ms > 0 && m.smooth.ms > 0)
      s << "; a frame then takes about " << f("%.3g", m.flat.ms) << " ms flat against " << f("%.3g", m.smooth.ms)
        << " ms smooth";
    s << " (" << xml_escape(h.backend) << "; interpolated log-log between depths).</p>\n";
    s << "<table><tr><th>target RMSE (steps)</th><th>flat needs</th><th>smooth-average needs</th><th>ratio</th>"
         "<th>flat ms/frame</th><th>smooth ms/frame</th></tr>\n";
    for (const Crossing& x : h.crossings)
      s << "<tr><td>" << f("%g", x.target_rmse) << "</td><td>" << reach_html(x.flat) << "</td><td>"
        << reach_html(x.smooth) << "</td><td>" << ratio_text(x.ratio) << "&times;</td><td>"
        << (x.flat.ms > 0 ? f("%.3g", x.flat.ms) : "") << "</td><td>" << (x.smooth.ms > 0 ? f("%.3g", x.smooth.ms) : "")
        << "</td></tr>\n";
    s << "</table>\n";
  }

  // Charts.
  s << "<h2 id=\"charts\">Error against run time</h2>\n"
    << "<img class=\"chart\" src=\"error_vs_time.svg\" alt=\"RMSE against milliseconds per frame\">\n"
    << "<img class=\"chart\" src=\"error_vs_triangles.svg\" alt=\"RMSE against triangles\">\n";

  // Pictures.
  s << "<h2 id=\"pictures\">Pictures (" << xml_escape(kb) << ")</h2>\n<p>Error maps: largest channel difference from the ideal, "
    << "<span class=\"swatch\" style=\"background:#000\"></span>equal "
    << "<span class=\"swatch\" style=\"background:#0000ff\"></span>1 step "
    << "<span class=\"swatch\" style=\"background:#800080\"></span>2 "
    << "<span class=\"swatch\" style=\"background:#ff0000\"></span>4 "
    << "<span class=\"swatch\" style=\"background:#ff8000\"></span>8 "
    << "<span class=\"swatch\" style=\"background:#ffff00\"></span>16 or more (the scale of every ffcompat heat map); "
       "silhouette: "
    << "<span class=\"swatch\" style=\"background:#ff00ff\"></span>only the picture covers "
    << "<span class=\"swatch\" style=\"background:#00ffff\"></span>only the ideal covers. Cropped to the sphere; click a "
       "picture for its pixels.</p>\n";
  auto img = [&](const std::string& path, const std::string& caption) {
    return "<td><a href=\"" + path + "\"><img src=\"" + path + "\" alt=\"" + xml_escape(caption) + "\"></a><div class=\"cap\">" +
           caption + "</div></td>";
  };
  for (const std::string& sc : scenes) {
    s << "<h3>lighting: " << xml_escape(sc) << "</h3>\n<table class=\"pics\"><tr><th>depth</th><th>ideal</th><th>GL_FLAT</th>"
      << "<th>flat &minus; ideal</th><th>GL_SMOOTH, averaged normals</th><th>smooth &minus; ideal</th></tr>\n";
    for (int d : w.keep_depths) {
      const Row* fl = find(rows, sc, d, "flat", kb);
      const Row* sm = find(rows, sc, d, "smooth-average", kb);
      if (!fl || !sm) continue;
      s << "<tr><th>" << d << "<br><span style=\"font-weight:normal\">" << short_count(double(fl->triangles))
        << " triangles</span></th>" << img(ideal_path(sc), "ray-cast sphere")
        << img(picture_path(sc, d, "flat", false), "rmse " + f("%.2f", fl->rmse) + ", max " + std::to_string(fl->max_error))
        << img(picture_path(sc, d, "flat", true), "silhouette " + std::to_string(fl->silhouette_pixels) + " px")
        << img(picture_path(sc, d, "smooth-average", false),
               "rmse " + f("%.2f", sm->rmse) + ", max " + std::to_string(sm->max_error))
        << img(picture_path(sc, d, "smooth-average", true), "silhouette " + std::to_string(sm->silhouette_pixels) + " px")
        << "</tr>\n";
    }
    s << "</table>\n";
  }

  // Tables.
  s << "<h2 id=\"tables\">Tables</h2>\n";
  for (const std::string& sc : scenes) {
    s << "<h3>RMSE (max) in 8-bit steps by depth and shading: " << xml_escape(sc) << ", " << xml_escape(kb)
      << "</h3>\n<table><tr><th>depth</th><th>triangles</th>";
    for (const auto& sh : shadings) s << "<th>" << xml_escape(sh) << "</th>";
    s << "<th>silhouette px (share)</th></tr>\n";
    for (int d : depths) {
      const Row* any = find(rows, sc, d, shadings.front(), kb);
      if (!any) continue;
      s << "<tr><td>" << d << "</td><td>" << any->triangles << "</td>";
      for (const auto& sh : shadings) {
        const Row* x = find(rows, sc, d, sh, kb);
        s << "<td>" << (x ? f("%.3f", x->rmse) + " (" + std::to_string(x->max_error) + ")" : "") << "</td>";
      }
      s << "<td>" << any->silhouette_pixels << " (" << f("%.2f", 100 * any->silhouette_share) << "%)</td></tr>\n";
    }
    s << "</table>\n";
  }
  s << "<h3>Milliseconds per frame (median), lighting " << xml_escape(scenes.empty() ? "" : scenes.front())
    << "</h3>\n<table><tr><th>depth</th><th>triangles</th>";
  for (const auto& b : backends) s << "<th>" << xml_escape(b) << " flat</th><th>" << xml_escape(b) << " smooth-average</th>";
  s << "</tr>\n";
  for (int d : depths) {
    const Row* any = scenes.empty() ? nullptr : find(rows, scenes.front(), d, shadings.front(), backends.front());
    if (!any) continue;
    s << "<tr><td>" << d << "</td><td>" << any->triangles << "</td>";
    for (const auto& b : backends)
      for (const char* sh : {"flat", "smooth-average"}) {
        const Row* x = find(rows, scenes.front(), d, sh, b);
        s << "<td>" << (x ? f("%.2f", x->ms_per_frame) : "") << "</td>";
      }
    s << "</tr>\n";
  }
  s << "</table>\n";
  // Flat, Gouraud and Phong side by side: GL_FLAT and GL_SMOOTH (averaged normals) on Mesa, and the
  // same equation per fragment from interpolated normals (glsl-phong), error against time.
  if (std::find(backends.begin(), backends.end(), "glsl-phong") != backends.end()) {
    s << "<h2 id=\"three\">Flat, Gouraud and Phong shading</h2>\n<p>GL_FLAT (face normals) and GL_SMOOTH (Gouraud, "
         "averaged normals) on Mesa, and Phong shading: the same GL lighting equation evaluated per fragment from "
         "interpolated eye-space normals and positions (backend <b>glsl-phong</b>, averaged normals). RMSE in 8-bit "
         "steps against the ideal sphere, and the median milliseconds per frame.</p>\n";
    for (const auto& sc : scenes) {
      s << "<h3>Lighting " << xml_escape(sc) << "</h3>\n<table><tr><th>depth</th><th>triangles</th>"
        << "<th>flat rmse</th><th>flat ms</th><th>Gouraud rmse</th><th>Gouraud ms</th><th>Phong rmse</th><th>Phong ms</th></tr>\n";
      for (int d : depths) {
        const Row* fl = find(rows, sc, d, "flat", "mesa");
        const Row* go = find(rows, sc, d, "smooth-average", "mesa");
        const Row* ph = find(rows, sc, d, "smooth-average", "glsl-phong");
        if (!fl && !go && !ph) continue;
        const Row* any = fl ? fl : go ? go : ph;
        s << "<tr><td>" << d << "</td><td>" << any->triangles << "</td>";
        for (const Row* x : {fl, go, ph})
          s << "<td>" << (x ? f("%.3f", x->rmse) : "") << "</td><td>" << (x ? f("%.2f", x->ms_per_frame) : "") << "</td>";
        s << "</tr>\n";
      }
      s << "</table>\n";
    }
  }
  s << "<h3>Milliseconds to compute the normals (median), by weighting</h3>\n<table><tr><th>depth</th><th>vertices</th>";
  for (const auto& sh : shadings) s << "<th>" << xml_escape(sh == "flat" ? "face (flat)" : sh.substr(sh.find('-') + 1)) << "</th>";
  s << "</tr>\n";
  for (int d : depths) {
    const Row* any = scenes.empty() ? nullptr : find(rows, scenes.front(), d, shadings.front(), backends.front());
    if (!any) continue;
    s << "<tr><td>" << d << "</td><td>" << any->vertices << "</td>";
    for (const auto& sh : shadings) {
      const Row* x = find(rows, scenes.front(), d, sh, backends.front());
      s << "<td>" << (x ? f("%.3f", x->normals_ms) : "") << "</td>";
    }
    s << "</tr>\n";
  }
  s << "</table>\n";
  s << "<details><summary>All " << rows.size() << " rows (as in results.csv)</summary>\n<table><tr>";
  for (const char* c : {"depth", "triangles", "shading", "scene", "backend", "rmse", "max", "rmse_exact", "silhouette px",
                        "ms/frame", "frames", "normals ms"})
    s << "<th>" << c << "</th>";
  s << "</tr>\n";
  for (const Row& x : rows)
    s << "<tr><td>" << x.depth << "</td><td>" << x.triangles << "</td><td class=\"l\">" << xml_escape(x.shading)
      << "</td><td class=\"l\">" << xml_escape(x.scene) << "</td><td class=\"l\">" << xml_escape(x.backend) << "</td><td>"
      << f("%.3f", x.rmse) << "</td><td>" << x.max_error << "</td><td>" << f("%.3f", x.rmse_exact) << "</td><td>"
      << x.silhouette_pixels << "</td><td>" << f("%.2f", x.ms_per_frame) << "</td><td>" << x.frames << "</td><td>"
      << f("%.3f", x.normals_ms) << "</td></tr>\n";
  s << "</table></details>\n";

  // Regression.
  s << "<h2 id=\"regression\">Regression against Mesa</h2>\n";
  if (!r.options.regression) {
    s << "<p>Not run (--no-regression).</p>\n";
  } else {
    size_t pass = 0;
    for (const SceneCheck& c : r.checks) pass += c.pass();
    s << "<p>Every shipped scene (" << (r.scenes_dir.empty() ? "none found" : "<code>" + xml_escape(shown_path(r.scenes_dir)) + "/*.toml</code>")
      << ") and the built-in scenes: our float pipeline's lit vertex colours against Mesa's feedback "
         "(check::compare_vertices; passes at 1e-5, or with a known Mesa deviation recorded), and the soft picture "
         "against Mesa's (image::compare; passes at 1 step). <b>"
      << pass << " of " << r.checks.size() << " pass.</b> The heat maps use the scale of the pictures above (black equal, blue 1 step, red 4, yellow 16 or more) "
         "are full size: a few differing pixels do not show in a thumbnail.</p>\n";
    s << "<table><tr><th class=\"l\">scene</th><th class=\"l\">source</th><th>size</th><th>vertices</th>"
         "<th>vertex max |&Delta;| float</th><th>double</th><th>window pos px</th><th>pixel max diff</th>"
         "<th>differing</th><th class=\"l\">result</th><th>Mesa</th><th class=\"l\">soft &minus; Mesa</th></tr>\n";
    for (size_t i = 0; i < r.checks.size(); ++i) {
      const SceneCheck& c = r.checks[i];
      s << "<tr><td class=\"l\">" << xml_escape(c.name) << "</td><td class=\"l\">" << xml_escape(shown_path(c.source)) << "</td>";
      if (!c.error.empty()) {
        s << "<td colspan=\"7\" class=\"l fail\">" << xml_escape(c.error) << "</td><td class=\"l fail\">error</td><td></td><td></td></tr>\n";
        continue;
      }
      std::string dev;
      for (const auto& d : c.known_mesa_deviations) dev += "<br><small>known: " + xml_escape(d) + "</small>";
      s << "<td>" << c.width << "&times;" << c.height << "</td><td>" << c.vertices << "</td><td>" << f("%.2g", c.vertex_max_abs)
        << "</td><td>" << f("%.2g", c.vertex_max_abs_double) << "</td><td>" << f("%.2g", c.max_position) << "</td><td>"
        << c.pixel_max_diff << "</td><td>" << f("%.2f", 100 * c.pixel_differing_share) << "%</td><td class=\"l "
        << (c.pass() ? "pass\">pass" : "fail\">FAIL") << (c.vertex_pass ? "" : " (vertex)") << (c.pixel_pass ? "" : " (pixel)")
        << dev << "</td><td class=\"thumb\"><a href=\"" << regression_path(i, c.name, "mesa") << "\"><img src=\""
        << regression_path(i, c.name, "mesa") << "\" alt=\"Mesa\"></a></td><td class=\"l\"><a href=\""
        << regression_path(i, c.name, "diff") << "\">heat map</a></td></tr>\n";
    }
    s << "</table>\n";
  }
  s << "<p class=\"meta\">Files: <a href=\"results.csv\">results.csv</a>, <a href=\"error_vs_time.svg\">error_vs_time.svg</a>, "
       "<a href=\"error_vs_triangles.svg\">error_vs_triangles.svg</a>.</p>\n</body></html>\n";
  return s.str();
}

}  // namespace ffc::report
