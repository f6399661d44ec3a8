# Sourced by the comparisons with PrusaSlicer (bench_prusaslicer.sh, bench_hollowing_prusa.sh),
# with $root the repository: prusaslicer_part SHAPE FACES HEIGHT checks that PrusaSlicer is
# installed, moves to a temporary folder (removed on exit) and writes there a generated part
# (tools/gen_family, seed 1) as member_000.ply and part.stl.
prusaslicer_part() {
  command -v prusa-slicer >/dev/null || { echo "prusa-slicer is not installed (apt-get install prusa-slicer)" >&2; exit 1; }
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  cd "$work"
  "$root/build/2020/tools/gen_family" --shape "$1" --faces "$2" --members 1 --height "$3" --seed 1 --out . >/dev/null
  "$root/scripts/meshlabserver" -i member_000.ply -o part.stl >/dev/null 2>&1
}
