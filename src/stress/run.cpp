// Running a stress case on the three backends, each guarded (a forked child per backend run, so a
// crash in Mesa or in ours cannot take the suite down), and judging what came back.
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "backends/backend.h"
#include "backends/soft/soft_backend.h"
#include "gl/dispatch.h"
#include "stress/stress.h"

namespace ffc::stress {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// What one backend run produces before the feedback is parsed.
struct RawRun {
  std::string error;  // non-empty: the run threw
  image::Image image;
  std::vector<float> feedback;
  uint64_t fragments = 0;
  uint32_t gl_error = 0;
};

// Draws the case once for the picture and once in feedback mode (GL_3D_COLOR), with a buffer that
// grows until everything fits.
RawRun draw_on(const Case& c, const std::string& backend_name) {
  RawRun r;
  try {
    auto backend = backends::make(backend_name);
    backend->begin(c.width, c.height);
    c.draw();
    r.gl_error = glGetError();
    r.image = backend->read();
    // Ours only, from the context begin() made for this picture: its count alone, whatever other
    // contexts of the process draw meanwhile.
    if (dynamic_cast<backends::SoftBackend*>(backend.get()) && state::Context::current())
      r.fragments = state::Context::current()->counters().nonfinite_fragments.load();
    for (size_t size = std::max<size_t>(c.feedback_hint + 64, size_t(1) << 16);; size *= 4) {
      if (size > (size_t(1) << 30)) throw std::runtime_error("feedback: more than 2^30 values");
      r.feedback.assign(size, 0.0f);
      backend->begin(c.width, c.height);
      glFeedbackBuffer(GLsizei(size), GL_3D_COLOR, r.feedback.data());
      glRenderMode(GL_FEEDBACK);
      c.draw();
      const GLint n = glRenderMode(GL_RENDER);
      if (n >= 0) {
        r.feedback.resize(size_t(n));
        break;
      }
    }
  } catch (const std::exception& e) {
    r.error = std::string(e.what()).empty() ? "exception" : e.what();
  } catch (...) {
    r.error = "unknown exception";
  }
  return r;
}

// --- the child's report, through a pipe

void put_bytes(std::string& out, const void* p, size_t n) { out.append(static_cast<const char*>(p), n); }
template <typename T>
void put(std::string& out, T v) {
  put_bytes(out, &v, sizeof v);
}

std::string encode(const RawRun& r) {
  std::string out;
  put<uint64_t>(out, r.error.size());
  out += r.error;
  put<int32_t>(out, r.image.width);
  put<int32_t>(out, r.image.height);
  put<uint64_t>(out, r.image.rgba.size());
  put_bytes(out, r.image.rgba.data(), r.image.rgba.size());
  put<uint64_t>(out, r.fragments);
  put<uint32_t>(out, r.gl_error);
  put<uint64_t>(out, r.feedback.size());
  put_bytes(out, r.feedback.data(), r.feedback.size() * sizeof(float));
  return out;
}

struct Reader {
  const std::string& s;
  size_t at = 0;
  void bytes(void* p, size_t n) {
    if (n > s.size() - at) throw std::runtime_error("truncated report from the child");
    if (n == 0) return;  // p may be an empty vector's null data(): memcpy's arguments must not be null
    std::memcpy(p, s.data() + at, n);
    at += n;
  }
  template <typename T>
  T get() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
};

RawRun decode(const std::string& s) {
  Reader in{s};
  RawRun r;
  r.error.resize(in.get<uint64_t>());
  in.bytes(r.error.data(), r.error.size());
  r.image.width = in.get<int32_t>();
  r.image.height = in.get<int32_t>();
  r.image.rgba.resize(in.get<uint64_t>());
  in.bytes(r.image.rgba.data(), r.image.rgba.size());
  r.fragments = in.get<uint64_t>();
  r.gl_error = in.get<uint32_t>();
  r.feedback.resize(in.get<uint64_t>());
  in.bytes(r.feedback.data(), r.feedback.size() * sizeof(float));
  return r;
}

void write_all(int fd, const std::string& s) {
  size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += size_t(n);
  }
}

