#!/bin/sh
# A program built against ffcompat's libraries directly with build/classic/pkgconfig's
# ffcompat-classic.pc runs on them with no LD_LIBRARY_PATH (the run path is in the program).
#   pkgconfig.sh build/classic/pkgconfig tests/classic_gl CC WORKDIR
pcdir=$1 src=$2 cc=$3 work=$4
export PKG_CONFIG_PATH="$pcdir"
mkdir -p "$work" || exit 1
libs=$(pkg-config --libs ffcompat-classic) || { echo "FAILED: pkg-config does not know ffcompat-classic"; exit 1; }
case "$libs" in
  *-Wl,-rpath,*-lglut*-lGLU*-lGL*) ;;
  *) echo "FAILED: pkg-config --libs gave: $libs"; exit 1 ;;
esac
# Only libGL is linked: libGLU and libglut may not be built in this tree.
"$cc" "$src/unsupported.c" -I"$src" $(pkg-config --cflags --libs-only-L --libs-only-other ffcompat-classic) -lGL \
  -o "$work/unsupported_pc" || { echo "FAILED: cannot build with the pkg-config flags"; exit 1; }
env -u LD_LIBRARY_PATH "$work/unsupported_pc"
