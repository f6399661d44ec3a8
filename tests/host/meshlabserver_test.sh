#!/usr/bin/env bash
# Host tests: runs Debian's meshlabserver 2020.09 (through scripts/meshlabserver) with the
# example filter scripts on a generated family and checks what it wrote.
#   meshlabserver_test.sh CASE     CASE: slice | transfer | masks | errors
# Environment (set by tests/host/CMakeLists.txt): MESHLABSERVER, SLICEREUSE_BUILD, GEN_FAMILY,
# HOST_CHECK, EXAMPLES, WORK (a scratch folder, emptied first).
set -euo pipefail
case_name=$1
rm -rf "$WORK" && mkdir -p "$WORK/out" && cd "$WORK"

fail() { echo "FAILED: $*" >&2; exit 1; }

# run LOG ARGS...: runs meshlabserver, keeps its output in LOG, and fails the test on a crash
# (signal or abort), which must never happen whatever the input.
run() {
  local log=$1; shift
  local rc=0
  "$MESHLABSERVER" "$@" >"$log" 2>&1 || rc=$?
  if [ "$rc" -ge 128 ] && [ "$rc" -ne 255 ]; then cat "$log" >&2; fail "meshlabserver crashed (status $rc): $*"; fi
  return "$rc"
}
ok() { run "$@" || { cat "$1" >&2; fail "meshlabserver failed: ${*:2}"; }; }
# must_fail LOG MESSAGE ARGS...: meshlabserver reports the failure (exit status 255, the filter's
# error message in its log), without crashing.
must_fail() {
  local log=$1 message=$2; shift 2
  local rc=0
  run "$log" "$@" || rc=$?
  [ "$rc" -eq 255 ] || { cat "$log" >&2; fail "expected exit status 255, got $rc: $*"; }
  grep -qF -- "$message" "$log" || { cat "$log" >&2; fail "log lacks '$message'"; }
  grep -qF "Problem with filter" "$log" || fail "meshlabserver did not report the filter failure"
}
no_outputs() { local left; left=$(find out -type f | head -n 5); [ -z "$left" ] || fail "files left behind: $left"; }

# edit SRC DST SED-EXPRESSIONS...: an example script with some values changed.
edit() { local src=$1 dst=$2; shift 2; local args=(); for e in "$@"; do args+=(-e "$e"); done; sed "${args[@]}" "$EXAMPLES/$src" >"$dst"; }

# Two members of an arch family (thin U-shaped sections with holes), and a torus with
# different faces for the connectivity check.
"$GEN_FAMILY" --shape arch --faces 4000 --members 2 --height 6 --seed 7 --out fam >/dev/null
m0=fam/member_000.ply m1=fam/member_001.ply

case $case_name in
slice)
  ok log_text.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  grep -q "Slice Mesh with Encoding: 60 layers" log_text.txt || fail "summary line missing: $(grep Slice log_text.txt)"
  "$HOST_CHECK" slice --float "$m0" out/slice.ctr out/slice.enc
  # Binary files, explicit z_start, and a preview layer saved by meshlabserver as an edge mesh.
  edit slice.mlx bin.mlx 's/name="file_format" value="0"/name="file_format" value="1"/' \
    's#out/slice\.ctr#out/slice.srb#' 's#out/slice\.enc#out/slice_enc.srb#' \
    's/name="z_start" value="-1e+30"/name="z_start" value="0.05"/' \
    's/name="preview_layers" value="0"/name="preview_layers" value="4"/'
  ok log_bin.txt -i "$m0" -s bin.mlx -o out/preview.ply -l x
  "$HOST_CHECK" slice --float "$m0" out/slice.srb out/slice_enc.srb
  [ "$(head -c 4 out/slice.srb)" != "# sl" ] || fail "file_format 1 wrote text"
  [ "$("$HOST_CHECK" layers out/slice.srb)" = 60 ] || fail "z_start 0.05 should give 60 layers of 0.1 below z = 6"
  grep -q "preview.ply (.* 0 fn)" log_bin.txt || fail "preview layer not saved as an edge mesh"
  ;;
transfer)
  ok log_slice.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  ok log_transfer.txt -i "$m0" -i "$m1" -s "$EXAMPLES/transfer.mlx"
  grep -q "Transfer Slicing to Mesh: .* in 60 layers" log_transfer.txt || fail "transfer summary missing"
  # The target's own files are a valid slicing of member 1 ...
  "$HOST_CHECK" slice --float "$m1" out/transfer.ctr out/transfer.enc
  # ... and equal slicing member 1 directly, point for point.
  edit slice.mlx direct.mlx 's#out/slice\.#out/direct.#g'
  ok log_direct.txt -i "$m1" -s direct.mlx
  "$HOST_CHECK" same out/transfer.ctr out/direct.ctr
  # Barycentric mode runs and reports its plane deviation.
  edit transfer.mlx bary.mlx 's/name="mode" value="0"/name="mode" value="1"/' 's#out/transfer\.#out/bary.#g'
  ok log_bary.txt -i "$m0" -i "$m1" -s bary.mlx
  grep -q "max plane deviation" log_bary.txt || fail "barycentric log lacks the plane deviation"
  # A member whose z changed: layers whose edges no longer straddle the same way are re-sliced,
  # and the result still equals slicing the member directly.
  "$GEN_FAMILY" --shape arch --faces 4000 --members 2 --height 6 --seed 7 --z-change --out famz >/dev/null
  ok log_zslice.txt -i famz/member_000.ply -s "$EXAMPLES/slice.mlx"
  ok log_ztransfer.txt -i famz/member_000.ply -i famz/member_001.ply -s "$EXAMPLES/transfer.mlx"
  grep -q "Transfer Slicing to Mesh: .*, [1-9][0-9]* re-sliced" log_ztransfer.txt ||
    fail "z-changed member re-sliced no layer: $(grep Transfer log_ztransfer.txt)"
  "$HOST_CHECK" slice --float famz/member_001.ply out/transfer.ctr out/transfer.enc
  ok log_zdirect.txt -i famz/member_001.ply -s direct.mlx
  "$HOST_CHECK" same --prefix out/transfer.ctr out/direct.ctr
  ;;
