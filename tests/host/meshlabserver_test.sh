#!/usr/bin/env bash
# Host tests: runs Debian's meshlabserver 2020.09 (through scripts/meshlabserver) with the
# example filter scripts on a generated family and checks what it wrote.
#   meshlabserver_test.sh CASE     CASE: slice | transfer | masks | print_job | errors | contours | crossparam |
#                                        supports
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
# error message in its log), without crashing. MESSAGE is the error's own words (a fragment
# that only this error's message holds, not just the filter's name), matched literally.
must_fail() {
  local log=$1 message=$2; shift 2
  local rc=0
  run "$log" "$@" || rc=$?
  [ "$rc" -eq 255 ] || { cat "$log" >&2; fail "expected exit status 255, got $rc: $*"; }
  grep -qF -- "$message" "$log" || { cat "$log" >&2; fail "log lacks '$message'"; }
  grep -qF "Problem with filter" "$log" || fail "meshlabserver did not report the filter failure"
}
# result LOG KEY: the value of KEY in the last filter result line of LOG (see docs/formats.md,
# "Filter result line").
result() { sed -n "s/^LOG: [0-9]* slicereuse-result .*\"$2\": \([^,}]*\).*/\1/p" "$1" | tail -n 1; }
# below A B / above A B: numeric comparisons of decimal or exponent notation.
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }
above() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 > b + 0) }'; }
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
  # xy member: every layer is certified and transferred.
  ok log_slice.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  ok log_transfer.txt -i "$m0" -i "$m1" -s "$EXAMPLES/transfer.mlx"
  grep -q "Transfer Slicing to Mesh: .* in 60 layers, 60 transferred, 0 re-sliced" log_transfer.txt ||
    fail "xy member should transfer all 60 layers: $(grep Transfer log_transfer.txt)"
  # The target's own files are a valid slicing of member 1 ...
  "$HOST_CHECK" slice --float "$m1" out/transfer.ctr out/transfer.enc
  # ... and equal slicing member 1 directly, point for point.
  edit slice.mlx direct.mlx 's#out/slice\.#out/direct.#g'
  ok log_direct.txt -i "$m1" -s direct.mlx
  "$HOST_CHECK" same out/transfer.ctr out/direct.ctr
  # Barycentric mode on a member changed in x-y only: every point stays on its plane.
  edit transfer.mlx bary.mlx 's/name="mode" value="0"/name="mode" value="1"/' 's#out/transfer\.#out/bary.#g'
  ok log_bary.txt -i "$m0" -i "$m1" -s bary.mlx
  deviation=$(result log_bary.txt max_plane_deviation)
  [ -n "$deviation" ] && below "$deviation" 1e-9 || fail "barycentric deviation on an xy member: '$deviation'"
  # A member changed in z within one band of heights: the band's layers are re-sliced, the
  # others transferred, and the result equals slicing the member directly (points, and masks
  # with S = 1).
  "$GEN_FAMILY" --shape arch --faces 4000 --members 2 --height 6 --seed 7 --z-band --out famb >/dev/null
  ok log_bslice.txt -i famb/member_000.ply -s "$EXAMPLES/slice.mlx"
  ok log_btransfer.txt -i famb/member_000.ply -i famb/member_001.ply -s "$EXAMPLES/transfer.mlx"
  transferred=$(result log_btransfer.txt transferred_layers) resliced=$(result log_btransfer.txt resliced_layers)
  [ "$(result log_btransfer.txt layers)" = 60 ] && [ "$resliced" -gt 0 ] && [ "$transferred" -gt $((2 * resliced)) ] ||
    fail "band member should transfer most layers and re-slice some: $(grep Transfer log_btransfer.txt)"
  # Barycentric mode on it: points leave their planes inside the band.
  ok log_bbary.txt -i famb/member_000.ply -i famb/member_001.ply -s bary.mlx
  deviation=$(result log_bbary.txt max_plane_deviation)
  [ -n "$deviation" ] && above "$deviation" 1e-3 || fail "barycentric deviation on a band member: '$deviation'"
  "$HOST_CHECK" slice --float famb/member_001.ply out/transfer.ctr out/transfer.enc
  ok log_bdirect.txt -i famb/member_001.ply -s direct.mlx
  "$HOST_CHECK" same out/transfer.ctr out/direct.ctr
  edit masks.mlx direct_masks.mlx 's#out/transfer\.ctr#out/direct.ctr#' 's#value="out/masks"#value="out/masks_direct"#'
  ok log_bmasks.txt -s "$EXAMPLES/masks.mlx"
  ok log_bmasks_direct.txt -s direct_masks.mlx
  ok log_bcmp.txt -s "$EXAMPLES/compare.mlx"
  grep -q "Compare Mask Stacks: 60 layers, min similarity 1 at layer 0, 0 differing pixels" log_bcmp.txt ||
    fail "band member, transfer vs direct masks: $(grep Compare log_bcmp.txt)"
  # A member changed in z everywhere fails most layers' certificate: the transfer falls back to
  # slicing every layer, and still equals slicing the member directly.
  "$GEN_FAMILY" --shape arch --faces 4000 --members 2 --height 6 --seed 7 --z-change --out famz >/dev/null
  ok log_zslice.txt -i famz/member_000.ply -s "$EXAMPLES/slice.mlx"
  ok log_ztransfer.txt -i famz/member_000.ply -i famz/member_001.ply -s "$EXAMPLES/transfer.mlx"
  grep -q "Transfer Slicing to Mesh: .* in \([0-9]*\) layers, 0 transferred, [1-9][0-9]* re-sliced" log_ztransfer.txt ||
    fail "z-changed member should take the fallback: $(grep Transfer log_ztransfer.txt)"
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
print_job)
  # Make Print Job on member 1 from member 0's encoding equals its direct print job (S = 1);
  # with contour_file, the contours equal direct slicing's.
  ok log_slice.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  layers=$("$HOST_CHECK" layers out/slice.ctr)
  edit print_job.mlx job.mlx 's#name="contour_file" value=""#name="contour_file" value="out/job.ctr"#'
  ok log_job.txt -i "$m1" -s job.mlx
  [ "$(result log_job.txt transferred_layers)" = "$layers" ] || fail "transfer: $(grep slicereuse-result log_job.txt)"
  [ "$(result log_job.txt resliced_layers)" = 0 ] || fail "re-sliced layers in an x-y member"
  [ -f out/print_job.sl1 ] || fail "no out/print_job.sl1"
  edit print_job.mlx direct_job.mlx 's#name="encoding_file" value="out/slice.enc"#name="encoding_file" value=""#' \
    's#out/print_job\.sl1#out/direct_job.sl1#'
  ok log_direct_job.txt -i "$m1" -s direct_job.mlx
  [ "$(result log_direct_job.txt resliced_layers)" = "$layers" ] || fail "direct job: $(grep slicereuse-result log_direct_job.txt)"
  edit compare.mlx cmp.mlx 's#out/masks_direct#out/direct_job.sl1#' 's#value="out/masks"#value="out/print_job.sl1"#'
  ok log_cmp.txt -s cmp.mlx
  grep -q "Compare Mask Stacks: $layers layers, min similarity 1 at layer 0, 0 differing pixels" log_cmp.txt ||
    fail "transferred vs direct print job: $(grep Compare log_cmp.txt)"
  # Labels: a solid box's name cut into its base (3 mm deep), as large as fits.
  "$GEN_FAMILY" --shape box --faces 2000 --members 1 --height 25 --seed 1 --out famlab >/dev/null
  edit print_job.mlx label_job.mlx 's#name="encoding_file" value="out/slice.enc"#name="encoding_file" value=""#' \
    's#name="labels" value="false"#name="labels" value="true"#' 's#out/print_job\.sl1#out/label_job.sl1#'
  ok log_label.txt -i famlab/member_000.ply -s label_job.mlx
  above "$(result log_label.txt label_height_mm)" 2.4 || fail "no label: $(grep -i label log_label.txt)"
  grep -q "Make Print Job: the current mesh labelled 'member_000'" log_label.txt ||
    fail "label not logged: $(grep -i label log_label.txt)"
  # On its front side instead (label_side 1), upright, logged with its side.
  edit print_job.mlx side_job.mlx 's#name="encoding_file" value="out/slice.enc"#name="encoding_file" value=""#' \
    's#name="labels" value="false"#name="labels" value="true"#' 's#name="label_side" value="0"#name="label_side" value="1"#' \
    's#out/print_job\.sl1#out/side_job.sl1#'
  ok log_side.txt -i famlab/member_000.ply -s side_job.mlx
  above "$(result log_side.txt label_height_mm)" 2.4 || fail "no side label: $(grep -i label log_side.txt)"
  grep -q "Make Print Job: the current mesh labelled 'member_000' on its front side" log_side.txt ||
    fail "side label not logged: $(grep -i label log_side.txt)"
  # Add Labels shows the label where the job cut it: the same height, its outline a new layer.
  ok log_add_label.txt -i famlab/member_000.ply -s "$EXAMPLES/add_labels.mlx" -o out/label_outline.ply -l x
  above "$(result log_add_label.txt label_height_mm)" 2.4 || fail "Add Labels: $(grep -i label log_add_label.txt)"
  [ -s out/label_outline.ply ] || fail "Add Labels wrote no outline layer"
  # Hollow Mesh shows the box's cavity (3 mm walls) as a new mesh layer, with its volume.
  ok log_hollow.txt -i famlab/member_000.ply -s "$EXAMPLES/hollow_mesh.mlx" -o out/cavity.ply -l x
  above "$(result log_hollow.txt cavity_mm3)" 1 || fail "Hollow Mesh: $(grep -i hollow log_hollow.txt)"
  [ -s out/cavity.ply ] || fail "Hollow Mesh wrote no cavity layer"
  # Add Drain Holes shows the hole as a point layer and writes it; a print job drills the hole of
  # that file, and, in one script, the one of the point layer it adds (layer 1): no resin trap.
  ok log_holes.txt -i famlab/member_000.ply -s "$EXAMPLES/add_drain_holes.mlx" -o out/holes.ply -l x
  [ "$(result log_holes.txt drain_holes)" = 1 ] || fail "Add Drain Holes: $(grep -i drain log_holes.txt)"
  [ -s out/holes.srp ] || fail "Add Drain Holes wrote no out/holes.srp"
  edit print_job.mlx holes_job.mlx 's#name="encoding_file" value="out/slice.enc"#name="encoding_file" value=""#' \
    's#name="hollow_wall_mm" value="0"#name="hollow_wall_mm" value="3"#' \
    's#name="drain_holes_file" value=""#name="drain_holes_file" value="out/holes.srp"#' 's#out/print_job\.sl1#out/holes_job.sl1#'
  ok log_holes_job.txt -i famlab/member_000.ply -s holes_job.mlx
  [ "$(result log_holes_job.txt drain_holes)" = 1 ] && [ "$(result log_holes_job.txt resin_traps)" = 0 ] ||
    fail "the holes file's job: $(grep -i 'drain\|trap' log_holes_job.txt)"
  edit print_job.mlx layer_job.mlx 's#name="encoding_file" value="out/slice.enc"#name="encoding_file" value=""#' \
    's#name="hollow_wall_mm" value="0"#name="hollow_wall_mm" value="3"#' \
    's#name="drain_points_layer" value="-1"#name="drain_points_layer" value="1"#' 's#out/print_job\.sl1#out/layer_job.sl1#'
  { sed '/<\/FilterScript>/d' "$EXAMPLES/add_drain_holes.mlx"; sed -n '/<filter name="Make Print Job">/,$p' layer_job.mlx; } >holes_layer.mlx
  ok log_holes_layer.txt -i famlab/member_000.ply -s holes_layer.mlx
  [ "$(result log_holes_layer.txt drain_holes)" = 1 ] && [ "$(result log_holes_layer.txt resin_traps)" = 0 ] ||
    fail "the point layer's job: $(grep -i 'drain\|trap' log_holes_layer.txt)"
  grep -q "drain hole at (.*) mm along (0.00, 0.00, -1.00)" log_holes_layer.txt ||
    fail "the point layer's hole: $(grep -i drain log_holes_layer.txt)"
  # Check Printability reads every layer of the print job and writes its CSV.
  ok log_check.txt -s "$EXAMPLES/check_printability.mlx"
  [ "$(result log_check.txt layers)" = "$layers" ] || fail "check_printability: $(grep slicereuse-result log_check.txt)"
  head -n 1 out/printability.csv | grep -q '^kind,first_layer,last_layer,' || fail "printability.csv: $(head -n 2 out/printability.csv)"
  edit slice.mlx direct.mlx 's#out/slice\.#out/direct.#g'
  ok log_direct.txt -i "$m1" -s direct.mlx
  "$HOST_CHECK" same --prefix out/job.ctr out/direct.ctr
  # Free Cached Memory after a print job in the same process gives back the encoding it cached.
  { sed '$d' job.mlx; sed -n '/<filter name="Free Cached Memory">/,/<\/filter>/p' "$EXAMPLES/free_cached_memory.mlx"
    echo '</FilterScript>'; } >job_free.mlx
  ok log_free.txt -i "$m1" -s job_free.mlx
  above "$(result log_free.txt encoding_bytes)" 0 || fail "no cached encoding freed: $(grep slicereuse-result log_free.txt)"
  above "$(result log_free.txt freed_bytes)" 0 || fail "no memory freed: $(grep slicereuse-result log_free.txt)"
  # A member with other faces is sliced directly, the result saying why; strict, it is refused
  # and nothing is written.
  "$GEN_FAMILY" --shape torus --faces 1000 --members 1 --height 6 --seed 1 --out other >/dev/null
  edit print_job.mlx other.mlx 's#out/print_job\.sl1#out/other.sl1#'
  ok log_other.txt -i other/member_000.ply -s other.mlx
  [ "$(result log_other.txt reused)" = 0 ] || fail "other faces: $(grep slicereuse-result log_other.txt)"
  grep -qF "Make Print Job: sliced directly, not by reuse: its faces differ from those of the mesh the encoding was made from" \
    log_other.txt || fail "the log does not say why the member was sliced directly"
  [ -f out/other.sl1 ] || fail "no out/other.sl1"
  edit print_job.mlx strict.mlx 's#out/print_job\.sl1#out/strict.sl1#' 's#name="strict" value="false"#name="strict" value="true"#'
  must_fail log_strict.txt "Make Print Job: the current mesh cannot be made by reuse: its faces differ" \
    -i other/member_000.ply -s strict.mlx
  [ ! -e out/strict.sl1 ] || fail "a refused print job left out/strict.sl1"
  ;;
