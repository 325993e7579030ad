#!/bin/sh
# A classic program that uses what the GLSL backend does not draw yet (docs/glsl.md, "Not
# supported"), run with `ffcompat run --compare --backend glsl`. It passes when the pictures agree
# (the backend has gained the features), or when they differ and, for each feature named, the
# backend said so on stderr ("the GLSL backend does not draw fog", "glBitmap is not supported by
# the GLSL backend"); a crash, a hang, a failed start or a silent difference fails.
# usage: glsl_needs.sh FFCOMPAT "FEATURE|FEATURE..." RUN-ARGS...
ffcompat=$1 needs=$2
shift 2
log=$(mktemp) || exit 1
trap 'rm -f "$log"' EXIT
"$ffcompat" run "$@" >"$log" 2>&1
rc=$?
cat "$log"
if [ "$rc" -eq 0 ]; then
  echo "glsl_needs: the pictures agree: the GLSL backend draws ($needs) now"
  exit 0
fi
if [ "$rc" -ne 2 ]; then
  echo "glsl_needs: ffcompat run failed (status $rc), not a picture difference"
  exit 1
fi
old_ifs=$IFS
IFS='|'
for need in $needs; do
  if ! grep -Fq "GLSL backend does not draw $need" "$log" && ! grep -Fq "$need is not supported by the GLSL backend" "$log"; then
    echo "glsl_needs: the pictures differ and the GLSL backend did not say that it lacks $need"
    exit 1
  fi
done
IFS=$old_ifs
echo "glsl_needs: differs where the GLSL backend said it lacks: $needs"
