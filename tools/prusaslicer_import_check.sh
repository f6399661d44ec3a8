#!/usr/bin/env bash
# Proves that an .sl1 / .sl1s archive opens in PrusaSlicer 2.5's own SLA-archive import, which only
# its GUI has (File > Import > Import SL1 / SL1S Archive; the CLI refuses the extension):
#   tools/prusaslicer_import_check.sh FILE.sl1s [OUT_DIR]
# Runs prusa-slicer under a private Xvfb with a fresh datadir, drives the menus with xdotool,
# imports the archive ("Import model and profile", default quality), exports the plate as
# OUT_DIR/imported.stl and checks that it has triangles and that its z extent is the archive's
# layer count x layer height (config.ini) within one layer. Prints one line, leaves a screenshot of
# the imported model in OUT_DIR/prusaslicer_import.png (or prusaslicer_import_failure.png) and
# exits 0 only on success. Needs prusa-slicer, Xvfb, xdotool, ImageMagick's import, localedef
# (scripts/setup installs them). PS_IMPORT_TIMEOUT: seconds the import may take (default 300).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
me="prusaslicer import"

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 FILE.sl1s [OUT_DIR]" >&2
  exit 2
fi
[ -f "$1" ] || { echo "$me: FAILED: no such file: $1" >&2; exit 1; }
archive=$(realpath "$1")
out=${2:-.}
mkdir -p "$out"
out=$(realpath "$out")
import_timeout=${PS_IMPORT_TIMEOUT:-300}
for tool in prusa-slicer Xvfb xdotool import localedef; do
  command -v "$tool" >/dev/null || { echo "$me: FAILED: $tool is missing (scripts/setup installs it)" >&2; exit 1; }
done