Run finish(RawRun&& raw, double seconds) {
  Run run;
  run.ran = true;
  run.seconds = seconds;
  if (!raw.error.empty()) {
    run.crashed = true;
    run.error = "threw: " + raw.error;
    return run;
  }
  run.image = std::move(raw.image);
  run.nonfinite_fragments = raw.fragments;
  run.gl_error = raw.gl_error;
  try {
    run.feedback = split_polygons(check::parse(raw.feedback.data(), int(raw.feedback.size())));
  } catch (const std::exception& e) {
    run.crashed = true;
    run.error = std::string("malformed feedback: ") + e.what();
  }
  return run;
}

Run run_isolated(const Case& c, const std::string& backend, double timeout) {
  const auto t0 = Clock::now();
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("stress: pipe failed");
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]), close(fds[1]);
    throw std::runtime_error("stress: fork failed");
  }
  if (pid == 0) {  // the child: draw, report, leave without running the parent's exit handlers
    close(fds[0]);
    write_all(fds[1], encode(draw_on(c, backend)));
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string report;
  std::vector<char> chunk(1 << 20);
  bool timed_out = false;
  for (;;) {
    const double left = timeout - since(t0);
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, int(std::min(left, 1.0) * 1000) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = read(fds[0], chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    report.append(chunk.data(), size_t(n));
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const double seconds = since(t0);
  Run run;
  run.ran = true;
  run.seconds = seconds;
  if (timed_out) {
    run.crashed = true;
    run.error = "ran out of time (" + std::to_string(int(timeout)) + " s)";
    return run;
  }
  if (WIFSIGNALED(status)) {
    run.crashed = true;
    run.error = std::string("died on signal ") + std::to_string(WTERMSIG(status)) + " (" +
                strsignal(WTERMSIG(status)) + ")";
    return run;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    run.crashed = true;
    run.error = "exited with status " + std::to_string(WEXITSTATUS(status));
    return run;
  }
  try {
    return finish(decode(report), seconds);
  } catch (const std::exception& e) {
    run.crashed = true;
    run.error = e.what();
    return run;
  }
}

Run run_backend(const Case& c, const std::string& backend, const Options& o) {
  if (o.isolate) return run_isolated(c, backend, o.timeout);
  const auto t0 = Clock::now();
  RawRun raw = draw_on(c, backend);
  return finish(std::move(raw), since(t0));
}

bool finite(const check::FeedbackVertex& v) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(v.position[k])) return false;
  for (int k = 0; k < 4; ++k)
    if (!std::isfinite(v.color[k])) return false;
  return true;
}

// |a - b|, where two equal non-finite values (both NaN, or the same infinity) count as equal.
double difference(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return 0;
  if (a == b) return 0;
  const double d = std::abs(a - b);
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

std::string same_shape(const std::vector<check::FeedbackPrimitive>& a, const std::vector<check::FeedbackPrimitive>& b,
                       const char* an, const char* bn) {
  if (a.size() != b.size())
    return std::string(an) + " reports " + std::to_string(a.size()) + " primitives, " + bn + " " +
           std::to_string(b.size());
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].token != b[i].token || a[i].vertices.size() != b[i].vertices.size())
      return "primitive " + std::to_string(i) + " differs in kind or size between " + an + " and " + bn;
  return "";
}

struct VertexDiff {
  double colour = 0, position = 0;
};

// Which rotation of b's vertices lines up best with a's (by window position): a triangle may start
// at another vertex after clipping.
size_t best_rotation(const check::FeedbackPrimitive& a, const check::FeedbackPrimitive& b) {
  const size_t n = a.vertices.size();
  if (a.token != GL_POLYGON_TOKEN || n < 3) return 0;
  size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (size_t r = 0; r < n; ++r) {
    double d = 0;
    for (size_t v = 0; v < n; ++v) {
      const glm::dvec3 e = a.vertices[v].position - b.vertices[(v + r) % n].position;
      d += glm::dot(e, e);
    }
    if (d < best_d) best_d = d, best = r;
  }
  return best;
}

