#!/usr/bin/env bash
# Makes the figures the README shows (docs/*.png) with the release binary.
# Usage: bash tools/figures/make_figures.sh [OUT_DIR]   (default: docs)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:-$root/docs}"
mkdir -p "$out"
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
bin="$root/target/release/pendulum"
# The isochronism of a deadbeat and a recoil escapement on the same seconds
# pendulum (5 kg, Q = 10,000, lift 2°, 20 µJ a beat at the nominal drive).
for kind in deadbeat recoil; do
  "$bin" clock --length 0.99362m --q 10000 --escapement "$kind" --lift-angle 2 \
    --drive 20uJ --drive-range 0.5x..2x --steps 13 --plot "$out/isochronism-$kind.png" >/dev/null
done
echo "wrote $out/isochronism-deadbeat.png $out/isochronism-recoil.png"
