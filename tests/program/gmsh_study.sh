#!/usr/bin/env bash
# Runs a study on meshes that gmsh makes from a .geo file, as a user would:
#   gmsh_study.sh EXE GEO STUDY OUT [LEVEL ...]
# Copies GEO and STUDY into OUT (emptied first), then in OUT runs
#   gmsh -2 NAME.geo                                   (no LEVEL: NAME.msh, LIRE_MAILLAGE's unit 19)
#   gmsh -2 -setnumber level L NAME.geo -o NAME_L.msh  (for each LEVEL L)
# and `EXE STUDY`; the exit status is the study's (0: every check OK).
set -euo pipefail
exe=$1 geo=$2 study=$3 out=$4
shift 4
rm -rf "$out"
mkdir -p "$out"
cp "$geo" "$study" "$out/"
cd "$out"
g=$(basename "$geo")
name=${g%.geo}
if [ $# -eq 0 ]; then
  gmsh -2 "$g" > gmsh.log 2>&1 || { cat gmsh.log; exit 2; }
else
  for level in "$@"; do
    gmsh -2 -setnumber level "$level" "$g" -o "${name}_$level.msh" > "gmsh_$level.log" 2>&1 ||
      { cat "gmsh_$level.log"; exit 2; }
  done
fi
exec "$exe" "$(basename "$study")"