VertexDiff compare_feedback(const std::vector<check::FeedbackPrimitive>& a,
                            const std::vector<check::FeedbackPrimitive>& b) {
  VertexDiff d;
  for (size_t p = 0; p < a.size(); ++p) {
    const size_t rot = best_rotation(a[p], b[p]), n = a[p].vertices.size();
    for (size_t v = 0; v < n; ++v) {
      const auto &x = a[p].vertices[v], &y = b[p].vertices[(v + rot) % n];
      for (int k = 0; k < 4; ++k) d.colour = std::max(d.colour, difference(x.color[k], y.color[k]));
      const double dx = x.position.x - y.position.x, dy = x.position.y - y.position.y;
      const double dp = std::sqrt(dx * dx + dy * dy);
      if (std::isfinite(dp)) d.position = std::max(d.position, dp);
    }
  }
  return d;
}

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

}  // namespace

std::vector<check::FeedbackPrimitive> split_polygons(const std::vector<check::FeedbackPrimitive>& f) {
  std::vector<check::FeedbackPrimitive> out;
  out.reserve(f.size());
  for (const auto& p : f) {
    if (p.token != GL_POLYGON_TOKEN || p.vertices.size() <= 3) {
      out.push_back(p);
      continue;
    }
    const auto& v = p.vertices;
    for (size_t i = 1; i + 1 < v.size(); ++i) out.push_back({p.token, {v[i], v[i + 1], v[0]}});
  }
  return out;
}

uint64_t nonfinite_vertices(const std::vector<check::FeedbackPrimitive>& f) {
  uint64_t n = 0;
  for (const auto& p : f)
    for (const auto& v : p.vertices) n += !finite(v);
  return n;
}

