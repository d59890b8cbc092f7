#!/usr/bin/env python3
"""Reference values of the Earth's body tide in gravity, from ETERNA PREDICT
(Wenzel 1996) through its Python wrapper PyGTide, for the `pendulum tide`
command's tests.

Writes crates/pendulum-theory/tests/data/tides/STATION.csv for two stations,
hourly from 2026-01-01T00:00:00Z to 2026-02-01T00:00:00Z inclusive (745 rows):

  bfo.csv        Black Forest Observatory (BFO), Schiltach, Germany:
                 48.3301 N, 8.3296 E, 589 m
  sutherland.csv South African Geodynamic Observatory Sutherland (SAGOS,
                 IGETS station SU), South Africa: 32.3814 S, 20.8109 E, 1755 m

Columns: `time` (ISO 8601, UTC, e.g. 2026-01-01T00:00:00Z) and
`gravity_nm_s2` (ETERNA's output channel "Signal [nm/s**2]", printed as ETERNA
prints it, F13.6, i.e. to 1e-6 nm/s^2). One leading '#' line names the maker.

Programs and data
-----------------
- PyGTide 0.9.7 (PyPI sdist, built with gfortran 12.2, numpy 2.4.6, pandas 3.1.1),
  wrapping "ETERNA PREDICT v3.4 (10/02/2013)" (ETERNA 3.4, i.e. 3.30 with the
  KSM03 catalogue added).
- Tidal potential catalogue: Kudryavtsev (2004) KSM03 (28 474 waves read by
  PREDICT here), PyGTide's default (`tidalpoten=8`), no amplitude
  truncation (`amtruncate=1e-10` m^2/s^2, the default). Hartmann-Wenzel 1995
  (HW95) is catalogue 7 and NOT the default.
- Time: input and output in UTC. ETERNA converts to TT with its leap-second
  table (commdat/etddt.dat; its last entry, 2017-01-01, TT-UTC = 69.184 s, is
  still correct for 2026) and to UT1 with commdat/etpolut1.dat (ends
  2024-11-23; ETERNA then holds the last UT1-UTC, 0.048 s, which moves the
  tide by < 0.01 nm/s^2). The wrapper warns that etddt.dat is old: harmless
  here. Nothing is downloaded: `pygtide.update()` (the only routine that goes
  online) is never called.
- Components: vertical component of the tidal acceleration ("gravity tide",
  `tidalcompo=0`), along the ellipsoidal normal (GRS80), at normal gravity of
  GRS80 (`statgravit` unset). Body tide only, Sun and Moon (plus KSM03's small
  terms: higher degrees, planets), the zero-frequency (permanent) tide
  INCLUDED (this month's long-period mean: +201 nm/s^2 at BFO, -40 at
  Sutherland). No ocean loading (PREDICT has none), no pole tide
  (`poltidecor=0`), no length-of-day tide (`lodtidecor=0`), no atmosphere.
  Heights are taken as ellipsoidal (Sutherland's 1755 m is its height above
  sea level; 30 m changes the tide by ~0.0005 %).
- Amplitude factors: the Wahr-Dehant-Zschau body-tide gravimetric factors
  delta that ETERNA computes (routine ETLOVE: Dehant 1987, elliptical,
  rotating, oceanless Earth, PREM with Zschau's INELASTIC mantle, liquid core;
  latitude dependent; the diurnal band has the nearly-diurnal free wobble
  resonance at 15.073729 deg/h, Wahr 1981). At BFO delta(2,0)=1.1672,
  delta(2,1)=1.1532 (before the resonance), delta(2,2)=1.1575, delta(3,m)=
  1.0728 (1.0695 for m=3), delta(4,m)=1.0363 (1.0350 for m=4).
  CAUTION: PyGTide's own default (one wave group 0-10 cpd with amplitude
  factor 1.0) is NOT this body tide: ETERNA divides each wave group's output
  by the body factor of the group's largest wave and multiplies it by the
  group's factor, so the default gives nearly the rigid-Earth tide. This
  script therefore runs PREDICT twice: once to read the body factor DBOD of
  the main wave of the single group 0-10 cpd, then with the group's amplitude
  factor set to exactly that DBOD, which leaves every wave with its own WDZ
  factor (the exact WDZ body tide, no band approximation).

SIGN CONVENTION (checked; see below): the value is the change of the
magnitude of gravity, positive DOWN, i.e. POSITIVE WHEN GRAVITY INCREASES
(what a gravimeter reads as more gravity). ETERNA's source says so (ETGCON:
"IC= 0: vertical tidal acceleration (gravity tide), geodetic coefficients in
nm/s**2 (positive down)": upward coefficients l*V/r with phase 180 deg), and
the series confirms it: with the Moon near upper culmination it is at or near
its minimum (the Moon's pull lifts, g decreases). Sutherland: the Moon
culminated 85.8 deg high at 2026-01-16 08:46 UTC (series: -1545.3 nm/s^2 at
09:00, the day's minimum -1546.1 at 10:00, the Sun then also near the
meridian) and 84.9 deg high at 2026-01-17 09:40 UTC (the day's minimum,
-1671.8 nm/s^2, at 10:00). BFO: the
Moon culminated 69.2 deg high at 2026-01-02 23:04 UTC; the series is
-1697.6 nm/s^2 at 23:00, the month's minimum. An independent time-domain
computation from astropy's Sun and Moon positions (g change = -delta dV/dup)
matches the semidiurnal band to 0.13 nm/s^2 rms, with the same sign. The
sign is the same as `pendulum tide`'s gravity_change_nm_s2 (positive: g
larger).

Accuracy (the programs' own statements): PyGTide's docs give the KSM03
catalogue ~0.025 nGal (0.00025 nm/s^2) rms; ETERNA's threshold table (for
HW95) gives 0.001 nm/s^2 rms at the threshold used (1e-10 m^2/s^2); output
is printed to 1e-6 nm/s^2. These are the accuracies of the model tide;
a real gravimeter also sees ocean loading (not modelled here), several to
tens of nm/s^2.

Note: ETERNA as shipped in PyGTide 0.9.7 caps the denominator 3cos^2(theta)-1
(theta geocentric colatitude) of the WDZ latitude terms of delta(2,0) at 0.1
in size (its "BUGFIX (2026)"); the true terms are finite there (they multiply
P20), so the zonal tide comes out wrong at geocentric latitudes 33.2..37.3
deg N or S, most near 35.26 deg: at Canberra (35.32 S) by +1.0..+2.3 nm/s^2.
Both stations here are outside that band (Sutherland: 3cos^2-1 = -0.15).

Regenerate (from the repository root; PyGTide needs gfortran to build):
  python3 -m venv /tmp/tidev && /tmp/tidev/bin/pip install pygtide==0.9.7
  /tmp/tidev/bin/python tools/reference/tides.py
"""
import os
import warnings

