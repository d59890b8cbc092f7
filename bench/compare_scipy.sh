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
DURATION=2000.3414
PENDULUM=target/release/pendulum
# The reference: our symplectic method at tolerance 1e-14 (DOP853 at 1e-14 agrees to 4e-12).
REFERENCE=$("$PENDULUM" simulate --length 0.99362m --amplitude 3deg --q 1e6 --duration ${DURATION}s \
  --method symplectic --tolerance 1e-14 --json | "$VENV/bin/python" -c 'import json,sys; print(json.load(sys.stdin)["final_amplitude_rad"])')
echo "reference final amplitude: $REFERENCE rad"
now() { date +%s.%N; }
report() { # name tol seconds amplitude
  "$VENV/bin/python" -c "import sys; n,t,s,a,r=sys.argv[1:]; print(f'{n:<22} tol {float(t):.0e}  {float(s)*1e3:9.1f} ms  final amplitude error {abs(float(a)-float(r))/float(r):.2e}')" "$1" "$2" "$3" "$4" "$REFERENCE"
}
for tol in 1e-8 1e-10 1e-12; do
  for method in dop853 symplectic; do
    t0=$(now)
    amp=$("$PENDULUM" simulate --length 0.99362m --amplitude 3deg --q 1e6 --duration ${DURATION}s \
      --method $method --tolerance $tol --swings /tmp/pendulum-bench-swings.csv --json \
      | "$VENV/bin/python" -c 'import json,sys; print(json.load(sys.stdin)["final_amplitude_rad"])')
    t1=$(now)
    # The JSON parse above is Python's start-up; time our process alone:
    t2=$(now)
    "$PENDULUM" simulate --length 0.99362m --amplitude 3deg --q 1e6 --duration ${DURATION}s \
      --method $method --tolerance $tol --swings /tmp/pendulum-bench-swings.csv --json >/dev/null
    t3=$(now)
    report "pendulum $method" $tol "$(echo "$t3 - $t2" | bc)" "$amp"
  done
  t0=$(now)
  line=$("$VENV/bin/python" bench/simulate_scipy.py $tol $DURATION)
  t1=$(now)
  report "scipy DOP853" $tol "$(echo "$t1 - $t0" | bc)" "$(echo "$line" | awk '{print $5}')"
  if command -v g++ >/dev/null && [ -f /usr/include/boost/numeric/odeint.hpp ]; then
    [ -x /tmp/boost_pendulum ] || g++ -O3 -o /tmp/boost_pendulum bench/boost_pendulum.cpp
    for stepper in dopri5 rkf78; do
      t0=$(now)
      line=$(/tmp/boost_pendulum $stepper $tol $DURATION)
      t1=$(now)
      report "boost $stepper" $tol "$(echo "$t1 - $t0" | bc)" "$(echo "$line" | awk '{print $5}')"
    done
  fi
done
rm -f /tmp/pendulum-bench-swings.csv
