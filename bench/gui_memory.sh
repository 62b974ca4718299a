#!/bin/sh
# The window's peak memory against the CLI's on one big program (issue 29 item 8, issue 42 item 3:
# the GUI within 3x, now 2x klueng-cli's peak).
#   bench/gui_memory.sh [BUILD_DIR] [BLOCKS] [roughing|mixed]   (defaults: build/default 2000000 roughing)
# Writes a straight roughing program of BLOCKS blocks (klueng-gen-program --roughing;
# mixed: its realistic job of cycles, arcs and tool changes instead),
# then measures with /usr/bin/time -v:
#   cli  klueng-cli simulate FILE
#   gui  klueng-bench-gui-memory FILE  (the real MainWindow, offscreen: open, check,
#        run to the end as fast as possible, quit; it prints RSS after each stage)
set -eu
build=${1:-build/default}
blocks=${2:-2000000}
shape=${3:-roughing}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prog="$work/roughing.nc"
if [ "$shape" = roughing ]; then
  "$build/bench/klueng-gen-program" --roughing "$blocks" "$prog"
else
  "$build/bench/klueng-gen-program" "$blocks" "$prog"
fi
echo "program: $blocks blocks, $(wc -l <"$prog") lines, $(du -m "$prog" | cut -f1) MB"

peak() {  # label, command...: wall time and max RSS of one process
  label=$1
  shift
  /usr/bin/time -v "$@" >"$work/out" 2>"$work/time" || { cat "$work/out" "$work/time"; exit 1; }
  kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time")
  wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$work/time")
  echo "$label: peak $((kb / 1024)) MB, wall $wall"
  echo "$kb" >"$work/$label.kb"
}

peak cli "$build/src/cli/klueng-cli" simulate "$prog" --config .
mkdir -p "$work/config/Klueng"
printf '[ui]\nlanguage=en\n' >"$work/config/Klueng/klueng.conf"
peak gui env XDG_CONFIG_HOME="$work/config" XDG_DATA_HOME="$work/data" QT_QPA_PLATFORM="${QT_QPA_PLATFORM:-offscreen}" \
  KLUENG_DATA_DIR="${KLUENG_DATA_DIR:-$PWD}" "$build/bench/klueng-bench-gui-memory" "$prog"
sed 's/^/  /' "$work/out"
awk -v g="$(cat "$work/gui.kb")" -v c="$(cat "$work/cli.kb")" 'BEGIN { printf "gui/cli peak: %.2fx (goal <= 2, issue 42 item 3)\n", g / c }'