errors)
  edit slice.mlx zero.mlx 's/name="layer_thickness" value="0.1"/name="layer_thickness" value="0"/'
  must_fail log1.txt "Slice Mesh with Encoding: layer_thickness must be greater than 0 mm (got 0)" -i "$m0" -s zero.mlx
  no_outputs
  edit slice.mlx neg.mlx 's/name="layer_thickness" value="0.1"/name="layer_thickness" value="-0.2"/'
  must_fail log2.txt "Slice Mesh with Encoding: layer_thickness must be greater than 0 mm (got -0.2)" -i "$m0" -s neg.mlx
  no_outputs
  # A parameter of the wrong type in a hand-written script: named, no assertion reached.
  edit slice.mlx wrongtype.mlx 's/type="RichFloat" name="layer_thickness" value="0.1"/type="RichInt" name="layer_thickness" value="1"/'
  must_fail log_type.txt "parameter 'layer_thickness' must be a number, but it is a RichInt" -i "$m0" -s wrongtype.mlx
  no_outputs
  edit slice.mlx nodir.mlx 's#out/slice\.enc#missing_dir/slice.enc#'
  must_fail log3.txt "encoding_file: cannot write 'missing_dir/slice.enc': folder 'missing_dir': No such file or directory" \
    -i "$m0" -s nodir.mlx
  no_outputs
  # The encoding write fails after the contour file was written (its 252-character name is
  # valid, but its staged twin, name.tmp-XXXXXX, is too long): neither file may remain.
  long=$(printf 'e%.0s' $(seq 248)).enc
  edit slice.mlx long.mlx "s#out/slice\.enc#out/$long#"
  must_fail log4.txt "cannot create a temporary file next to 'out/$long': File name too long" -i "$m0" -s long.mlx
  no_outputs
  # Transfer: missing map file, target with other faces and no map, missing encoding file.
  ok log5.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  rm -f out/slice.ctr
  edit transfer.mlx map.mlx 's#name="map_file" value=""#name="map_file" value="missing.map"#'
  must_fail log6.txt "Transfer Slicing to Mesh: cannot open the map file 'missing.map': No such file or directory" \
    -i "$m0" -i "$m1" -s map.mlx
  "$GEN_FAMILY" --shape torus --faces 1000 --members 1 --height 6 --seed 1 --out other >/dev/null
  must_fail log7.txt "needs a cross-parameterization map" -i "$m0" -i other/member_000.ply -s "$EXAMPLES/transfer.mlx"
  [ ! -e out/transfer.ctr ] && [ ! -e out/transfer.enc ] || fail "failed transfer left output"
  rm -f out/slice.enc
  must_fail log8.txt "Transfer Slicing to Mesh: cannot open 'out/slice.enc': No such file or directory" \
    -i "$m0" -i "$m1" -s "$EXAMPLES/transfer.mlx"
  # Masks and compare with missing inputs.
  must_fail log9.txt "Export Mask Images: cannot open 'out/transfer.ctr': No such file or directory" -s "$EXAMPLES/masks.mlx"
  must_fail log10.txt "Compare Mask Stacks: mask stack 'out/masks' does not exist" -s "$EXAMPLES/compare.mlx"
  no_outputs
  ;;
