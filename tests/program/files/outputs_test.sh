#!/usr/bin/env bash
# No lost or corrupted file. Scenarios:
#   fsize         writes fail past a file-size limit (prlimit --fsize: EFBIG), as on
#                 a full disk: STAT_NON_LINE stops with exit 2 and a <F> naming the
#                 file and the reason, RESU.pvd lists exactly the whole instants on
#                 disk (as many as the message says), a MED file of an earlier run
#                 stays as it was; runs anywhere.
#   tmpfs         the same on a real full disk (a small tmpfs, ENOSPC); needs root
#                 and mount, skipped (exit 77) where mounting is not allowed.
#   stale         a folder reused by a run with fewer instants keeps no RESU_<k>.vtu
#                 of the earlier run, and nothing else is removed.
#   study_folder  --output-dir set to the study's folder, whose etude.med is the
#                 input mesh: IMPR_RESU{FORMAT='MED'} without a unit never writes
#                 over it; a unit bound to it is a <F>.
# usage: outputs_test.sh EXE SOURCE_DIR WORK_DIR SCENARIO
set -u
exe=$1 src=$2 work=$3 scenario=$4
here=$src/tests/program/files
mesh=$src/tests/bad_input/base.mail
fail() { echo "FAIL: $*"; [ -f "$work/log" ] && cat "$work/log"; exit 1; }

rm -rf "$work"
mkdir -p "$work"

# Runs aster-lite with ARGS under the limit LIMIT (bytes, or "none"); the log goes
# through a pipe (the limit would cut a log file too); sets $status.
run() {
  local limit=$1
  shift
  if [ "$limit" = none ]; then
    "$exe" "$@" 2>&1 | cat > "$work/log"
  else
    prlimit --fsize="$limit" "$exe" "$@" 2>&1 | cat > "$work/log"
  fi
  status=${PIPESTATUS[0]}
}

# DIR/RESU.pvd is whole and lists RESU_0.vtu, RESU_1.vtu, ..., each on disk and
# whole; no other RESU_<k>.vtu and no temporary folder is there. Sets $listed.
check_archive() {
  local dir=$1 k=0 f
  [ -f "$dir/RESU.pvd" ] || fail "no $dir/RESU.pvd"
  [ "$(tail -n 1 "$dir/RESU.pvd")" = "</VTKFile>" ] || fail "RESU.pvd is not whole"
  for f in $(sed -n 's/.*file="\([^"]*\)".*/\1/p' "$dir/RESU.pvd"); do
    [ "$f" = "RESU_$k.vtu" ] || fail "instant $k is listed as $f"
    [ -f "$dir/$f" ] || fail "$f is listed but absent"
    [ "$(tail -n 1 "$dir/$f")" = "</VTKFile>" ] || fail "$f is not whole"
    k=$((k + 1))
  done
  local onDisk
  onDisk=$(ls "$dir" | grep -cE '^RESU_[0-9]+\.vtu$')
  [ "$onDisk" -eq "$k" ] || fail "$onDisk RESU_<k>.vtu on disk, $k listed by RESU.pvd"
  ! ls -a "$dir" | grep -q partial || fail "temporary files left in $dir"
  listed=$k
}

# The run stopped on a write error: exit 2, the <F> names FILE and REASON, and says
# how many instants are on disk, which is what RESU.pvd lists.
check_full() {
  local dir=$1 file=$2 reason=$3
  [ "$status" -eq 2 ] || fail "exit status $status, expected 2"
  grep -qE "^<F> <STAT_NON_LINE> .*many_instants.lua:[0-9]+: cannot write $dir/$file: $reason; [0-9]+ instant\(s\) were stored before the failure, in $dir/RESU.pvd$" "$work/log" \
    || fail "no <F> naming $dir/$file and '$reason'"
  local said
  said=$(sed -n 's/.*; \([0-9]*\) instant(s) were stored before the failure.*/\1/p' "$work/log")
  check_archive "$dir"
  [ "$said" -eq "$listed" ] || fail "the message says $said instants were stored, RESU.pvd lists $listed"
  [ "$listed" -ge 1 ] || fail "no instant on disk"
}

# A copy of etude.lua and its mesh etude.med in DIR.
make_study() {
  mkdir -p "$1"
  cp "$here/etude.lua" "$1/"
  cp "$src/studies/ssnp150a.med" "$1/etude.med"
}

