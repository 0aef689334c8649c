#!/usr/bin/env bash
# Start-up of the program itself: no re-execution, nothing of its BLAS settings in
# the environment its children inherit.
# usage: startup_test.sh EXE SOURCE_DIR WORKDIR CASE
#   one_execve         strace: ssnp150a runs in the process started (one execve of the
#                      program, none of /proc/self/exe); skipped (77) without a working strace
#   child_environment  a child process (env, run by the study) sees no OPENBLAS_*,
#                      ASTER_BLAS* or GLIBC_TUNABLES variable
set -u
exe=$(realpath "$1") src=$(realpath "$2") work=$3 case=$4
fail() { echo "FAIL ($case): $*"; [ -f "$work/log" ] && cat "$work/log"; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
# Whatever the caller's environment: none of the variables the program might set
# itself, nor any other of their families the caller had (OPENBLAS_L2_SIZE, ...).
clean=(env -u OMP_NUM_THREADS -u GOTO_NUM_THREADS -u GLIBC_TUNABLES)
for name in $(compgen -e); do
  case $name in OPENBLAS_* | ASTER_BLAS*) clean+=(-u "$name") ;; esac
done

case $case in
one_execve)
  command -v strace > /dev/null || { echo "SKIP: no strace"; exit 77; }
  strace -f -o /dev/null true 2> /dev/null || { echo "SKIP: strace cannot trace here"; exit 77; }
  # LeakSanitizer cannot run under ptrace: a sanitizer build checks leaks elsewhere.
  "${clean[@]}" ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
    strace -f -qq -e trace=execve -o trace "$exe" --quiet --output-dir out "$src/studies/ssnp150a.lua" \
    > log 2>&1 || fail "exit status $?"
  grep -q ' OK ' log || fail "no check ran"
  program=$(grep -c "execve(\"$exe\"" trace)
  again=$(grep -c 'execve("/proc/self/exe"' trace)
  [ "$program" -eq 1 ] || { cat trace; fail "$program execve of $exe, expected 1"; }
  [ "$again" -eq 0 ] || { cat trace; fail "the program re-executed itself ($again execve of /proc/self/exe)"; }
  ;;
child_environment)
  cat > study.lua <<'LUA'
local child = assert(io.popen('env'))
io.write(child:read('a'))
child:close()
LUA
  "${clean[@]}" STARTUP_TEST_MARKER=seen "$exe" --unsafe-lua --output-dir out study.lua > log 2>&1 ||
    fail "exit status $?"
  grep -q '^STARTUP_TEST_MARKER=seen$' log || fail "the child's environment was not printed"
  leaked=$(grep -E '^(OPENBLAS_|ASTER_BLAS|GLIBC_TUNABLES=)' log)
  [ -z "$leaked" ] || fail "the child inherited: $leaked"
  ;;
*)
  fail "unknown case"
  ;;
esac
echo "PASS ($case)"