contours)
  # The io_encoding plugin: contour files open as layers and save back, exactly.
  ok log_slice.txt -i "$m0" -s "$EXAMPLES/slice.mlx"
  ok log_srb.txt -i out/slice.ctr -o out/copy.srb
  [ -f out/copy_enc.srb ] || fail "the encoding beside slice.ctr was not saved as copy_enc.srb"
  ok log_back.txt -i out/copy.srb -o out/back.ctr
  cmp out/back.ctr out/slice.ctr || fail "ctr -> srb -> ctr changed the contour file"
  cmp out/back.enc out/slice.enc || fail "ctr -> srb -> ctr changed the encoding file"
  # A layer changed by a MeshLab filter is saved as it is now, not as it was opened.
  cat >move.mlx <<'EOF'
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Transform: Translate, Center, set Origin">
  <Param type="RichEnum" name="traslMethod" value="0" enum_cardinality="4" enum_val0="XYZ translation" enum_val1="Center on Scene BBox" enum_val2="Center on Layer BBox" enum_val3="Set new Origin"/>
  <Param type="RichDynamicFloat" name="axisX" value="1" min="-100" max="100"/>
  <Param type="RichDynamicFloat" name="axisY" value="0" min="-100" max="100"/>
  <Param type="RichDynamicFloat" name="axisZ" value="0" min="-100" max="100"/>
  <Param type="RichPoint3f" name="newOrigin" x="0" y="0" z="0"/>
  <Param type="RichBool" name="Freeze" value="true"/>
  <Param type="RichBool" name="allLayers" value="false"/>
 </filter>
