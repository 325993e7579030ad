#!/bin/sh
# Each program's first frame on the system's freeglut, GLU and libGL (GLX on Xvfb, Mesa's
# llvmpipe) against its first frame on ffcompat's libglut, libGLU and libGL on the mesa backend:
# our GLUT (window, reshape, shapes, teapot) and GLU must give the same picture, within 1 step.
# Runs inside xvfb-run. Arguments: FFCOMPAT GRAB_WINDOW OUT_DIR then PROGRAM TITLE pairs.
set -u
ffcompat=$1 grab=$2 out=$3
shift 3
mkdir -p "$out"
status=0
while [ $# -ge 2 ]; do
  prog=$1 title=$2 name=$(basename "$1")
  shift 2
  # -geometry puts the window on the screen, whole (freeglut and ours both take it out of argv).
  env -u LD_LIBRARY_PATH LIBGL_ALWAYS_SOFTWARE=1 "$prog" -geometry +40+40 >/dev/null 2>&1 &
  pid=$!
  "$grab" "$out/$name-freeglut.png" "$title"
  grabbed=$?
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  if [ $grabbed -ne 0 ]; then
    echo "$name: no picture from the system's freeglut"
    status=1
    continue
  fi
  if ! "$ffcompat" run --backend mesa --frames 1 --out "$out/$name" -- "$prog" -geometry +40+40 >/dev/null; then
    echo "$name: ffcompat run failed"
    status=1
    continue
  fi
  diff=$("$ffcompat" compare "$out/$name-freeglut.png" "$out/$name/frame-000.png" --diff "$out/$name-diff.png" | sed -n 's/^max_diff *\([0-9]*\) steps/\1/p')
  echo "$name: freeglut and GLX against ffcompat on mesa: $diff steps apart at most"
  if [ -z "$diff" ] || [ "$diff" -gt 1 ]; then status=1; fi
done
exit $status
