#!/usr/bin/env python3
"""Runs `pendulum listen` on the recordings `generate.py` wrote (or on a
folder of `synth ticks` recordings with the same truth.json keys) and
prints a table of what it read against the truth, and the tally.

    python tools/recordings/table.py /tmp/recordings [--binary target/release/pendulum]

Each recording is read twice: free (the beat found) and with --bph. An
answer is
* right: the beat rate the clock's (not half, not double), the beat
  error within 0.5 ms and the rate within 1 s/day (free: when a rate is
  given at all);
* refused: exit 2 with a reason (counted right for noise and sounds that
  are not a clock, and as a refusal, not an error, for a clock at 8 dB);
* warned: off by more than 1 s/day with a warning printed;
* WRONG: anything else (a figure off with no warning; a non-clock read).
For WAV files with two sounds a beat, `event` says what the ticks were
timed on: `unlock`, `drop`, or `mixed N%` (the share on the other sound).
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np


def run(binary, path, extra):
    with tempfile.NamedTemporaryFile(suffix=".csv", delete=False) as f:
        ticks = f.name
    r = subprocess.run([binary, "listen", path, "--json", "--ticks", ticks, *extra],
                       capture_output=True, text=True)
    out = None
    times = None
    if r.returncode == 0:
        out = json.loads(r.stdout)
        data = np.loadtxt(ticks, delimiter=",", skiprows=1, ndmin=2)
        times = data[:, 0] if len(data) else np.array([])
    os.unlink(ticks)
    return r.returncode, out, r.stderr.strip(), times


def event(times, truth):
    """What the ticks were timed on: each tick's offset from the nearest
    true unlocking, near 0 (the unlocking) or near the drop."""
    unlocks = np.array(truth.get("unlock_times_s", []))
    drops = np.array(truth.get("drop_times_s", []))
    if times is None or len(times) == 0 or len(drops) == 0:
        return ""
    i = np.clip(np.searchsorted(unlocks, times), 1, len(unlocks) - 1)
    nearest = np.where(np.abs(times - unlocks[i - 1]) < np.abs(times - unlocks[i]),
                       unlocks[i - 1], unlocks[i])
    off = times - nearest
    d = truth["drop_ms"] * 1e-3
    on_drop = np.abs(off - d) < np.abs(off)
    share = on_drop.mean()
    if share > 0.98:
        return "drop"
    if share < 0.02:
        return "unlock"
    return f"mixed {100 * min(share, 1 - share):.0f}%"


def judge(name, truth, code, out, err):
    kind = truth.get("kind")
    if kind in ("noise", "not_a_clock"):
        return ("right (refused)" if code != 0 else "WRONG (read)"), ""
    if code != 0:
        return "refused", err.replace("error: ", "")[:90]
    true_bph = truth["bph"] * (1 + truth["rate_s_per_day"] / 86400)
    ratio = out["beats_per_hour"] / true_bph
    warned = bool(out.get("warning_codes"))
    if abs(ratio - 1) > 0.02:
        what = f"beat x{ratio:.2f}"
        return ("warned " if warned else "WRONG ") + what, ""
    be = out["beat_error_ms"] - truth["beat_error_ms"]
    if abs(be) > 0.5:
        return ("warned" if warned else "WRONG") + f" beat error {be:+.2f} ms", ""
    rate = out.get("rate_s_per_day")
    if rate is None:
        return "right (no rate)", ""
    e = rate - truth["rate_s_per_day"]
    if abs(e) <= 1.0:
        return "right", ""
    return ("warned" if warned else "WRONG") + f" {e:+.2f} s/day", ",".join(out["warning_codes"])


def main():
    p = argparse.ArgumentParser()
    p.add_argument("dir")
    p.add_argument("--binary", default="target/release/pendulum")
    args = p.parse_args()
    truth = json.load(open(os.path.join(args.dir, "truth.json")))
    tally = {}
    print("| recording | bph | kHz | shape | SNR dB | be ms | miss | echo/hum/drift | mode | "
          "read bph | rate err s/day | be read | event | verdict |")
    print("|" + "---|" * 14)
    for name, t in truth.items():
        fname = name if "." in name else name + ".wav"
        path = os.path.join(args.dir, fname)
        for mode, extra in (("free", []), ("--bph", ["--bph", str(t["bph"])])):
            code, out, err, times = run(args.binary, path, extra)
            verdict, note = judge(name, t, code, out, err)
            key = verdict.split(" ")[0]
            tally[(mode, key)] = tally.get((mode, key), 0) + 1
            if "kind" in t:
                print(f"| {name} | | | {t['kind']} | | | | | {mode} | | | | | {verdict} |")
                continue
            flags = "/".join(w for w, on in (("echo", t["echo"]), ("hum", t["hum"]),
                                             ("drift", t["drift"])) if on) or "-"
            read = f"{out['beats_per_hour']:.0f}" if out else ""
            rerr = (f"{out['rate_s_per_day'] - t['rate_s_per_day']:+.3f}"
                    if out and out.get("rate_s_per_day") is not None else "")
            be = f"{out['beat_error_ms']:.2f}" if out else ""
            ev = event(times, t) if ("copy_of" not in t and t.get("two_sounds")) else ""
            shape = t["shape"] + ("" if t.get("two_sounds") else " (1 sound)")
            print(f"| {name} | {t['bph']} | {t['sample_rate'] / 1000:g} | {shape} | "
                  f"{t['snr_db']} | {t['beat_error_ms']:g} | {t['missing']:.0%} | {flags} | "
                  f"{mode} | {read} | {rerr} | {be} | {ev} | {verdict} {note} |")
    print()
    for mode in ("free", "--bph"):
        row = {k: v for (m, k), v in tally.items() if m == mode}
        print(f"{mode}: " + ", ".join(f"{k} {v}" for k, v in sorted(row.items())))
    wrong = sum(v for (m, k), v in tally.items() if k == "WRONG")
    sys.exit(1 if wrong else 0)


if __name__ == "__main__":
    main()
