#!/bin/sh
# `ffcompat calls`: every function of gl_exports.inc listed once, glBegin implemented by soft and
# glTexImage2D not, the summary's counts those of the list, --missing only the missing ones; and
# docs/classic.md's list is the current output of `ffcompat calls --markdown` (after soft gains
# an entry point, regenerate it: see the doc).
#   calls.sh build/ffcompat src/classic/gl/gl_exports.inc docs/classic.md
exe=$1 inc=$2 doc=$3
fail=0
tmp=$(mktemp -d) && trap 'rm -rf "$tmp"' EXIT
"$exe" calls > "$tmp/all" || { echo "FAILED: ffcompat calls exited $?"; exit 1; }
listed=$(grep -c '^FFC_CLASSIC_GL(' "$inc")
rows=$(grep -c '^gl' "$tmp/all")
yes=$(grep -c '^gl[A-Za-z0-9_]* *yes ' "$tmp/all")
[ "$rows" = "$listed" ] || { echo "FAILED: $rows rows for $listed functions"; fail=1; }
grep -q '^glBegin  *yes ' "$tmp/all" || { echo "FAILED: glBegin is not listed as implemented"; fail=1; }
grep -q '^glTexImage2D  *no ' "$tmp/all" || { echo "FAILED: glTexImage2D is not listed as missing"; fail=1; }
grep -q "^# soft implements $yes of the $listed functions" "$tmp/all" ||
  { echo "FAILED: the summary does not say $yes of $listed: $(tail -1 "$tmp/all")"; fail=1; }
"$exe" calls --missing > "$tmp/missing"
[ "$(grep -c '^gl' "$tmp/missing")" = "$((listed - yes))" ] || { echo "FAILED: --missing lists the wrong number"; fail=1; }
grep -q '^gl[A-Za-z0-9_]* *yes ' "$tmp/missing" && { echo "FAILED: --missing lists an implemented one"; fail=1; }
"$exe" calls --backend mesa > /dev/null 2>&1 && { echo "FAILED: --backend mesa accepted"; fail=1; }
"$exe" calls --markdown > "$tmp/md"
sed -n '/^<!-- calls:begin -->$/,/^<!-- calls:end -->$/p' "$doc" | sed '1d;$d' > "$tmp/doc"
if ! cmp -s "$tmp/md" "$tmp/doc"; then
  echo "FAILED: docs/classic.md's list is not the output of 'ffcompat calls --markdown' (regenerate it)"
  fail=1
fi
[ $fail = 0 ] && echo "ffcompat calls: $yes of $listed implemented by soft; docs/classic.md current"
exit $fail
