#!/usr/bin/env python3
"""Live listening at the sound card's pace, and its memory over the hours.

Latency: a recording made by `pendulum synth ticks` is fed to
`pendulum listen -` at real speed (blocks of 0.1 s, each when its time
comes), and each line it prints is stamped with the seconds of sound fed
by then: the first (provisional) reading's, and each window's lateness
after its end. Memory: ten minutes and an hour of a watch piped as fast as
they go, the peak resident memory of each (/usr/bin/time -v).

Run from the repository root after `cargo build --release`:
    python3 bench/live.py
"""
import json
import os
import subprocess
import sys
import tempfile
import threading
import time

BIN = os.path.join("target", "release", "pendulum")


def synth(path, bph, seconds, seed):
    subprocess.run([BIN, "synth", "ticks", path, "--bph", str(bph), "--duration", f"{seconds}s",
                    "--rate", "5", "--beat-error", "0.6", "--seed", str(seed)],
                   check=True, stdout=subprocess.DEVNULL)


def paced(path, every):
    """Feeds `path` at real speed; returns (fed seconds, line) for each line."""
    data = open(path, "rb").read()
    per_second = int.from_bytes(data[28:32], "little")
    child = subprocess.Popen([BIN, "listen", "-", "--every", every, "--json"],
                             stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    fed = [0.0]
    start = time.monotonic()

    def feed():
        child.stdin.write(data[:44])
        step = per_second // 10
        for i in range(44, len(data), step):
            child.stdin.write(data[i:i + step])
            child.stdin.flush()
            fed[0] = (i + step - 44) / per_second
            wait = start + fed[0] - time.monotonic()
            if wait > 0:
                time.sleep(wait)
        child.stdin.close()

    threading.Thread(target=feed, daemon=True).start()
    lines = [(time.monotonic() - start, json.loads(line)) for line in child.stdout]
    child.wait()
    return lines


def peak_kb(path):
    with open(path, "rb") as wav:
        run = subprocess.run(["/usr/bin/time", "-v", BIN, "listen", "-", "--every", "5min",
                              "--json"], stdin=wav, capture_output=True, text=True, check=True)
    line = [l for l in run.stderr.splitlines() if "Maximum resident" in l][0]
    return int(line.split()[-1])


def main():
    with tempfile.TemporaryDirectory() as d:
        for name, bph, seconds, every in [("watch", 28800, 60, "10s"),
                                          ("seconds clock", 3600, 330, "30s")]:
            wav = os.path.join(d, "rec.wav")
            synth(wav, bph, seconds, 45)
            lines = paced(wav, every)
            first = next(t for t, v in lines if "provisional" in v or "window" in v)
            late = [round(t - v["window"]["end_s"], 2) for t, v in lines if "window" in v]
            print(f"{name} ({bph} bph) at real speed: first reading after {first:.1f} s; "
                  f"windows of {every} printed after their ends by {late} s")
        for minutes in (10, 60):
            wav = os.path.join(d, f"watch-{minutes}.wav")
            synth(wav, 28800, minutes * 60, 11)
            print(f"a watch, {minutes} min piped: peak {peak_kb(wav) / 1024:.1f} MB")
            os.remove(wav)


if __name__ == "__main__":
    sys.exit(main())
