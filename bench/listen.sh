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
# A watch: an hour at 28,800 beats an hour (eight times the beats), in
# windows of five minutes.
wav="$dir/watch-1h.wav"
"$bin" synth ticks "$wav" --duration 1h --sample-rate 48000 --bph 28800 \
  --rate -3 --beat-error 0.4 --snr-db 25 --seed 5 >/dev/null
/usr/bin/time -f "listen watch 1 h --every 5min: %e s wall, %U s user, %M kB peak" \
  "$bin" listen "$wav" --every 5min --json >"$dir/out.json"
python3 - "$dir/out.json" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
print("  beats %d, missed %d, rate %.4f s/day (truth -3), beat error %.4f ms (truth 0.4), %d windows"
      % (v["beats"], v["missed"], v["rate_s_per_day"], v["beat_error_ms"], len(v["windows"])))
PY
# The same hour of a clock piped to `listen -` (live: bounded memory),
# beside the file.
wav="$dir/clock-live.wav"
"$bin" synth ticks "$wav" --duration 1h --sample-rate 48000 \
  --bph 3600 --rate 4 --beat-error 0.8 --snr-db 20 --seed 3 >/dev/null
/usr/bin/time -f "listen 1 h file --every 10min: %e s wall, %U s user, %M kB peak" \
  "$bin" listen "$wav" --every 10min --json >"$dir/file.json"
/usr/bin/time -f "listen - (1 h piped) --every 10min: %e s wall, %U s user, %M kB peak" \
  sh -c "cat '$wav' | '$bin' listen - --every 10min --json >'$dir/live.json'"
python3 - "$dir/file.json" "$dir/live.json" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))
lines = open(sys.argv[2]).read().splitlines()
v = json.loads(lines[-1])
print("  file: beats %d, rate %.6f s/day, beat error %.5f ms" % (f["beats"], f["rate_s_per_day"], f["beat_error_ms"]))
print("  pipe: beats %d, rate %.6f s/day, beat error %.5f ms, %d windows printed as they completed"
      % (v["beats"], v["rate_s_per_day"], v["beat_error_ms"], len(lines) - 1))
PY