</FilterScript>
EOF
  ok log_move.txt -i out/slice.ctr -s move.mlx -o out/moved.ctr
  "$HOST_CHECK" shifted out/slice.ctr out/moved.ctr 1 >/dev/null
  # CLI (ASCII: meshlabserver saves with default parameters) and SLC, checked by the readers
  # written from the specifications.
  ok log_cli.txt -i out/slice.ctr -o out/slice.cli
  "$HOST_CHECK" export out/slice.ctr out/slice.cli | grep -q "^ok: ASCII CLI, \$\$LAYERS/$("$HOST_CHECK" layers out/slice.ctr)$" ||
    fail "slice.cli does not hold slice.ctr's layers"
  ok log_slc.txt -i out/slice.ctr -o out/slice.slc
  "$HOST_CHECK" export out/slice.ctr out/slice.slc >/dev/null
  # A CLI file opens too (no encoding), and ASCII CLI keeps every coordinate.
  ok log_fromcli.txt -i out/slice.cli -o out/fromcli.ctr
  "$HOST_CHECK" same out/fromcli.ctr out/slice.ctr >/dev/null
  # Masks from the opened layer (empty contour_file) equal masks from the file.
  edit masks.mlx layer_masks.mlx 's#value="out/transfer\.ctr"#value=""#' 's#value="out/masks"#value="out/masks_layer"#'
  edit masks.mlx file_masks.mlx 's#out/transfer\.ctr#out/slice.ctr#' 's#value="out/masks"#value="out/masks_file"#'
  ok log_lmasks.txt -i out/slice.ctr -s layer_masks.mlx
  ok log_fmasks.txt -s file_masks.mlx
  edit compare.mlx cmp.mlx 's#out/masks_direct#out/masks_layer#' 's#value="out/masks"#value="out/masks_file"#'
  ok log_cmp.txt -s cmp.mlx
  grep -q "Compare Mask Stacks: 60 layers, min similarity 1 at layer 0, 0 differing pixels" log_cmp.txt ||
    fail "masks from the layer differ from masks from the file: $(grep Compare log_cmp.txt)"
  # Damaged files are refused without a crash and without output; a plain mesh is no contour layer.
  # meshlabserver prints no IO plugin's message (README, known host issues), only that this file
  # failed to load; the readers' words are checked by the unit tests and test_io_encoding.py.
  head -c 2000 out/slice.cli >cut.cli
  rc=0; run log_cut.txt -i cut.cli -o out/cut.ctr || rc=$?
  [ "$rc" -eq 255 ] && [ ! -e out/cut.ctr ] && grep -qF "Failed loading of $WORK/cut.cli" log_cut.txt ||
    fail "a truncated CLI file was not refused (status $rc)"
  head -c 3000 out/slice.ctr >cut.ctr
  rc=0; run log_cutctr.txt -i cut.ctr -o out/cut.srb || rc=$?
  [ "$rc" -eq 255 ] && [ ! -e out/cut.srb ] && grep -qF "Failed loading of $WORK/cut.ctr" log_cutctr.txt ||
    fail "a truncated contour file was not refused (status $rc)"
  run log_plain.txt -i "$m0" -o out/plain.ctr || true
  grep -q "has NOT been saved" log_plain.txt && [ ! -e out/plain.ctr ] || fail "a plain mesh was saved as contours"
  ;;
