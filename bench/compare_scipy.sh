#!/usr/bin/env bash
# Prints our period / K(m) evaluation speed beside SciPy's vectorised
# scipy.special.ellipk on the same inputs, from one run on this machine.
# Builds its own Python venv in bench/.venv (numpy, scipy). Not part of CI.
#
# Usage: bash bench/compare_scipy.sh [N] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
N=${1:-1000000}
REPEATS=${2:-20}
VENV=bench/.venv
if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV"
  "$VENV/bin/pip" install --quiet --upgrade pip
  "$VENV/bin/pip" install --quiet numpy scipy
fi
cargo build --release --quiet -p pendulum-theory --example bench_period

echo "== machine: $(nproc) cores, $(uname -m); N=$N, best of $REPEATS passes"
echo "== pendulum-theory (Rust, one core)"
target/release/examples/bench_period "$N" "$REPEATS"
echo "== SciPy $("$VENV/bin/python" -c 'import scipy; print(scipy.__version__)') (numpy $("$VENV/bin/python" -c 'import numpy; print(numpy.__version__)'))"
"$VENV/bin/python" - "$N" "$REPEATS" <<'PY'
import sys, time
import numpy as np
from scipy.special import ellipk
n, repeats = int(sys.argv[1]), int(sys.argv[2])
for lo, hi in ((1.0, 15.0), (1.0, 179.0)):
    a = np.radians(np.linspace(lo, hi, n))
    m = np.sin(a / 2) ** 2
    def best(f):
        t = float("inf")
        for _ in range(repeats):
            s = time.perf_counter(); f(); t = min(t, time.perf_counter() - s)
        return t * 1e9 / n
    k = best(lambda: ellipk(m))
    # The whole period from amplitudes, as a NumPy user would write it.
    l_over_g = 0.99362 / 9.80665
    period = best(lambda: 4 * np.sqrt(l_over_g) * ellipk(np.sin(a / 2) ** 2))
    print(f"{lo:g}..{hi:g} deg  numpy period(A0): {period:.2f} ns  ellipk(m): {k:.2f} ns")
PY