read -r layers layer_height < <("$root/scripts/python" -c '
import sys
from slicereuse_prusaslicer import archive_height
try:
    print(*archive_height(sys.argv[1]))
except ValueError as e:
    sys.exit(f"prusaslicer import: FAILED: {e}")' "$archive") || exit 1
rm -f "$out/imported.stl" "$out/prusaslicer_import.png" "$out/prusaslicer_import_failure.png"

tmp=$(mktemp -d)
xvfb= slicer=
cleanup() {
  if [ -n "$slicer" ] && kill -0 "$slicer" 2>/dev/null; then
    kill "$slicer" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$slicer" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$slicer" 2>/dev/null || true
  fi
  if [ -n "$xvfb" ]; then kill "$xvfb" 2>/dev/null || true; wait "$xvfb" 2>/dev/null || true; fi
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

fail() {
  [ -n "${DISPLAY:-}" ] && import -window root "$out/prusaslicer_import_failure.png" 2>/dev/null || true
  echo "$me: FAILED: $*" >&2
  [ -f "$tmp/ps.log" ] && grep -v -e '\[trace\]' -e DBus -e Dbus "$tmp/ps.log" | grep -iE 'error|exception' | tail -n 5 >&2
  exit 1
}

# The visible window whose title matches the regex, within $2 seconds (its id on stdout).
wait_window() {
  local deadline=$((SECONDS + $2)) id
  while [ $SECONDS -lt $deadline ]; do
    kill -0 "$slicer" 2>/dev/null || fail "PrusaSlicer exited while waiting for window '$1'"
    id=$(xdotool search --onlyvisible --name "$1" 2>/dev/null | head -n1) && [ -n "$id" ] && { echo "$id"; return 0; }
    sleep 0.2
  done
  return 1
}

wait_window_gone() {
  local deadline=$((SECONDS + $2))
  while [ $SECONDS -lt $deadline ]; do
    xdotool search --onlyvisible --name "$1" >/dev/null 2>&1 || return 0
    sleep 0.2
  done
  return 1
}

# wxWidgets exits at start when the English locale is missing: compile it privately if needed.
locale_env=(LANG=en_US.UTF-8 LC_ALL=en_US.UTF-8)
if ! locale -a 2>/dev/null | grep -qix 'en_US.utf-\?8'; then
  mkdir -p "$tmp/locale"
  localedef -i en_US -f UTF-8 "$tmp/locale/en_US.UTF-8" 2>/dev/null || fail "localedef could not make en_US.UTF-8 (package locales)"
  locale_env+=(LOCPATH="$tmp/locale")
fi

# A datadir that skips the Configuration Wizard (an installed SL1S printer), the system-info,
# update and unsaved-project dialogs and the tips, with the main window at the screen's corner so
# the menu bar's place is known.
datadir=$tmp/datadir
mkdir -p "$datadir/vendor"
cp /usr/share/PrusaSlicer/profiles/PrusaResearch.ini "$datadir/vendor/"
cat >"$datadir/PrusaSlicer.ini" <<'INI'
default_action_on_close_application = discard
default_action_on_dirty_project = 0
notify_release = none
preset_update = 0
version_check = 0
show_hints = 0
show_splash_screen = 0
version_system_info_sent = 2.5.0
restore_win_position = 1
window_mainframe = 0; 0; 1600; 1000; 1

[presets]
printer = Original Prusa SL1S SPEED
sla_print = 0.05 Normal @SL1S
sla_material = Prusa Orange Tough @0.05 SL1S

[vendor:PrusaResearch]
model:SL1S = default
INI

# A private Xvfb that picks a free display itself (-displayfd), as scripts/meshlabserver does.
Xvfb -displayfd 3 -screen 0 1600x1000x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb=$!
for _ in $(seq 200); do
  [ -s "$tmp/display" ] && break
  kill -0 "$xvfb" 2>/dev/null || fail "Xvfb did not start: $(cat "$tmp/xvfb.log")"
  sleep 0.05
done
[ -s "$tmp/display" ] || fail "Xvfb gave no display"
export DISPLAY=:$(head -n1 "$tmp/display")

start=$SECONDS
env "${locale_env[@]}" prusa-slicer --datadir "$datadir" >"$tmp/ps.log" 2>&1 &
slicer=$!
disown "$slicer"  # 2.5 may crash while quitting a big plate; no failure of the import, so no job notice
main=$(wait_window '^PrusaSlicer-' 60) || fail "no PrusaSlicer main window within 60 s"
sleep 2  # the plater finishes laying out after the window maps

# The File menu by a click at its place in the menu bar, then its items by their mnemonics (a key
# press before the menu has a selection would go to the menu bar's own mnemonics).
file_menu() {
  xdotool windowfocus --sync "$main"
  xdotool mousemove --window "$main" 18 13 click 1
  sleep 0.5
  xdotool key Down
}

file_menu
xdotool key i
sleep 0.3
xdotool key Down Down Return  # Import > the third item, "Import SL1 / SL1S Archive..."
dialog=$(wait_window '^Import SLA archive$' 15) || fail "File > Import > Import SL1 / SL1S Archive did not open its dialog"
xdotool windowfocus --sync "$dialog"
xdotool key space  # the file picker has the focus
chooser=$(wait_window '^Choose SLA archive:$' 15) || fail "the import dialog's file picker did not open"
xdotool windowfocus --sync "$chooser"
xdotool key ctrl+l
xdotool type --delay 10 "$archive"
sleep 0.5  # the location entry's completion must settle, or it takes the Return
xdotool key Return
wait_window_gone '^Choose SLA archive:$' 15 || fail "the file chooser did not take $archive"
xdotool windowfocus --sync "$dialog"
xdotool key Tab Tab Tab Tab Tab Tab space  # picker, what to import, quality, Cancel, OK
wait_window_gone '^Import SLA archive$' 15 || fail "the import dialog did not close on OK"
import_start=$SECONDS

# The import runs as a background job; File > Export > Export Plate as STL is enabled once the
# plate has the object, so it is tried until its file dialog opens.
while :; do
  file_menu
  xdotool key e
  sleep 0.4
  xdotool key s
  saver=$(wait_window '^Export STL file:$' 2) && break
  xdotool key Escape Escape Escape
  [ $((SECONDS - import_start)) -lt "$import_timeout" ] || fail "no object on the plate ${import_timeout} s after the import started"
  sleep 2
done
import_seconds=$((SECONDS - import_start))
xdotool windowfocus --sync "$saver"
xdotool key ctrl+a
xdotool type --delay 10 "$out/imported.stl"
sleep 0.5
xdotool key Return
wait_window_gone '^Export STL file:$' 15 || fail "the STL file dialog did not take $out/imported.stl"
# PrusaSlicer writes the STL on its main thread: done when the size holds still for a second.
size=-1
deadline=$((SECONDS + 120))
while [ $SECONDS -lt $deadline ]; do
  now=$(stat -c %s "$out/imported.stl" 2>/dev/null || echo -1)
  [ "$now" -gt 0 ] && [ "$now" = "$size" ] && break
  size=$now
  sleep 1
done
[ -s "$out/imported.stl" ] || fail "Export Plate as STL wrote no $out/imported.stl"

# The picture for a human: click the empty canvas (deselects), Z zooms to the objects.
xdotool mousemove --window "$main" 900 180 click 1
xdotool key z
sleep 3
import -window root "$out/prusaslicer_import.png"

file_menu
xdotool key q
deadline=$((SECONDS + 15))
while kill -0 "$slicer" 2>/dev/null && [ $SECONDS -lt $deadline ]; do sleep 0.2; done
kill -0 "$slicer" 2>/dev/null && echo "$me: note: File > Quit did not end PrusaSlicer within 15 s; it is killed" >&2
total_seconds=$((SECONDS - start))

verdict=$("$root/scripts/python" -c '
import sys
from slicereuse_prusaslicer import stl_z_extent
stl, layers, h = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
try:
    count, low, high = stl_z_extent(stl)
except ValueError as e:
    sys.exit(f"FAILED: {e}")
extent = high - low
about = f"z extent {extent:.3f} mm (archive: {layers} layers of {h:g} mm)"
if count == 0:
    sys.exit(f"FAILED: {stl} has no triangles")
if abs(extent - layers * h) > h + 1e-6:
    sys.exit(f"FAILED: {about}, not {layers * h:.3f} mm within one layer")
print(f"OK, {count} triangles, {about}")' "$out/imported.stl" "$layers" "$layer_height" 2>&1) || {
  echo "$me: $verdict" >&2
  exit 1
}
echo "$me: $verdict"
echo "$me: import ${import_seconds} s, whole run ${total_seconds} s" >&2
