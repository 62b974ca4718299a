#!/usr/bin/env bash
# Builds the libFuzzer targets (the `fuzz` preset: clang, ASan+UBSan) and runs each
# on its seed corpus and dictionary for SECONDS (default 60), two at a time.
# CI's smoke test; for a long run pass e.g. 3600. New inputs go to a scratch
# folder, never into fuzz/corpus; a crash, a hang (> 10 s) or a blow-up (> 2 GB)
# fails the script and leaves the input in build/fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
bin=build/fuzz/fuzz
artifacts=build/fuzz/artifacts
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$artifacts"

# target  corpus  dictionary
targets=(
  "fuzz_pipeline pipeline gcode.dict"
  "fuzz_macro macro gcode.dict"
  "fuzz_gcode gcode gcode.dict"
  "fuzz_config config -"
  "fuzz_bitmap bitmap bitmap.dict"
  "fuzz_design design design.dict"
)

run() {
  local target=$1 corpus=$2 dict=$3
  local args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
              -artifact_prefix="$artifacts/$target-")
  [ "$dict" = "-" ] || args+=(-dict="fuzz/dict/$dict")
  # Drawings: lines past dxflib's 1,023 characters hung it; let inputs grow past that.
  [ "$target" = "fuzz_design" ] && args+=(-max_len=16384)
  mkdir -p "$scratch/$target"
  if "$bin/$target" "${args[@]}" "$scratch/$target" "fuzz/corpus/$corpus" >"$scratch/$target.log" 2>&1; then
    echo "fuzz: $target clean, $(grep -h 'stat::number_of_executed_units' "$scratch/$target.log" | awk '{print $2}') runs in ${seconds}s," \
         "$(grep -ho 'cov: [0-9]*' "$scratch/$target.log" | tail -1), peak RSS $(grep -h 'stat::peak_rss_mb' "$scratch/$target.log" | awk '{print $2}') MB"
  else
    echo "fuzz: $target FAILED (input in $artifacts/):"
    grep -h -A12 '^==[0-9]*==ERROR\|^SUMMARY\|ERROR: libFuzzer' "$scratch/$target.log" | head -40
    # The input itself, so a failure seen only in CI can be replayed anywhere.
    local unit
    unit=$(ls -t "$artifacts/$target-"* 2>/dev/null | head -1 || true)
    if [ -n "$unit" ]; then
      echo "fuzz: $unit ($(stat -c %s "$unit") bytes) as base64:"
      head -c 4096 "$unit" | base64 -w 100
    fi
    return 1
  fi
}

status=0
pids=()
for i in "${!targets[@]}"; do
  # shellcheck disable=SC2086
  run ${targets[$i]} &
  pids+=($!)
  if (( ${#pids[@]} == 2 )) || (( i == ${#targets[@]} - 1 )); then
    for p in "${pids[@]}"; do wait "$p" || status=1; done
    pids=()
  fi
done
exit $status