crossparam)
  # Targets of really different connectivity: a member remeshed by MeshLab's Isotropic Explicit
  # Remeshing (another vertex count), and a member with its vertices and faces renumbered.
  here=$(cd "$(dirname "$0")" && pwd)
  # The arch pairs have 40000 faces: barycentric transfer places one point per source point on the
  # target's section and joins them by chords, so the source's sampling bounds S where the section
  # bends tightly (see test_crossparam.py).
  "$GEN_FAMILY" --shape arch --faces 40000 --members 2 --height 6 --seed 7 --out arch >/dev/null
  "$GEN_FAMILY" --shape arch --faces 40000 --members 2 --height 6 --seed 7 --shuffle --out shuffled >/dev/null
  "$GEN_FAMILY" --shape handle --faces 4000 --members 2 --height 6 --seed 7 --shuffle --out handle >/dev/null
  ok log_remesh.txt -i arch/member_001.ply -s "$here/remesh.mlx" -o remeshed.ply
  ok log_remesh_handle.txt -i handle/member_001.ply -s "$here/remesh.mlx" -o handle_remeshed.ply
  edit transfer.mlx exact.mlx 's#name="map_file" value=""#name="map_file" value="out/crossparam.map"#'
  edit transfer.mlx bary.mlx 's#name="map_file" value=""#name="map_file" value="out/crossparam.map"#' \
    's/name="mode" value="0"/name="mode" value="1"/' 's#out/transfer\.ctr#out/bary.ctr#' \
    's#name="target_encoding_file" value="out/transfer.enc"#name="target_encoding_file" value=""#'
  edit slice.mlx direct.mlx 's#out/slice\.#out/direct.#g' 's/name="z_start" value="-1e+30"/name="z_start" value="0"/'
  edit masks.mlx masks_direct.mlx 's#out/transfer\.ctr#out/direct.ctr#' 's#value="out/masks"#value="out/masks_direct"#'
  edit masks.mlx masks_bary.mlx 's#out/transfer\.ctr#out/bary.ctr#' 's#value="out/masks"#value="out/masks_bary"#'
  edit compare.mlx compare_bary.mlx 's#value="out/masks"#value="out/masks_bary"#'
  # pair SOURCE TARGET GENUS MIN_BARYCENTRIC_S: map, exact and barycentric transfer, checked.
  pair() {
    local source=$1 target=$2 genus=$3 min_s=$4
    rm -rf out && mkdir out
    ok log_slice.txt -i "$source" -s "$EXAMPLES/slice.mlx"
    ok log_map.txt -i "$source" -i "$target" -s "$EXAMPLES/crossparam.mlx"
    [ "$(result log_map.txt flipped_triangles)" = 0 ] || fail "$target: flipped triangles in the map"
    [ "$(result log_map.txt genus)" = "$genus" ] || fail "$target: genus $(result log_map.txt genus), expected $genus"
    # Exact transfer through the map equals slicing the target directly, with its own encoding.
    ok log_exact.txt -i "$source" -i "$target" -s exact.mlx
    grep -q "Transfer Slicing to Mesh: .*, through the map" log_exact.txt || fail "$target: transfer ignored the map"
    above "$(result log_exact.txt transferred_layers)" 0 || fail "$target: no layer was traced through the map"
    "$HOST_CHECK" slice --float "$target" out/transfer.ctr out/transfer.enc
    ok log_direct.txt -i "$target" -s direct.mlx
    "$HOST_CHECK" same out/transfer.ctr out/direct.ctr
    ok log_masks.txt -s "$EXAMPLES/masks.mlx"
    ok log_masks_direct.txt -s masks_direct.mlx
    ok log_cmp.txt -s "$EXAMPLES/compare.mlx"
    [ "$(result log_cmp.txt min_similarity)" = 1 ] || fail "$target: exact masks differ: $(grep Compare log_cmp.txt)"
    # Barycentric transfer through the map, against direct slicing of the target.
    ok log_bary.txt -i "$source" -i "$target" -s bary.mlx
    ok log_masks_bary.txt -s masks_bary.mlx
    ok log_cmp_bary.txt -s compare_bary.mlx
    local s; s=$(result log_cmp_bary.txt min_similarity)
    echo "$target: barycentric min S $s"
    if below "$s" "$min_s"; then fail "$target: barycentric masks reach only S = $s (< $min_s)"; fi
  }
  # The method's S >= 0.9999 on every layer, on every pair (the 40000-face arch pairs reach
  # 0.99996 remeshed and shuffled: the closest margin, set by the layers of the
  # arch's upper third, its domes' tops and tooth ridges).
  pair handle/member_000.ply handle_remeshed.ply 1 0.9999
  pair handle/member_000.ply handle/member_001.ply 1 0.9999
  pair arch/member_000.ply remeshed.ply 0 0.9999
  pair arch/member_000.ply shuffled/member_001.ply 0 0.9999
  # A genus-0 source and a genus-1 target are refused, and no map is written.
  rm -rf out && mkdir out
  must_fail log_genus.txt "cross-parameterization: the source has genus 0, the target 1" \
    -i "$m0" -i handle/member_001.ply -s "$EXAMPLES/crossparam.mlx"
  no_outputs
  ;;