masks)
  ok log_slice.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  ok log_transfer.txt -i "$m0" -i "$m1" -s "$EXAMPLES/transfer.mlx"
  edit slice.mlx direct.mlx 's#out/slice\.#out/direct.#g'
  ok log_direct.txt -i "$m1" -s direct.mlx
  layers=$("$HOST_CHECK" layers out/transfer.ctr)
  # Masks need no mesh: run without -i.
  ok log_masks.txt -s "$EXAMPLES/masks.mlx"
  [ "$(find out/masks -name '*.png' | wc -l)" -eq "$layers" ] || fail "expected $layers PNG masks"
  edit masks.mlx direct_masks.mlx 's#out/transfer\.ctr#out/direct.ctr#' 's#value="out/masks"#value="out/masks_direct.sl1"#'
  ok log_masks_direct.txt -s direct_masks.mlx
  # A stack compared with itself: S = 1 on every layer.
  edit compare.mlx self.mlx 's#out/masks_direct#out/masks#' 's#out/compare\.csv#out/self.csv#'
  ok log_self.txt -s self.mlx
  grep -q "Compare Mask Stacks: $layers layers, min similarity 1 at layer 0, 0 differing pixels" log_self.txt ||
    fail "self comparison: $(grep Compare log_self.txt)"
  # Transferred vs directly sliced member (PNG folder vs .sl1 archive): identical masks.
  edit compare.mlx cmp.mlx 's#out/masks_direct#out/masks_direct.sl1#'
  ok log_cmp.txt -s cmp.mlx
  grep -q "Compare Mask Stacks: $layers layers, min similarity 1 at layer 0, 0 differing pixels" log_cmp.txt ||
    fail "transfer vs direct: $(grep Compare log_cmp.txt)"
  # The masks are not trivially equal: member 0's masks differ from member 1's.
  edit masks.mlx m0_masks.mlx 's#out/transfer\.ctr#out/slice.ctr#' 's#value="out/masks"#value="out/masks_m0"#'
  ok log_masks_m0.txt -s m0_masks.mlx
  edit compare.mlx m0.mlx 's#out/masks_direct#out/masks_m0#' 's#out/compare\.csv#out/m0.csv#'
  ok log_m0.txt -s m0.mlx
  grep -q "Compare Mask Stacks: $layers layers, min similarity 0\.[0-9]* at layer [0-9]*, [1-9][0-9]* differing pixels" log_m0.txt ||
    fail "member 0 vs member 1 masks should differ: $(grep Compare log_m0.txt)"
  rows=$(grep -c '^[0-9]' out/compare.csv)
  [ "$rows" -eq "$layers" ] || fail "compare.csv has $rows rows for $layers layers"
  ;;
errors)
  edit slice.mlx zero.mlx 's/name="layer_thickness" value="0.1"/name="layer_thickness" value="0"/'
  must_fail log1.txt "layer_thickness must be greater than 0" -i "$m0" -s zero.mlx
  no_outputs
  edit slice.mlx neg.mlx 's/name="layer_thickness" value="0.1"/name="layer_thickness" value="-0.2"/'
  must_fail log2.txt "layer_thickness must be greater than 0" -i "$m0" -s neg.mlx
  no_outputs
  edit slice.mlx nodir.mlx 's#out/slice\.enc#missing_dir/slice.enc#'
  must_fail log3.txt "encoding_file: cannot write" -i "$m0" -s nodir.mlx
  no_outputs
  # The encoding write fails after the contour file was written: neither file may remain.
  mkdir -p out/slice.enc.partial/blocker
  must_fail log4.txt "Slice Mesh with Encoding:" -i "$m0" -s "$EXAMPLES/slice.mlx"
  [ ! -e out/slice.ctr ] && [ ! -e out/slice.enc ] || fail "a failed run left an output file"
  rm -rf out/slice.enc.partial
  no_outputs
  # Transfer: unsupported map, target with other faces, missing encoding file.
  ok log5.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  rm -f out/slice.ctr
  edit transfer.mlx map.mlx 's#name="map_file" value=""#name="map_file" value="map.txt"#'
  must_fail log6.txt "cross-parameterization maps are not supported yet" -i "$m0" -i "$m1" -s map.mlx
  "$GEN_FAMILY" --shape torus --faces 1000 --members 1 --height 6 --seed 1 --out other >/dev/null
  must_fail log7.txt "Transfer Slicing to Mesh:" -i "$m0" -i other/member_000.ply -s "$EXAMPLES/transfer.mlx"
  [ ! -e out/transfer.ctr ] && [ ! -e out/transfer.enc ] || fail "failed transfer left output"
  rm -f out/slice.enc
  must_fail log8.txt "Transfer Slicing to Mesh:" -i "$m0" -i "$m1" -s "$EXAMPLES/transfer.mlx"
  # Masks and compare with missing inputs.
  must_fail log9.txt "Export Mask Images:" -s "$EXAMPLES/masks.mlx"
  must_fail log10.txt "Compare Mask Stacks:" -s "$EXAMPLES/compare.mlx"
  no_outputs
  ;;
*) fail "unknown case $case_name" ;;
esac
echo "host test $case_name: ok"