import numpy as np
import pygtide
import pygtide.etpred as etpred

OUT = "crates/pendulum-theory/tests/data/tides"
START = "2026-01-01"  # 00:00 UTC
HOURS = 31 * 24       # to 2026-02-01T00:00Z, both ends included
STEP_S = 3600
STATIONS = {
    # name: (latitude deg N, longitude deg E, ellipsoidal height m)
    "bfo": (48.3301, 8.3296, 589.0),
    "sutherland": (-32.3814, 20.8109, 1755.0),
}
CONTROL = dict(tidalpoten=8, tidalcompo=0, amtruncate=1e-10, poltidecor=0.0, lodtidecor=0.0)


def body_tide(lat, lon, height):
    """ETERNA's gravity body tide (WDZ factors, every wave its own), nm/s^2."""
    pt = pygtide.pygtide(msg=False)
    pt.set_wavegroup(np.array([[0.0, 10.0, 1.0, 0.0]]))
    pt.predict(lat, lon, height, START, HOURS, STEP_S, **CONTROL)
    assert int(etpred.controlmod.ngr) == 1
    dbod = float(etpred.controlmod.dbod[0])  # body factor of the group's main wave
    # The group's factor equal to the main wave's body factor: no rescaling.
    pt.set_wavegroup(np.array([[0.0, 10.0, dbod, 0.0]]))
    pt.predict(lat, lon, height, START, HOURS, STEP_S, **CONTROL)
    assert abs(float(etpred.controlmod.dbod[0]) - dbod) < 1e-15
    assert str(pt.headers[2]).startswith("Signal")
    raw = np.array(pt.raw())
    rows = []
    for date, hms, signal in raw[:, :3]:
        d, t = int(round(date)), int(round(hms))
        stamp = f"{d // 10000:04d}-{d // 100 % 100:02d}-{d % 100:02d}T{t // 10000:02d}:{t // 100 % 100:02d}:{t % 100:02d}Z"
        rows.append((stamp, signal))
    return rows, dbod


def main():
    warnings.filterwarnings("ignore", message="Please consider updating the leap second")
    os.makedirs(OUT, exist_ok=True)
    pt = pygtide.pygtide(msg=False)
    maker = (f"# made by tools/reference/tides.py with PyGTide {pygtide.__version__} "
             f"({pt.fortran_version}), KSM03, WDZ body tide, no ocean/pole/LOD; "
             "positive when gravity increases")
    for name, (lat, lon, height) in STATIONS.items():
        rows, dbod = body_tide(lat, lon, height)
        assert len(rows) == HOURS + 1
        assert rows[0][0] == "2026-01-01T00:00:00Z" and rows[-1][0] == "2026-02-01T00:00:00Z"
        path = f"{OUT}/{name}.csv"
        with open(path, "w", newline="\n") as fh:
            fh.write(f"{maker}; station {lat} {lon} {height} m\n")
            fh.write("time,gravity_nm_s2\n")
            for stamp, g in rows:
                fh.write(f"{stamp},{g:.6f}\n")
        g = np.array([r[1] for r in rows])
        print(f"{path}: {len(rows)} rows, main-wave factor {dbod:.6f}, "
              f"min {g.min():.3f} max {g.max():.3f} nm/s^2")


if __name__ == "__main__":
    main()