supports)
  # The three support examples on a box family (raised: its flat bottom takes points on both
  # sides of x = 0, which the edit example tells apart): points generated on member 0,
  # transferred to member 1 (kept + moved + dropped = the source's), its supports built from its
  # file; member 1's print job on the transferred supports stands 60 layers (5 mm and the pad's
  # 1 mm at 0.1 mm) higher. A points file for another mesh is refused in words.
  "$GEN_FAMILY" --shape box --faces 4000 --members 2 --height 6 --seed 7 --out boxes >/dev/null
  ok log_gen.txt -i boxes/member_000.ply -s "$EXAMPLES/generate_supports.mlx"
  points=$(result log_gen.txt points)
  above "$points" 0 || fail "no support points: $(grep slicereuse-result log_gen.txt)"
  [ -f out/source.srp ] || fail "no out/source.srp"
  ok log_tr.txt -i boxes/member_001.ply -s "$EXAMPLES/transfer_supports.mlx"
  [ "$(result log_tr.txt transferred)" = "$points" ] || fail "transfer: $(grep slicereuse-result log_tr.txt)"
  [ $(( $(result log_tr.txt kept) + $(result log_tr.txt moved) + $(result log_tr.txt dropped) )) = "$points" ] ||
    fail "kept + moved + dropped is not the source's: $(grep slicereuse-result log_tr.txt)"
  ok log_build.txt -i boxes/member_001.ply -s "$EXAMPLES/build_supports.mlx"
  [ "$(result log_build.txt layers_below)" = 60 ] || fail "build: $(grep slicereuse-result log_build.txt)"
  [ "$(result log_build.txt points)" = "$(result log_tr.txt points)" ] || fail "build: not the member's points"
  edit print_job.mlx job.mlx 's#name="encoding_file" value="out/slice.enc"#name="encoding_file" value=""#' \
    's#name="supports" value="0"#name="supports" value="2"#' \
    's#name="support_points_file" value=""#name="support_points_file" value="out/source.srp"#' \
    's#out/print_job\.sl1#out/supported.sl1#'
  ok log_job.txt -i boxes/member_001.ply -s job.mlx
  [ "$(result log_job.txt support_points)" = "$(result log_tr.txt points)" ] || fail "job: $(grep slicereuse-result log_job.txt)"
  [ -f out/supported.sl1 ] || fail "no out/supported.sl1"
  # The point layer edited with MeshLab's own selection and delete filters: the supports are
  # built from the points left, as many as were generated minus those deleted.
  ok log_edit.txt -i boxes/member_000.ply -s "$EXAMPLES/edit_supports.mlx"
  deleted=$(sed -n 's/^LOG: [0-9]* Deleted \([0-9]*\) vertices, 0 faces\.$/\1/p' log_edit.txt | head -n 1)
  above "$deleted" 0 || fail "edit: no point deleted: $(grep -E 'Deleted|slicereuse-result' log_edit.txt)"
  [ "$(result log_edit.txt points)" = $(( points - deleted )) ] ||
    fail "edit: the supports are not built from the points left: $(grep -E 'Deleted|slicereuse-result' log_edit.txt)"
  must_fail log_other.txt "the support points are for a mesh of" -i "$m0" -s "$EXAMPLES/build_supports.mlx"
  edit transfer_supports.mlx other.mlx 's#out/member\.srp#out/other.srp#'
  must_fail log_other_tr.txt "the support points are for a mesh of" -i "$m0" -s other.mlx
  [ ! -e out/other.srp ] || fail "a points file was written for another mesh"
  ;;
*) fail "unknown case $case_name" ;;
esac
echo "host test $case_name: ok"
