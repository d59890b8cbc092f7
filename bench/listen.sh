#!/usr/bin/env bash
# Listening speed and memory: one and two hours of 48 kHz mono, made by
# `pendulum synth ticks`, analysed by `pendulum listen`, with the wall and
# user time and the peak resident memory from /usr/bin/time -v.
# Run from the repository root: bash bench/listen.sh
set -euo pipefail
cargo build --release -q
bin=target/release/pendulum
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for hours in 1 2; do
  wav="$dir/clock-${hours}h.wav"
  /usr/bin/time -f "synth ${hours} h: %e s wall, %M kB peak" \
    "$bin" synth ticks "$wav" --duration "${hours}h" --sample-rate 48000 \
    --bph 3600 --rate 4 --beat-error 0.8 --snr-db 20 --seed 3 >/dev/null
  /usr/bin/time -f "listen ${hours} h: %e s wall, %U s user, %M kB peak" \
    "$bin" listen "$wav" --json >"$dir/out.json"
  python3 - "$dir/out.json" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
print("  beats %d, missed %d, rate %.5f s/day (truth 4), beat error %.4f ms (truth 0.8)"
      % (v["beats"], v["missed"], v["rate_s_per_day"], v["beat_error_ms"]))
PY
done
