#!/bin/sh
# libGL.so.1 exports exactly the GLAPI functions of gl_exports.inc, glXGetProcAddress(ARB) and
# the ffcompat_* surface API, is named libGL.so.1, and needs neither OSMesa nor any other libGL.
# And libOpenGL.so.0 exports nothing and needs libGL.so.1.
#   exports.sh build/classic/libGL.so.1 src/classic/gl/gl_exports.inc build/classic/libOpenGL.so.0
lib=$1 inc=$2 opengl=$3
fail=0
tmp=$(mktemp -d) && trap 'rm -rf "$tmp"' EXIT
nm -D --defined-only "$lib" | awk '{print $NF}' | sort > "$tmp/defined"
grep -v '^gl' "$tmp/defined" | grep -v '^ffcompat_' > "$tmp/foreign"
if [ -s "$tmp/foreign" ]; then
  echo "FAILED: exported beyond gl* and ffcompat_*: $(head -5 "$tmp/foreign" | tr '\n' ' ')($(wc -l < "$tmp/foreign") in all)"
  fail=1
fi
# gl.h's functions, and GLX's two loaders (which answer with the same addresses).
{ sed -n 's/^FFC_CLASSIC_GL([^,]*, *\(gl[A-Za-z0-9_]*\),.*/\1/p' "$inc"; echo glXGetProcAddress; echo glXGetProcAddressARB; } |
  sort > "$tmp/listed"
grep '^gl' "$tmp/defined" > "$tmp/gl"
if ! cmp -s "$tmp/listed" "$tmp/gl"; then
  echo "FAILED: the gl* exports differ from gl_exports.inc:"; diff "$tmp/listed" "$tmp/gl" | head -10
  fail=1
fi
listed=$(wc -l < "$tmp/listed")
if [ "$listed" -lt 402 ]; then echo "FAILED: only $listed names in $inc"; fail=1; fi
for f in ffcompat_surface_create ffcompat_surface_make_current ffcompat_surface_read_rgba \
         ffcompat_surface_destroy ffcompat_get_proc_address; do
  grep -qx "$f" "$tmp/defined" || { echo "FAILED: $f is not exported"; fail=1; }
done
soname=$(readelf -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ "$soname" = libGL.so.1 ] || { echo "FAILED: SONAME '$soname'"; fail=1; }
needed=$(readelf -d "$lib" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
case "$needed" in
  *OSMesa*|*libGL*|*glapi*) echo "FAILED: libGL.so.1 needs $needed"; fail=1 ;;
esac
if [ -n "$opengl" ]; then
  extra=$(nm -D --defined-only "$opengl" | awk '{print $NF}' | tr '\n' ' ')
  [ -z "$extra" ] || { echo "FAILED: libOpenGL.so.0 exports $extra"; fail=1; }
  readelf -d "$opengl" | grep -q 'NEEDED.*\[libGL\.so\.1\]' || { echo "FAILED: libOpenGL.so.0 does not need libGL.so.1"; fail=1; }
  [ "$(readelf -d "$opengl" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')" = libOpenGL.so.0 ] ||
    { echo "FAILED: libOpenGL.so.0's SONAME"; fail=1; }
fi
[ $fail = 0 ] && echo "libGL.so.1: $listed gl* exports and the surface API, nothing else; needs $needed"
exit $fail
