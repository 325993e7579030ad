#include "difftest/runner.h"

#ifdef FFCOMPAT_WITH_MESA
#include "backends/mesa/mesa_backend.h"
#endif
#include <poll.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "backends/backend.h"
#include "difftest/probes.h"
#include "gl/dispatch.h"
#include "state/context.h"
#include "state/soft_gl.h"

namespace ffc::difftest {

const char* side_name(Side s) { return s == Side::Mesa ? "mesa" : "soft"; }

namespace {

// Entry points outside the dispatch's list, loaded per side as programs load them.
void(APIENTRY* g_Lightiv)(GLenum, GLenum, const GLint*) = nullptr;
void(APIENTRY* g_LightModeliv)(GLenum, const GLint*) = nullptr;
void(APIENTRY* g_Materialiv)(GLenum, GLenum, const GLint*) = nullptr;

// A number as the C parameter type would receive it; out-of-range values saturate rather than
// being undefined behaviour, NaN becomes 0 (the stream's printed C makes the same conversion
// explicit only for values in range, which is all the generator makes for integers).
template <class T>
T to_param(double v) {
  if constexpr (std::is_floating_point_v<T>) {
    return T(v);
  } else {
    using L = std::numeric_limits<T>;
    if (std::isnan(v)) return T(0);
    if constexpr (std::is_unsigned_v<T>) {
      if (v < 0) return T(int64_t(std::max(v, -2147483648.0)));  // as C converts a negative int
    }
    if (v <= double(L::min())) return L::min();
    if (v >= double(L::max())) return L::max();
    return T(v);
  }
}

template <class T>
T convert(const Arg& a, void* mem) {
  if constexpr (std::is_pointer_v<T>) return static_cast<T>(mem);
  else return to_param<T>(a.num);
}

template <class R, class... A, size_t... I>
double invoke_with(R(APIENTRY* f)(A...), const Call& c, void* const* mem, std::index_sequence<I...>) {
  if constexpr (std::is_void_v<R>) {
    f(convert<A>(c.args[I], mem[I])...);
    return NAN;
  } else if constexpr (std::is_pointer_v<R>) {
    return f(convert<A>(c.args[I], mem[I])...) != nullptr;  // strings differ by design: only null counts
  } else {
    return double(f(convert<A>(c.args[I], mem[I])...));
  }
}
// A null pointer (an entry point the side does not provide) is called all the same: the crash is
// the finding, and it happens in the child.
template <class R, class... A>
double invoke(R(APIENTRY* f)(A...), const Call& c, void* const* mem) {
  return invoke_with(f, c, mem, std::index_sequence_for<A...>{});
}

using Invoker = double (*)(const Call&, void* const*);
const std::vector<Invoker>& invokers() {
  static const std::vector<Invoker> v = {
#define FFC_GL_FUNCTION(ret, name, params) [](const Call& c, void* const* m) { return invoke(ffc_gl##name, c, m); },
#include "gl/gl_functions.inc"
#undef FFC_GL_FUNCTION
      [](const Call& c, void* const* m) { return invoke(g_Lightiv, c, m); },
      [](const Call& c, void* const* m) { return invoke(g_LightModeliv, c, m); },
      [](const Call& c, void* const* m) { return invoke(g_Materialiv, c, m); },
  };
  return v;
}

// The memory a stream's pointers point at: arrays converted to their types, output buffers of
// 8 bytes an element filled with a pattern (a short write shows), each with slack behind it so
// that a GL reading a little past an array reads zeros on both sides rather than faulting.
struct Memory {
  std::vector<std::vector<std::vector<double>>> store;  // [call][arg]
  std::vector<std::vector<void*>> ptr;

