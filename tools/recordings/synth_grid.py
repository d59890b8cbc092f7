#!/usr/bin/env python3
"""The grid of `pendulum synth ticks` recordings the listening is checked
on beside generate.py's: 12 beat rates x beat error 0/3/8 ms x SNR 30/12
dB, 40 s each, rate 7.3 s/day, seed bph + beat error + SNR; writes the
recordings and a truth.json that table.py reads.

    python tools/recordings/synth_grid.py /tmp/grid [--binary target/release/pendulum]
"""
import argparse
import json
import os
import subprocess

RATES = [1800, 2880, 3600, 5400, 7200, 9000, 14400, 18000, 21600, 28800, 36000, 43200]

p = argparse.ArgumentParser()
p.add_argument("dir")
p.add_argument("--binary", default="target/release/pendulum")
a = p.parse_args()
os.makedirs(a.dir, exist_ok=True)
truth = {}
for bph in RATES:
    for be in (0, 3, 8):
        be_ms = min(be, 0.15 * 3600 / bph * 1e3)
        for snr in (30, 12):
            name = f"synth_{bph}_be{be}_snr{snr}"
            subprocess.run([a.binary, "synth", "ticks", os.path.join(a.dir, name + ".wav"),
                            "--bph", str(bph), "--rate", "7.3", "--beat-error", f"{be_ms:g}",
                            "--duration", "40", "--snr-db", str(snr),
                            "--seed", str(bph + be + snr)], check=True, capture_output=True)
            truth[name] = {"bph": bph, "rate_s_per_day": 7.3, "beat_error_ms": be_ms,
                           "sample_rate": 44100, "shape": "synth", "snr_db": snr,
                           "missing": 0.0, "echo": True, "hum": True, "drift": False,
                           "two_sounds": False}
json.dump(truth, open(os.path.join(a.dir, "truth.json"), "w"), indent=1)
print(len(truth), "recordings in", a.dir)
