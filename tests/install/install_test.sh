#!/usr/bin/env bash
# The installed Klueng (issue 13): `cmake --install` into a scratch prefix and
# the .deb from CPack unpacked with `dpkg -x`; both run with no environment
# variables pointing at the sources. A missing tool fails this test, never skips it.
#   install_test.sh BUILD_DIR
set -euo pipefail
build="$(cd "$1" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "install_test: $*" >&2; exit 1; }
for tool in desktop-file-validate update-mime-database xvfb-run dpkg-deb cpack; do
  command -v "$tool" >/dev/null || fail "$tool is missing (scripts/setup.sh installs it)"
done

# A user with nothing set up: no KLUENG_DATA_DIR, an empty home.
run_as_new_user() {
  env -u KLUENG_DATA_DIR HOME="$work/home" XDG_DATA_HOME="$work/home/.local/share" \
      XDG_CONFIG_HOME="$work/home/.config" XDG_RUNTIME_DIR="$work/runtime" "$@"
}
mkdir -p "$work/home"
mkdir -m 700 -p "$work/runtime"  # Qt's runtime folder here, not /tmp/runtime-$USER

check_tree() {  # check_tree ROOT: the programs and data under ROOT/usr
  local root="$1" cli="$1/usr/bin/klueng-cli" data="$1/usr/share/klueng"
  local sample="$data/samples/01-step-shaft.txt"
  [ -x "$cli" ] || fail "$cli missing"
  [ -x "$root/usr/bin/klueng" ] || fail "klueng missing"
  for f in tools.cfg offset.cfg machine.cfg resources/tools/01-outside-turning.bmp \
           resources/tools/library/library.cfg samples/01-step-shaft.txt; do
    [ -f "$data/$f" ] || fail "$data/$f missing"
  done
  [ -f "$root/usr/share/man/man1/klueng-cli.1.gz" ] || fail "klueng-cli(1) missing"
  [ -f "$root/usr/share/icons/hicolor/scalable/apps/klueng.svg" ] || fail "icon missing"
  desktop-file-validate "$root/usr/share/applications/klueng.desktop" || fail "the .desktop file is not valid"

  run_as_new_user "$cli" check "$sample" || fail "$cli check on the installed sample failed"
  local t
  t="$(run_as_new_user "$cli" simulate "$sample" --cycle-time --no-persist)" || fail "simulate failed"
  [[ "$t" =~ ^[0-9]+\.[0-9]+$ ]] || fail "simulate --cycle-time printed '$t'"
  # --png opens the picture module from ../lib/klueng (the screen's painters).
  rm -f "$work/section.png"
  run_as_new_user "$cli" simulate "$sample" --no-persist --png "$work/section.png" || fail "simulate --png failed"
  file "$work/section.png" | grep -q "PNG image data" || fail "simulate --png wrote no PNG"

  # It reads the installed setup, not the sources: a bad value in the installed machine.cfg is reported there.
  cp "$data/machine.cfg" "$work/machine.cfg.keep"
  echo "rapid_x = -5" >>"$data/machine.cfg"
  local out status=0
  out="$(run_as_new_user "$cli" check "$sample" 2>&1)" || status=$?
  cp "$work/machine.cfg.keep" "$data/machine.cfg"
  [ "$status" -ne 0 ] || fail "with rapid_x = -5 in the installed machine.cfg, check exited 0"
  grep -q "^$data/machine.cfg:[0-9]*:[0-9]*: error" <<<"$out" || fail "expected an error in $data/machine.cfg, got: $out"

  # The MIME type: .nc files and G-code .txt files are lathe programs.
  cp -r "$root/usr/share/mime" "$work/mime"
  update-mime-database "$work/mime" >/dev/null 2>&1
  grep -q "text/x-gcode:\*\.nc" "$work/mime/globs" || fail "*.nc is not text/x-gcode"

  # The window, under Xvfb, on the installed sample.
  rm -f "$work/shot.png"
  run_as_new_user xvfb-run -a -s "-screen 0 1366x768x24" "$root/usr/bin/klueng" --lang en \
      --screenshot "$work/shot.png" "$sample" >/dev/null || fail "klueng --screenshot failed"
  [ "$(stat -c %s "$work/shot.png")" -gt 20000 ] || fail "the screenshot is too small"
}

cmake --install "$build" --prefix "$work/prefix/usr" >/dev/null || fail "cmake --install failed"
check_tree "$work/prefix"
echo "install_test: cmake --install tree ok"

(cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/deb" >/dev/null) || fail "cpack failed"
deb="$(ls "$work"/deb/klueng_*.deb)"
depends="$(dpkg-deb -f "$deb" Depends)"
for d in fonts-thai-tlwg libqt6widgets6 libqt6svg6; do
  grep -q "$d" <<<"$depends" || fail "the package does not depend on $d: $depends"
done
dpkg-deb -x "$deb" "$work/root"
check_tree "$work/root"
echo "install_test: $(basename "$deb") ok ($(stat -c %s "$deb") bytes; Depends: $depends)"