case $scenario in
  fsize)
    # The .pvd of 80 instants grows past the limit first (each .vtu, with its
    # SIEF_ELGA cell data, is smaller than it).
    run 3500 --output-dir "$work/pvd" -u 20="$mesh" "$here/many_instants.lua"
    check_full "$work/pvd" RESU.pvd "File too large"
    # The second instant's .vtu is past the limit.
    run 1900 --output-dir "$work/vtu" -u 20="$mesh" "$here/many_instants.lua"
    check_full "$work/vtu" RESU_1.vtu "File too large"
    [ "$listed" -eq 1 ] || fail "$listed instants listed, expected 1"
    # A MED file of an earlier run stays whole when this run cannot write it.
    make_study "$work/study"
    run none --output-dir "$work/out" "$work/study/etude.lua"
    [ "$status" -eq 0 ] || fail "exit status $status for the first run"
    cp "$work/out/etude.med" "$work/before.med"
    run 4096 --output-dir "$work/out" "$work/study/etude.lua"
    [ "$status" -eq 2 ] || fail "exit status $status under the limit, expected 2"
    grep -q "^<F> <IMPR_RESU> .*etude.lua:5: $work/out/etude.med: MED error while .*: File too large$" "$work/log" \
      || fail "no <F> naming etude.med and the limit"
    cmp -s "$work/out/etude.med" "$work/before.med" || fail "the earlier run's etude.med was changed"
    ! ls -a "$work/out" | grep -q partial || fail "temporary files left"
    ;;
  tmpfs)
    mnt=$work/mnt
    mkdir -p "$mnt"
    mount -t tmpfs -o size=512k tmpfs "$mnt" 2>/dev/null || { echo "cannot mount a tmpfs here: skipped"; exit 77; }
    trap 'umount "$mnt"' EXIT
    # 60 kB free: about a dozen of the 80 instants fit.
    dd if=/dev/zero of="$mnt/filler" bs=1k count=450 2>/dev/null
    run none --output-dir "$mnt" -u 20="$mesh" "$here/many_instants.lua"
    check_full "$mnt" 'RESU[^:]*' "No space left on device"
    [ "$listed" -lt 81 ] || fail "every instant fitted: the disk was not full"
    rm -f "$mnt"/* && rm -rf "$mnt"/.[!.]*
    # A MED file of an earlier run stays whole on a full disk.
    make_study "$work/study"
    run none --output-dir "$mnt" "$work/study/etude.lua"
    [ "$status" -eq 0 ] || fail "exit status $status for the first run"
    cp "$mnt/etude.med" "$work/before.med"
    dd if=/dev/zero of="$mnt/filler" bs=4k 2>/dev/null  # until the disk is full
    run none --output-dir "$mnt" "$work/study/etude.lua"
    [ "$status" -eq 2 ] || fail "exit status $status on a full disk, expected 2"
    grep -q "^<F> <IMPR_RESU> .*etude.lua:5: .*etude.med.*: No space left on device$" "$work/log" \
      || fail "no <F> naming etude.med and the full disk"
    cmp -s "$mnt/etude.med" "$work/before.med" || fail "the earlier run's etude.med was changed"
    ! ls -a "$mnt" | grep -q partial || fail "temporary files left"
    ;;
  stale)
    out=$work/out
    run none --output-dir "$out" -u 20="$mesh" "$here/three_instants.lua"
    [ "$status" -eq 0 ] || fail "exit status $status for three instants"
    check_archive "$out"
    [ "$listed" -eq 4 ] || fail "$listed instants listed, expected 4"
    echo "mine" > "$out/RESU_notes.txt"
    echo "mine" > "$out/OTHER_3.vtu"
    run none --output-dir "$out" -u 20="$mesh" "$here/one_instant.lua"
    [ "$status" -eq 0 ] || fail "exit status $status for one instant"
    check_archive "$out"
    [ "$listed" -eq 2 ] || fail "$listed instants listed, expected 2"
    [ "$(ls "$out" | grep '^RESU' | tr '\n' ' ')" = "RESU.pvd RESU_0.vtu RESU_1.vtu RESU_notes.txt " ] \
      || fail "files of the first run left: $(ls "$out" | tr '\n' ' ')"
    [ "$(cat "$out/RESU_notes.txt" "$out/OTHER_3.vtu")" = "$(printf 'mine\nmine')" ] || fail "a file not ours changed"
    grep -q "STAT_NON_LINE: 5 file(s) an earlier run wrote for RESU removed from $out (RESU.pvd, RESU_0.vtu, RESU_1.vtu, ...)" "$work/log" || fail "no message on the removal"
    ;;
  study_folder)
    study=$work/study
    make_study "$study"
    for pass in 1 2; do
      run none --output-dir "$study" "$study/etude.lua"
      [ "$status" -eq 0 ] || fail "exit status $status (pass $pass)"
      cmp -s "$study/etude.med" "$src/studies/ssnp150a.med" || fail "the input mesh etude.med was written over"
      grep -q "IMPR_RESU: FORMAT='MED' (UNITE=80) written to $study/etude-2.med (etude.med is an input of the study, never written over)$" "$work/log" \
        || fail "the first IMPR_RESU does not say where it wrote"
      grep -q "IMPR_RESU: FORMAT='MED' (UNITE=80) written to $study/etude-2.med (added to the file of an earlier IMPR_RESU of this run: mesh MAIL (already there)) (etude.med is an input of the study, never written over)$" "$work/log" \
        || grep -q "written to $study/etude-2.med (added to the file of an earlier IMPR_RESU of this run: mesh MAIL (already there))$" "$work/log" \
        || fail "the second IMPR_RESU does not say it added to etude-2.med"
      [ -s "$study/etude-2.med" ] || fail "no etude-2.med"
    done
    # A unit bound to the input mesh: a <F>, the mesh untouched.
    run none --output-dir "$work/out" -u 80="$study/etude.med" "$study/etude.lua"
    [ "$status" -eq 2 ] || fail "exit status $status with unit 80 bound to the input, expected 2"
    grep -q "^<F> <IMPR_RESU> .*etude.lua:5: UNITE=80 is bound to $study/etude.med, an input of the study (read by LIRE_MAILLAGE at .*etude.lua:4): aster-lite never writes over a file the study read; bind another file to the unit$" "$work/log" \
      || fail "no <F> naming the unit and the input"
    cmp -s "$study/etude.med" "$src/studies/ssnp150a.med" || fail "the input mesh etude.med was written over"
    ;;
  *)
    fail "unknown scenario $scenario"
    ;;
esac
echo "OK: $scenario"
