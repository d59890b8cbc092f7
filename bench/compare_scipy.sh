#!/usr/bin/env bash
# Prints our figures beside SciPy's (and Boost.Odeint's, where Boost is
# installed) from one run on this machine:
#  1. period / K(m) evaluation speed against scipy.special.ellipk;
#  2. simulating 1000 periods of a seconds pendulum (3°, Q = 1e6) with every
#     turning point located, against solve_ivp(DOP853) with the same events
#     and Boost.Odeint's dopri5 (dense output) and rkf78 (step, then bisect):
#     wall time of the whole process (start-up included) and final amplitude
#     error against a converged reference, at several tolerances.
# Builds its own Python venv in bench/.venv (numpy, scipy). Not part of CI.
# For the Boost peer: apt-get install libboost-dev (g++ builds bench/boost_pendulum.cpp).
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
cargo build --release --quiet -p pendulum-cli

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

echo
echo "== Simulation: 1000 periods (2000.3414 s), l = 0.99362 m, A0 = 3 deg, Q = 1e6, all turning points"
echo "   wall time per process, start-up included (best of 10; SciPy: one run)"
BOOST=""
if command -v g++ >/dev/null && [ -f /usr/include/boost/numeric/odeint.hpp ]; then
  g++ -O3 -o bench/.venv/boost_pendulum bench/boost_pendulum.cpp && BOOST=bench/.venv/boost_pendulum
else
  echo "   (Boost.Odeint not installed: apt-get install libboost-dev to include it)"
fi
"$VENV/bin/python" bench/compare_simulation.py target/release/pendulum $BOOST
