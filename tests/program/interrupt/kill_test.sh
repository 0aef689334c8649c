#!/usr/bin/env bash
# No lost results: runs square_many_instants.lua, stops it after a few instants
# with SIGNAL (INT: Ctrl-C, KILL: no chance to react), then reads back what is on
# disk. RESU.pvd must list consecutive instants from 0, each named .vtu must be
# whole, and its DEPL must be the exact solution at that instant:
# max |DY| = 0.01 INST (the top edge) and max |DX| = 0.01 INST NU/(1-NU).
# usage: kill_test.sh EXE STUDY MESH OUTDIR INT|KILL
set -u
exe=$1 study=$2 mesh=$3 out=$4 signal=$5
fail() { echo "FAIL: $*"; [ -f "$out.log" ] && cat "$out.log"; exit 1; }

rm -rf "$out" "$out.log"
mkdir -p "$out"
set -m  # job control: the background run gets its own process group, SIGINT not ignored
"$exe" --output-dir "$out" -u 20="$mesh" "$study" > "$out.log" 2>&1 &
pid=$!
pvd="$out/RESU.pvd"
listed() { grep -c '<DataSet' "$pvd" 2>/dev/null || echo 0; }
for _ in $(seq 1800); do  # 180 s at most
  [ "$(listed)" -ge 4 ] && break
  kill -0 "$pid" 2>/dev/null || fail "the run ended before it could be stopped"
  sleep 0.1
done
[ "$(listed)" -ge 4 ] || { kill -KILL "$pid"; fail "fewer than 4 instants on disk after 180 s"; }
kill "-$signal" "$pid"
wait "$pid"
status=$?

if [ "$signal" = INT ]; then
  [ "$status" -eq 130 ] || fail "exit status $status after SIGINT, expected 130"
  grep -q "interrupted (SIGINT) during the instant" "$out.log" || fail "no message about the interruption"
  grep -q "instant(s) were stored before it" "$out.log" || fail "the message does not say what was stored"
  ! ls -a "$out" | grep -q partial || fail "temporary files left behind after SIGINT"
else
  [ "$status" -eq 137 ] || fail "exit status $status after SIGKILL, expected 137"
fi

grep -q '</VTKFile>' "$pvd" || fail "$pvd is not whole"
expected=0
while read -r inst file; do
  [ "$file" = "RESU_$expected.vtu" ] || fail "instant $expected is listed as $file"
  vtu="$out/$file"
  [ -f "$vtu" ] || fail "$file is listed but absent"
  [ "$(tail -n 1 "$vtu")" = "</VTKFile>" ] || fail "$file is not whole"
  awk -v t="$inst" -v f="$file" '
    /<DataArray/ && /Name="DEPL"/ { inside = 1; next }
    inside && /<\/DataArray>/ { inside = 0 }
    inside { n++; x = ($1 < 0 ? -$1 : $1); y = ($2 < 0 ? -$2 : $2);
             if (x > mx) mx = x; if (y > my) my = y }
    END {
      ey = 0.01 * t; ex = 0.01 * t * 0.3 / 0.7
      if (n == 0) { print "FAIL: " f " has no DEPL"; exit 1 }
      d1 = my - ey; d2 = mx - ex
      if (d1 < 0) d1 = -d1; if (d2 < 0) d2 = -d2
      if (d1 > 1e-12 || d2 > 1e-12) {
        printf "FAIL: %s at INST %s: max|DY| %.15g (exact %.15g), max|DX| %.15g (exact %.15g)\n", f, t, my, ey, mx, ex
        exit 1
      }
    }' "$vtu" || fail "wrong values in $file"
  expected=$((expected + 1))
done < <(sed -n 's/.*timestep="\([^"]*\)".*file="\([^"]*\)".*/\1 \2/p' "$pvd")
[ "$expected" -ge 4 ] || fail "only $expected instants listed in $pvd"
echo "SIG$signal: $expected instants on disk, each whole and exact"