  explicit Memory(const Stream& s) : store(s.size()), ptr(s.size()) {
    for (size_t i = 0; i < s.size(); ++i) {
      store[i].resize(s[i].args.size());
      ptr[i].assign(s[i].args.size(), nullptr);
      for (size_t k = 0; k < s[i].args.size(); ++k) {
        const Arg& a = s[i].args[k];
        auto& buf = store[i][k];
        if (a.kind == Arg::Kind::Blob) {
          buf.assign(a.blob.size() + 16, 0.0);
          char* p = reinterpret_cast<char*>(buf.data());
          for (size_t e = 0; e < a.blob.size(); ++e) put(p, e, a.type, a.blob[e]);
        } else if (a.kind == Arg::Kind::Out) {
          buf.assign(size_t(a.num) + 16, 0.0);
          std::memset(buf.data(), 0xA5, buf.size() * sizeof(double));
        } else {
          continue;
        }
        ptr[i][k] = buf.data();
      }
    }
  }
  static void put(char* p, size_t e, GLenum t, double v) {
    switch (t) {
      case GL_FLOAT: reinterpret_cast<float*>(p)[e] = float(v); break;
      case GL_DOUBLE: reinterpret_cast<double*>(p)[e] = v; break;
      case GL_INT: reinterpret_cast<int32_t*>(p)[e] = to_param<int32_t>(v); break;
      case GL_UNSIGNED_INT: reinterpret_cast<uint32_t*>(p)[e] = to_param<uint32_t>(v); break;
      case GL_SHORT: reinterpret_cast<int16_t*>(p)[e] = to_param<int16_t>(v); break;
      case GL_UNSIGNED_SHORT: reinterpret_cast<uint16_t*>(p)[e] = to_param<uint16_t>(v); break;
      case GL_BYTE: reinterpret_cast<int8_t*>(p)[e] = to_param<int8_t>(v); break;
      default: reinterpret_cast<uint8_t*>(p)[e] = to_param<uint8_t>(v); break;
    }
  }
};

// An output buffer as numbers: by the pointee type; glReadPixels' by its type argument.
std::vector<double> decode(const Call& c, size_t arg, const void* mem) {
  const Function& f = functions()[size_t(c.fn)];
  const size_t n = size_t(c.args[arg].num);
  std::vector<double> v(n);
  const std::string& t = f.ctypes[arg];
  GLenum type = t.rfind("GLfloat", 0) == 0 ? GL_FLOAT : t.rfind("GLdouble", 0) == 0 ? GL_DOUBLE : GL_INT;
  double scale = 1;
  if (f.name == "glReadPixels") {
    type = to_param<GLenum>(c.args[5].num);
    switch (type) {
      case GL_UNSIGNED_BYTE: scale = 255; break;
      case GL_BYTE: scale = 127; break;
      case GL_UNSIGNED_SHORT: scale = 65535; break;
      case GL_SHORT: scale = 32767; break;
      case GL_UNSIGNED_INT: scale = 4294967295.0; break;
      case GL_INT: scale = 2147483647.0; break;
      case GL_FLOAT: break;
      default: type = GL_UNSIGNED_BYTE, scale = 1; break;  // packed types: compare bytes exactly
    }
  }
  const char* p = static_cast<const char*>(mem);
  for (size_t e = 0; e < n; ++e) {
    double x = 0;
    switch (type) {
      case GL_FLOAT: { float f32; std::memcpy(&f32, p + 4 * e, 4); x = f32; break; }
      case GL_DOUBLE: std::memcpy(&x, p + 8 * e, 8); break;
      case GL_INT: { int32_t i; std::memcpy(&i, p + 4 * e, 4); x = i; break; }
      case GL_UNSIGNED_INT: { uint32_t i; std::memcpy(&i, p + 4 * e, 4); x = i; break; }
      case GL_SHORT: { int16_t i; std::memcpy(&i, p + 2 * e, 2); x = i; break; }
      case GL_UNSIGNED_SHORT: { uint16_t i; std::memcpy(&i, p + 2 * e, 2); x = i; break; }
      case GL_BYTE: x = double(int8_t(p[e])); break;
      default: x = double(uint8_t(p[e])); break;
    }
    v[e] = x / scale;
  }
  return v;
}

// ---------------------------------------------------------------- the child's report

struct Writer {
  std::vector<double> d;
  void num(double v) { d.push_back(v); }
  void vec(const std::vector<double>& v) { num(double(v.size())), d.insert(d.end(), v.begin(), v.end()); }
  void str(const std::string& s) { vec(std::vector<double>(s.begin(), s.end())); }
};
struct Reader {
  const std::vector<double>& d;
  size_t i = 0;
  double num() {
    if (i >= d.size()) throw std::runtime_error("truncated report");
    return d[i++];
  }
  std::vector<double> vec() {
    const size_t n = size_t(num());
    if (n > d.size() - i) throw std::runtime_error("truncated report");
    std::vector<double> v(d.begin() + long(i), d.begin() + long(i + n));
    i += n;
    return v;
  }
  std::string str() {
    const auto v = vec();
    return std::string(v.begin(), v.end());
  }
};

std::vector<double> encode(const SideResult& r) {
  Writer w;
  w.num(double(r.status)), w.num(r.call), w.str(r.what);
  w.vec(std::vector<double>(r.errors.begin(), r.errors.end()));
  w.vec(r.returns);
  w.num(double(r.checkpoints.size()));
  for (const auto& c : r.checkpoints) w.vec(c);
  w.num(double(r.outputs.size()));
  for (const auto& o : r.outputs) w.num(o.call), w.vec(o.values);
  w.num(r.width), w.num(r.height), w.vec(std::vector<double>(r.pixels.begin(), r.pixels.end()));
  w.num(double(r.deviations.size()));
  for (const auto& s : r.deviations) w.str(s);
  return w.d;
}

SideResult decode_report(const std::vector<double>& d) {
  Reader rd{d};
  SideResult r;
  r.status = SideResult::Status(int(rd.num()));
  r.call = int(rd.num());
  r.what = rd.str();
  for (double e : rd.vec()) r.errors.push_back(GLenum(e));
  r.returns = rd.vec();
  for (size_t n = size_t(rd.num()); n > 0; --n) r.checkpoints.push_back(rd.vec());
  for (size_t n = size_t(rd.num()); n > 0; --n) {
    Output o;
    o.call = int(rd.num());
    o.values = rd.vec();
    r.outputs.push_back(std::move(o));
  }
  r.width = int(rd.num()), r.height = int(rd.num());
  for (double p : rd.vec()) r.pixels.push_back(uint8_t(p));
  for (size_t n = size_t(rd.num()); n > 0; --n) r.deviations.push_back(rd.str());
  return r;
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

SideResult execute(const Stream& s, Side side, const RunOptions& o, volatile int* progress) {
  SideResult r;
  auto backend = backends::make(side_name(side));
  backend->begin(o.width, o.height);
  auto load = [side, &backend](const char* name) -> void* {
#ifdef FFCOMPAT_WITH_MESA
    return side == Side::Mesa ? backends::mesa_proc_address(static_cast<backends::MesaBackend&>(*backend).platform(), name)
                              : state::proc_address(name);
#else
    return side == Side::Mesa ? nullptr : state::proc_address(name);  // make("mesa") threw already
#endif
  };
  g_Lightiv = reinterpret_cast<decltype(g_Lightiv)>(load("glLightiv"));
  g_LightModeliv = reinterpret_cast<decltype(g_LightModeliv)>(load("glLightModeliv"));
  g_Materialiv = reinterpret_cast<decltype(g_Materialiv)>(load("glMaterialiv"));
  while (glGetError() != GL_NO_ERROR) {
  }
  Memory mem(s);
  for (size_t i = 0; i < s.size(); ++i) {
    *progress = int(i);
    if (int(i) == o.crash_at) std::raise(SIGSEGV);
    while (int(i) == o.hang_at) *progress = int(i);
    const Call& c = s[i];
    if (c.fn == checkpoint_fn()) {
      r.checkpoints.push_back(read_back());
      r.errors.push_back(GLenum(r.checkpoints.back().back()));
      r.returns.push_back(NAN);
      continue;
    }
    r.returns.push_back(invokers()[size_t(c.fn)](c, mem.ptr[i].data()));
    r.errors.push_back(glGetError());
  }
  *progress = int(s.size());
  // Past any open glBegin (a shrunk stream may have lost its glEnd: glFinish inside would be an
  // error that flushes nothing on Mesa, its vbo still holding earlier primitives), so the picture
  // can be read; then every output buffer as it stands. The errors here are not compared.
  glEnd();
  glFinish();
  while (glGetError() != GL_NO_ERROR) {
  }
  image::Image img;
  backend->read_into(img);
  r.width = img.width, r.height = img.height;
  r.pixels = std::move(img.rgba);
  for (size_t i = 0; i < s.size(); ++i)
    for (size_t k = 0; k < s[i].args.size(); ++k)
      if (s[i].args[k].kind == Arg::Kind::Out) r.outputs.push_back({int(i), decode(s[i], k, mem.ptr[i][k])});
  if (side == Side::Soft && state::Context::current())
    for (const auto& d : state::Context::current()->deviations()) r.deviations.push_back(d);
  // Mesa's teardown after unflushed immediate-mode drawing can crash in OSMesaDestroyContext; the
  // glFinish above has flushed it.
  backend.reset();
  return r;
}

SideResult run_side(const Stream& s, Side side, const RunOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!o.isolate) {
    int progress = 0;
    SideResult r = execute(s, side, o, &progress);
    r.seconds = since(t0);
    return r;
  }
  auto* progress = static_cast<volatile int*>(
      mmap(nullptr, sizeof(int), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  if (progress == MAP_FAILED) throw std::runtime_error("difftest: mmap failed");
  *progress = -1;
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("difftest: pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("difftest: fork failed");
  if (pid == 0) {  // the child: run, report, leave without the parent's exit handlers
    close(fds[0]);
    SideResult r;
    try {
      r = execute(s, side, o, progress);
    } catch (const std::exception& e) {
      r = {};
      r.status = SideResult::Status::Crashed;
      r.call = *progress;
      r.what = std::string("threw: ") + e.what();
    }
    const std::vector<double> d = encode(r);
    const uint64_t n = d.size();
    const char* p = reinterpret_cast<const char*>(&n);
    std::string bytes(p, p + 8);
    bytes.append(reinterpret_cast<const char*>(d.data()), d.size() * sizeof(double));
    for (size_t done = 0; done < bytes.size();) {
      const ssize_t w = write(fds[1], bytes.data() + done, bytes.size() - done);
      if (w <= 0) break;
      done += size_t(w);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string report;
  char chunk[1 << 16];
  bool timed_out = false;
  for (;;) {
    const double left = o.timeout - since(t0);
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, int(std::min(left, 1.0) * 1000) + 1);
    if (ready <= 0) continue;
    const ssize_t n = read(fds[0], chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    report.append(chunk, size_t(n));
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const int at = *progress;
  munmap(const_cast<int*>(progress), sizeof(int));
  SideResult r;
  r.call = at;
  if (timed_out) {
    r.status = SideResult::Status::Hung;
    r.what = "ran past " + std::to_string(o.timeout) + " s";
  } else if (WIFSIGNALED(status)) {
    r.status = SideResult::Status::Crashed;
    r.what = std::string("signal ") + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  } else {
    try {
      uint64_t n = 0;
      if (report.size() < 8) throw std::runtime_error("no report (exit status " + std::to_string(WEXITSTATUS(status)) + ")");
      std::memcpy(&n, report.data(), 8);
      if (report.size() != 8 + n * sizeof(double)) throw std::runtime_error("truncated report");
      std::vector<double> d(n);
      std::memcpy(d.data(), report.data() + 8, n * sizeof(double));
      r = decode_report(d);
    } catch (const std::exception& e) {
      r.status = SideResult::Status::Crashed;
      r.what = e.what();
    }
  }
  r.seconds = since(t0);
  return r;
}

}  // namespace ffc::difftest
