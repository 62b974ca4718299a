#!/usr/bin/env bash
# The web page (issue 41, docs/web.md): installs Debian's emscripten and Chromium when missing,
# the page's npm packages (npm ci: CodeMirror, esbuild, puppeteer-core), builds the `wasm` preset
# (build/wasm/site) and runs the browser test, which compares the page with build/default's
# klueng-cli (build that first: the README's test command; .ci/run runs this after it).
# Arguments go to the test: scripts/web-test.sh --screenshots build/wasm/screenshots
set -euo pipefail
cd "$(dirname "$0")/.."

missing=()
command -v emcc >/dev/null || missing+=(emscripten)
[ -x /usr/bin/chromium ] || missing+=(chromium)
command -v npm >/dev/null || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "web-test: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ ! -x build/default/src/cli/klueng-cli ]; then
  echo "web-test: build/default/src/cli/klueng-cli is missing: the test compares the page with it" >&2
  echo "  (cmake --preset default && cmake --build --preset default)" >&2
  exit 2
fi

(cd web && npm ci --no-audit --no-fund)
cmake --preset wasm
cmake --build --preset wasm
node web/tests/browser_test.mjs "$@"