Result run(const Case& c, const Options& o, bool keep) {
  const auto t0 = Clock::now();
  Result r;
  r.name = c.name, r.group = c.group, r.note = c.note;
  Observed ob;
  if (o.mesa && !c.skip_mesa) ob.mesa = run_backend(c, "mesa", o);
  ob.soft = run_backend(c, "soft", o);
  ob.dbl = run_backend(c, "soft-double", o);

  // Ours.
  r.crashed = ob.soft.crashed || ob.dbl.crashed;
  r.nan_pixels = ob.soft.nonfinite_fragments + ob.dbl.nonfinite_fragments;
  r.nan_vertices = nonfinite_vertices(ob.soft.feedback) + nonfinite_vertices(ob.dbl.feedback);
  r.primitives[1] = ob.soft.feedback.size(), r.primitives[2] = ob.dbl.feedback.size();
  r.gl_errors[1] = ob.soft.gl_error, r.gl_errors[2] = ob.dbl.gl_error;
  std::string float_shape;
  if (!r.crashed) {
    float_shape = same_shape(ob.dbl.feedback, ob.soft.feedback, "double", "float");
    if (float_shape.empty()) {
      const VertexDiff d = compare_feedback(ob.dbl.feedback, ob.soft.feedback);
      r.max_abs_vs_double = d.colour, r.max_position_vs_double_px = d.position;
    } else {
      r.max_abs_vs_double = 1.0;
    }
  }

  // Mesa.
  r.mesa_ran = ob.mesa.ran;
  r.mesa_crashed = ob.mesa.crashed;
  r.primitives[0] = ob.mesa.feedback.size();
  r.gl_errors[0] = ob.mesa.gl_error;
  r.mesa_nan_vertices = nonfinite_vertices(ob.mesa.feedback);
  if (ob.mesa.ran && !ob.mesa.crashed && !ob.soft.crashed) {
    std::vector<std::string> why;
    const std::string shape = same_shape(ob.mesa.feedback, ob.soft.feedback, "Mesa", "ours");
    if (!shape.empty()) {
      why.push_back(shape);
    } else {
      const VertexDiff d = compare_feedback(ob.mesa.feedback, ob.soft.feedback);
      r.max_colour_vs_mesa = d.colour, r.max_position_px = d.position;
      if (d.colour > 1e-4) why.push_back("vertex colours differ by up to " + fmt(d.colour));
    }
    const image::Image &a = ob.mesa.image, &b = ob.soft.image;
    if (a.width == b.width && a.height == b.height) {
      for (size_t i = 0; i < a.rgba.size(); i += 4) {
        int m = 0;
        for (int k = 0; k < 4; ++k) m = std::max(m, std::abs(int(a.rgba[i + k]) - int(b.rgba[i + k])));
        r.max_pixel_steps = std::max(r.max_pixel_steps, m);
        r.differing_pixels += m > 1;
      }
      if (r.max_pixel_steps > 1)
        why.push_back("pixels differ by up to " + std::to_string(r.max_pixel_steps) + " steps (" +
                      std::to_string(r.differing_pixels) + " more than one step apart)");
    } else {
      why.push_back("the pictures differ in size");
    }
    r.mesa_agrees = why.empty();
    for (size_t i = 0; i < why.size(); ++i) r.mesa_difference += (i ? "; " : "") + why[i];
  } else if (ob.mesa.crashed) {
    r.mesa_difference = "Mesa " + ob.mesa.error;
  }

  // The case's own hand-derived check, on what was observed.
  if (!r.crashed && c.check) r.check_failure = c.check(ob);

  // The verdict: ours first, then Mesa.
  auto crash_text = [&] {
    return ob.soft.crashed ? "soft " + ob.soft.error : "soft-double " + ob.dbl.error;
  };
  if (r.crashed) {
    r.verdict = "FAIL: " + crash_text();
  } else if (r.nan_pixels > 0) {
    r.verdict = "FAIL: " + std::to_string(r.nan_pixels) + " fragments written from non-finite colours";
  } else if (r.nan_vertices > 0) {
    r.verdict = "FAIL: " + std::to_string(r.nan_vertices) + " non-finite vertices in our feedback";
  } else if (!r.check_failure.empty()) {
    r.verdict = "FAIL: " + r.check_failure;
  } else if (!float_shape.empty() && c.float_limit < 1) {
    r.verdict = "FAIL: float path and double reference differ: " + float_shape;
  } else if (r.max_abs_vs_double > c.float_limit) {
    r.verdict = "FAIL: float path off the double reference by " + fmt(r.max_abs_vs_double);
  } else {
    std::string v;
    if (!r.mesa_ran) {
      v = o.mesa ? "ok (Mesa not run: see the note)" : "ok (Mesa not run)";
    } else if (r.mesa_crashed) {
      v = "mesa-deviation: Mesa " + ob.mesa.error;
    } else if (r.mesa_agrees) {
      v = "ok";
    } else if (c.mesa == MesaExpectation::Undefined) {
      v = "ok: differs from Mesa where the spec leaves it undefined (" + c.mesa_reason + ")";
    } else if (c.mesa == MesaExpectation::Deviation) {
      v = "mesa-deviation: " + c.mesa_reason;
    } else {
      v = "FAIL: differs from Mesa: " + r.mesa_difference;
    }
    if (r.max_abs_vs_double > 1e-4 && v.rfind("FAIL", 0) != 0)
      v += "; float path off the double reference by " + fmt(r.max_abs_vs_double) +
           (c.float_reason.empty() ? "" : " (" + c.float_reason + ")");
    r.verdict = v;
  }
  r.seconds = since(t0);
  if (keep) r.observed = std::move(ob);
  return r;
}

const Case* find(const std::string& name) {
  for (const Case& c : catalogue())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace ffc::stress
