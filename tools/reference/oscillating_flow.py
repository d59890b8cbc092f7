#!/usr/bin/env python3
"""Reference values for crates/pendulum-theory/tests/all/oscillating_flow.rs.

1. bessel.csv: the ratio K1(z)/K0(z) of modified Bessel functions of the
   second kind at z = x e^{i pi/4} (the argument of Stokes's oscillating
   cylinder), x from 1e-3 to 100 (60 log-spaced points), by mpmath.besselk
   at 40 significant digits.
2. cylinder.csv: the cylinder's added-mass and damping coefficients
   k - i k' = 1 + 4 K1(z) / (z K0(z)), z = a sqrt(i omega / nu), at the
   same points, so the crate's whole formula is checked, not only the
   Bessel functions.

Run from the repository root: python3 tools/reference/oscillating_flow.py
(needs mpmath; the committed files were made with mpmath 1.3.0)."""
import csv
import os

import mpmath as mp

OUT = "crates/pendulum-theory/tests/data/oscillating_flow"
mp.mp.dps = 40


def main():
    os.makedirs(OUT, exist_ok=True)
    xs = [mp.mpf(10) ** (-3 + 5 * mp.mpf(i) / 59) for i in range(60)]
    with open(f"{OUT}/bessel.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["x", "ratio_re", "ratio_im"])
        for x in xs:
            z = x * mp.exp(1j * mp.pi / 4)
            r = mp.besselk(1, z) / mp.besselk(0, z)
            w.writerow([mp.nstr(x, 20), mp.nstr(r.real, 20), mp.nstr(r.imag, 20)])
    with open(f"{OUT}/cylinder.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["x", "added_mass", "damping"])
        for x in xs:
            z = x * mp.exp(1j * mp.pi / 4)
            g = 1 + 4 * mp.besselk(1, z) / (z * mp.besselk(0, z))
            w.writerow([mp.nstr(x, 20), mp.nstr(g.real, 20), mp.nstr(-g.imag, 20)])


if __name__ == "__main__":
    main()
