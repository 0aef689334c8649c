#!/usr/bin/env bash
# The Lua sandbox and Ctrl-C, on the real program (cases that need a file name
# chosen at run time, a check that no file appeared, or a real SIGINT).
# usage: sandbox_test.sh EXE WORKDIR CASE
#   gmsh_written_geo   a study writes a .geo with SystemCall and reads it as GMSH
#   gnuplot_quotes     backquotes in IMPR_FONCTION's texts and in the study's name
#   ctrl_c_<loop>      one SIGINT stops a study stuck in Lua code within a second
set -u
exe=$(realpath "$1") work=$2 case=$3
fail() { echo "FAIL ($case): $*"; [ -f "$work/log" ] && cat "$work/log"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
work=$(pwd)
pwned() { find "$work" -name 'pwned*' | grep -q . && fail "a shell command ran: $(find "$work" -name 'pwned*')"; }

case $case in
gmsh_written_geo)
  mkdir out
  cat > study.lua <<LUA
local f = assert(io.open('$work/out/evil.geo', 'w'))
f:write('SystemCall "touch $work/pwned";\nPoint(1) = {0, 0, 0, 1};\n')
f:close()
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = '$work/out/evil.geo'}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
LUA
  "$exe" --output-dir out study.lua > log 2>&1
  status=$?
  pwned
  [ "$status" -eq 2 ] || fail "exit status $status, expected 2"
  [ -f out/evil.geo ] || fail "the study could not write in its output folder"
  grep -q "^<F> <LIRE_MAILLAGE> study.lua:5: UNITE=19: $work/out/evil.geo is a gmsh script (.geo).*--unsafe-lua" log ||
    fail "no <F> naming LIRE_MAILLAGE, the file and --unsafe-lua"
  ;;
gnuplot_quotes)
  command -v gnuplot > /dev/null || { echo "gnuplot is not installed: skipped"; exit 0; }
  study='plot`touch pwned_name`.lua'
  cat > "$study" <<'LUA'
IMPR_FONCTION{FORMAT = 'SVG', TITRE = "`touch pwned_title` 'quoted' \"double\" $HOME @x", SOUS_TITRE = '`touch pwned_sub`',
              LEGENDE_X = '`touch pwned_x`', LEGENDE_Y = '`touch pwned_y`',
              COURBE = {ABSCISSE = {0, 1, 2}, ORDONNEE = {0, 1, 4}, LEGENDE = '`touch pwned_legend`'}}
LUA
  "$exe" "$study" > log 2>&1
  status=$?
  pwned
  [ "$status" -eq 0 ] || fail "exit status $status, expected 0"
  image='plot`touch pwned_name`/fonction_1.svg'
  [ -s "$image" ] || fail "no plot drawn"
  # Every text is drawn as written, backquotes and all.
  for text in '`touch pwned_title` '"'quoted'"' "double" $HOME @x' '`touch pwned_sub`' '`touch pwned_x`' \
              '`touch pwned_y`' '`touch pwned_legend`'; do
    grep -qF "<text>$text</text>" "$image" || fail "the plot does not show $text"
  done
  ;;
ctrl_c_*)
  case $case in
  ctrl_c_loop) code='while true do end' ;;
  ctrl_c_pcall) code='while true do pcall(function() while true do end end) end' ;;
  ctrl_c_coroutine) code='while true do coroutine.resume(coroutine.create(function() while true do end end)) end' ;;
  ctrl_c_formule) code='F = FORMULE{VALE = function(x) while true do end end, NOM_PARA = "X"}
F(1.0)' ;;
  # One call into the string library that never returns (no hook runs there):
  # the watchdog ends the run, plot and summary included.
  ctrl_c_string_find) code='IMPR_FONCTION{FORMAT = "SVG", COURBE = {ABSCISSE = {0, 1}, ORDONNEE = {0, 1}}}
TEST_FONCTION{VALEUR = {FONCTION = FORMULE{VALE = "X", NOM_PARA = "X"}, VALE_PARA = 1.0, VALE_CALC = 1.0}}
print("looping")
string.find(string.rep("a", 1e6), ".-.-.-.-.-.-.-b")' ;;
  *) fail "unknown case" ;;
  esac
  printf 'print("looping")\n%s\n' "$code" > study.lua
  set -m  # job control: the background run gets its own process group, SIGINT not ignored
  "$exe" --output-dir out study.lua > log 2>&1 &
  pid=$!
  for _ in $(seq 300); do grep -q looping log && break; sleep 0.1; done
  grep -q looping log || { kill -KILL "$pid"; fail "the study did not start"; }
  sleep 0.3
  kill -0 "$pid" 2> /dev/null || fail "the study ended by itself"
  start=$(date +%s%N)
  kill -INT "$pid"
  for _ in $(seq 500); do kill -0 "$pid" 2> /dev/null || break; sleep 0.01; done
  elapsed=$((($(date +%s%N) - start) / 1000000))
  kill -0 "$pid" 2> /dev/null && { kill -KILL "$pid"; fail "still running 5 s after SIGINT"; }
  wait "$pid"
  status=$?
  [ "$status" -eq 130 ] || fail "exit status $status after SIGINT, expected 130"
  [ "$elapsed" -le 1000 ] || fail "stopped $elapsed ms after SIGINT, expected within a second"
  grep -q "^<F> .*interrupted (SIGINT)" log || fail "no message about the interruption"
  if [ "$case" = ctrl_c_string_find ]; then
    [ -s out/fonction_1.svg ] || fail "the plot was not drawn"
    grep -q "<I> checks: 1 OK, 0 NOOK" log || fail "no summary of the checks"
  fi
  echo "stopped $elapsed ms after SIGINT"
  ;;
*) fail "unknown case" ;;
esac
echo "$case: OK"
