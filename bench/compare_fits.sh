#!/usr/bin/env bash
# Fits the same decay and trajectory files with `pendulum fit` and with
# scipy.optimize.curve_fit and prints both side by side (see compare_fits.py).
# Builds its own Python venv in bench/.venv (numpy, scipy). Not part of CI.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=bench/.venv
if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV"
  "$VENV/bin/pip" install --quiet --upgrade pip
  "$VENV/bin/pip" install --quiet numpy scipy
fi
cargo build --release --quiet -p pendulum-cli
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
"$VENV/bin/python" bench/compare_fits.py target/release/pendulum "$WORK"
