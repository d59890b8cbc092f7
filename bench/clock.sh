#!/usr/bin/env bash
# The long-run method against the symplectic integrator, and a year of a
# clock. Prints wall times (best of three) for:
#  1. a week of the free pendulum (3°, Q = 10^6, every turning point to CSV)
#     by `simulate --method averaged` and `--method symplectic --tolerance 1e-10`,
#     and how far their last turning points differ;
#  2. a year of a deadbeat seconds clock whose mainspring's drive falls by
#     30% over eight days and is rewound, a row a day.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
bin="$root/target/release/pendulum"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
best() { # best wall time of three runs of "$@"
  local b=1e9
  for _ in 1 2 3; do
    local s e
    s=$(date +%s.%N); "$@" >/dev/null; e=$(date +%s.%N)
    b=$(python3 -c "print(min($b, $e - $s))")
  done
  printf '%.3f' "$b"
}
week=(--length 0.99362m --amplitude 3 --q 1e6 --duration 1week)
a=$(best "$bin" simulate "${week[@]}" --method averaged --swings "$work/avg.csv")
s=$(best "$bin" simulate "${week[@]}" --method symplectic --tolerance 1e-10 --swings "$work/sym.csv")
echo "week, every turning point: averaged ${a} s, symplectic 1e-10 ${s} s, ratio $(python3 -c "print(round($s/$a, 1))")"
echo "  last turning point (averaged):   $(tail -1 "$work/avg.csv")"
echo "  last turning point (symplectic): $(tail -1 "$work/sym.csv")"
python3 - "$work/spring.csv" <<'PY'
import sys
rows = ["time_s,drive_factor"]
eight = 8 * 86400
for k in range(47):
    rows.append(f"{k * eight},1")
    rows.append(f"{(k + 1) * eight - 1},0.7")
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
PY
y=$(best "$bin" clock --length 0.99362m --q 10000 --escapement deadbeat --lift-angle 2 --drive 20uJ \
  --duration 1year --every 1day --drive-file "$work/spring.csv" --swings "$work/year.csv")
echo "year of a deadbeat clock, a row a day: ${y} s ($(($(wc -l < "$work/year.csv") - 1)) rows)"
echo "  last row: $(tail -1 "$work/year.csv")"
