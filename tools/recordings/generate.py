#!/usr/bin/env python3
"""A second generator of clock recordings, independent of `pendulum synth
ticks`, for checking `pendulum listen` on sounds it was not written against.

Written from scratch in numpy (it shares no code, shape or parameter with
the Rust synthesiser). What it varies, each from a fixed seed:

* the tick's shape: ringing modes (a struck metal part), a dry click, a
  burst of decaying noise (an escape wheel's tooth), a low wooden thud;
* two sounds a beat: the unlocking, 6 dB (or more) below the drop that
  follows it 3-30 ms later (the time across the lift), or one sound;
* the beat error (tick and tock intervals beat + e and beat - e, e up to
  8 ms), a rate of up to ±60 s/day, timing jitter of the escapement;
* noise (white and pink) for a tick peak to noise RMS of 30 down to 8 dB;
* a room: an early reflection and a reverberant tail;
* mains hum at 50 or 60 Hz with its third harmonic;
* the level drifting (the microphone or the clock moved), tick to tick
  loudness varying by ±20%;
* up to 30% of the ticks missing (lost under a louder noise, or not made);
* 1,800 to 36,000 beats an hour, at 44.1, 48 and 8 kHz; some copies as
  MP3 and M4A (ffmpeg).

Beside them: white noise, a non-clock sound (irregular knocks and a tone),
and a clean clip of ten beats.

Writes `DIR/<name>.wav` (16-bit PCM), the copies, and `DIR/truth.json`
(per recording: nominal bph, rate s/day, beat error ms, the true unlocking
and drop times of the ticks present, and what was varied).

    python tools/recordings/generate.py /tmp/recordings [--count 48]
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np

RATES = [1800, 2880, 3600, 4800, 5400, 7200, 9000, 10800,
         14400, 18000, 19800, 21600, 25200, 28800, 36000]
SAMPLE_RATES = [44100, 48000, 8000]
SHAPES = ["ringing", "click", "burst", "thud"]
SNRS = [30, 20, 15, 11, 8]
BEAT_ERRORS_MS = [0.0, 1.0, 3.0, 5.0, 8.0]
MISSING = [0.0, 0.1, 0.2, 0.3]


def tick_sound(rng, shape, fs, scale):
    """One sound of a tick, peak 1, as an array (at most 40 ms)."""
    nyq = 0.45 * fs
    n = int(0.04 * fs)
    t = np.arange(n) / fs
    if shape == "ringing":
        s = np.zeros(n)
        for _ in range(rng.integers(2, 5)):
            f = min(rng.uniform(1500, 7000), nyq * rng.uniform(0.5, 0.95))
            tau = rng.uniform(0.4e-3, 2.5e-3) * scale
            s += rng.uniform(0.3, 1) * np.exp(-t / tau) * np.sin(
                2 * np.pi * f * t + rng.uniform(0, 2 * np.pi))
    elif shape == "click":
        f = min(rng.uniform(3000, 9000), 0.9 * nyq)
        s = np.exp(-t / (0.25e-3 * scale)) * np.sin(2 * np.pi * f * t)
        s += 0.3 * np.exp(-t / 2e-3) * np.sin(2 * np.pi * rng.uniform(600, 1200) * t)
    elif shape == "burst":
        noise = rng.standard_normal(n)
        # A first difference: brighter than white, as metal on metal.
        noise = np.diff(noise, prepend=0.0)
        s = noise * np.exp(-t / (rng.uniform(0.6e-3, 2e-3) * scale))
    else:  # thud
        f = rng.uniform(250, 900)
        s = np.exp(-t / (rng.uniform(3e-3, 7e-3) * scale)) * np.sin(2 * np.pi * f * t)
        s += 0.4 * np.exp(-t / 0.5e-3) * rng.standard_normal(n)
    # A rise of a few samples: a real sound does not start on a step.
    rise = max(2, int(0.15e-3 * fs))
    s[:rise] *= np.linspace(0, 1, rise)
    return s / np.max(np.abs(s))


def pink(rng, n):
    """Pink noise by filtering white in the frequency domain, RMS 1."""
    spec = np.fft.rfft(rng.standard_normal(n))
    f = np.arange(len(spec))
    f[0] = 1
    spec /= np.sqrt(f)
    x = np.fft.irfft(spec, n)
    return x / np.std(x)


def recording(rng, spec):
    fs = spec["sample_rate"]
    bph = spec["bph"]
    nominal_beat = 3600.0 / bph
    beat = nominal_beat / (1 + spec["rate_s_per_day"] / 86400.0)
    e = spec["beat_error_ms"] * 1e-3
    duration = spec["duration_s"]
    n = int(duration * fs)
    # The true unlocking times: tick then tock intervals beat + e, beat - e.
    times = []
    t = rng.uniform(0.05, 0.9) * beat
    k = 0
    while t < duration - 0.06:
        times.append(t)
        t += beat + (e if k % 2 == 0 else -e)
        k += 1
    times = np.array(times)
    jitter = spec["jitter_us"] * 1e-6
    heard = times + jitter * rng.standard_normal(len(times))
    present = rng.random(len(times)) >= spec["missing"]
    shapes = [tick_sound(rng, spec["shape"], fs, 1.0) for _ in range(2)]
    drops = [tick_sound(rng, spec["shape"], fs, 1.3) for _ in range(2)]
    x = np.zeros(n + int(0.2 * fs))
    unlock_gain = 10 ** (-spec["unlock_below_drop_db"] / 20)
    drop_after = spec["drop_ms"] * 1e-3
    drop_times = []
    for i, (ti, keep) in enumerate(zip(heard, present)):
        if not keep:
            continue
        side = i % 2
        g = 1 + 0.2 * rng.uniform(-1, 1)
        if spec["two_sounds"]:
            add(x, ti, unlock_gain * g * shapes[side], fs)
            # The drop's delay varies a little beat to beat, as the swing.
            td = ti + drop_after * (1 + 0.02 * rng.standard_normal())
            add(x, td, g * drops[side], fs)
            drop_times.append(td)
        else:
            add(x, ti, g * shapes[side], fs)
    x = x[:n]
    if spec["echo"]:
        # An early reflection and a reverberant tail (exponential noise).
        d = int(rng.uniform(3e-3, 12e-3) * fs)
        x[d:] += 0.45 * x[:-d].copy()
        tail_n = int(0.4 * fs)
        tail = rng.standard_normal(tail_n) * np.exp(-np.arange(tail_n) / fs / 0.08)
        tail *= 0.35 / np.sqrt(np.sum(tail ** 2))
        x += np.convolve(x, tail)[:n] * 3
    if spec["drift"]:
        tt = np.arange(n) / fs
        x *= 10 ** ((-5 + 5 * np.sin(2 * np.pi * tt / duration + rng.uniform(0, 6.3))) / 20)
    # Noise against the loudest tick peak, with the level the ticks have.
    peak = np.percentile(np.abs(x[x != 0]), 99.9) if np.any(x) else 1.0
    sigma = peak / 10 ** (spec["snr_db"] / 20)
    noise = 0.7 * rng.standard_normal(n) + 0.7 * pink(rng, n)
    x += sigma * noise / np.std(noise)
    if spec["hum"]:
        tt = np.arange(n) / fs
        f = spec["hum_hz"]
        x += sigma * 3 * (np.sin(2 * np.pi * f * tt) + 0.4 * np.sin(2 * np.pi * 3 * f * tt + 1))
    x *= 0.5 / np.max(np.abs(x))
    unlocks = heard[present]
    return x, unlocks, np.array(drop_times), times


def add(x, t, sound, fs):
    """Adds `sound` starting at time `t`, to a fraction of a sample (by a
    linear interpolation of the sound, good to well under a microsecond at
    these rates for the timing the tests ask)."""
    start = t * fs
    i = int(math.floor(start))
    frac = start - i
    # The sound delayed by frac of a sample.
    s = np.concatenate([[0.0], sound])
    shifted = (1 - frac) * s[1:] + frac * s[:-1]
    end = min(len(x), i + len(shifted))
    if i < len(x):
        x[i:end] += shifted[: end - i]


def specs(count, rng):
    out = []
    for k in range(count):
        bph = RATES[k % len(RATES)]
        beat = 3600.0 / bph
        be = BEAT_ERRORS_MS[(k * 3) % len(BEAT_ERRORS_MS)]
        be = min(be, 0.15 * beat * 1e3)
        clock = bph <= 10800
        two = (k % 5) != 4
        spec = {
            "name": f"rec{k:02d}_{bph}",
            "bph": bph,
            "sample_rate": SAMPLE_RATES[(k // 3) % 3],
            "shape": SHAPES[(k // 2) % len(SHAPES)],
            "snr_db": SNRS[(k * 2) % len(SNRS)],
            "beat_error_ms": be,
            "rate_s_per_day": round(float(rng.uniform(-60, 60)), 3),
            "jitter_us": 200.0 if clock else 30.0,
            "two_sounds": two,
            "unlock_below_drop_db": float(rng.choice([6.0, 6.0, 9.0])) if two else 0.0,
            # The time across the lift: 10-30 ms for a pendulum clock,
            # 3-12 ms for a balance.
            "drop_ms": round(float(rng.uniform(10, 30) if clock else rng.uniform(3, 12)), 2),
            "echo": bool(k % 3 == 1),
            "hum": bool(k % 4 == 2),
            "hum_hz": 50.0 if k % 8 < 4 else 60.0,
            "drift": bool(k % 6 == 5),
            "missing": MISSING[(k // 4) % len(MISSING)],
            "duration_s": 120.0 if bph < 5400 else 60.0,
            "copies": ["mp3"] if k % 6 == 0 else (["m4a"] if k % 6 == 3 else []),
        }
        out.append(spec)
    return out


def write_wav(path, x, fs):
    import wave
    data = np.clip(np.round(x * 32767), -32768, 32767).astype("<i2")
    with wave.open(path, "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(fs)
        w.writeframes(data.tobytes())


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("dir")
    p.add_argument("--count", type=int, default=48)
    p.add_argument("--seed", type=int, default=2024)
    p.add_argument("--tests", action="store_true",
                   help="write only the three short 8 kHz recordings the CLI tests read "
                        "(crates/pendulum-cli/tests/data/recordings)")
    args = p.parse_args()
    if args.tests:
        return test_set(args)
    os.makedirs(args.dir, exist_ok=True)
    rng = np.random.default_rng(args.seed)
    truth = {}
    ffmpeg = shutil.which("ffmpeg")
    for spec in specs(args.count, rng):
        r = np.random.default_rng([args.seed, spec["bph"], len(truth)])
        x, unlocks, drops, _ = recording(r, spec)
        path = os.path.join(args.dir, spec["name"] + ".wav")
        write_wav(path, x, spec["sample_rate"])
        entry = dict(spec)
        entry["unlock_times_s"] = [round(float(t), 7) for t in unlocks]
        entry["drop_times_s"] = [round(float(t), 7) for t in drops]
        truth[spec["name"]] = entry
        for c in spec["copies"]:
            if not ffmpeg:
                print("no ffmpeg: copies skipped", file=sys.stderr)
                break
            out = os.path.join(args.dir, spec["name"] + "." + c)
            codec = ["-b:a", "128k"] if c == "mp3" else ["-c:a", "aac", "-b:a", "128k"]
            subprocess.run([ffmpeg, "-loglevel", "error", "-y", "-i", path, *codec, out],
                           check=True)
            copy = dict(entry)
            copy["copy_of"] = spec["name"]
            truth[spec["name"] + "." + c] = copy
    # Sounds that are not a clock, and a short clean clip.
    r = np.random.default_rng([args.seed, 1])
    fs = 44100
    write_wav(os.path.join(args.dir, "noise_white.wav"), 0.1 * r.standard_normal(30 * fs), fs)
    truth["noise_white"] = {"kind": "noise", "bph": 3600}
    n = 30 * fs
    x = 0.01 * r.standard_normal(n)
    t = 0.0
    while t < 29.0:
        add(x, t, r.uniform(0.2, 1) * tick_sound(r, "thud", fs, 1.0), fs)
        t += r.exponential(0.7)
    tt = np.arange(n) / fs
    x += 0.2 * np.sin(2 * np.pi * 440 * tt) * (np.sin(2 * np.pi * 0.3 * tt) > 0)
    write_wav(os.path.join(args.dir, "not_a_clock.wav"), x / np.max(np.abs(x)) * 0.5, fs)
    truth["not_a_clock"] = {"kind": "not_a_clock", "bph": 3600}
    spec = {"name": "clip10", "bph": 5400, "sample_rate": 44100, "shape": "ringing",
            "snr_db": 30, "beat_error_ms": 1.0, "rate_s_per_day": 10.0, "jitter_us": 50.0,
            "two_sounds": True, "unlock_below_drop_db": 6.0, "drop_ms": 15.0,
            "echo": False, "hum": False, "hum_hz": 50.0, "drift": False, "missing": 0.0,
            "duration_s": 10 * 3600 / 5400 + 0.1, "copies": []}
    x, unlocks, drops, _ = recording(np.random.default_rng([args.seed, 2]), spec)
    write_wav(os.path.join(args.dir, "clip10.wav"), x, 44100)
    spec["unlock_times_s"] = [round(float(t), 7) for t in unlocks]
    spec["drop_times_s"] = [round(float(t), 7) for t in drops]
    truth["clip10"] = spec
    with open(os.path.join(args.dir, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    print(f"{len(truth)} recordings in {args.dir}")


def test_set(args):
    """Three short recordings at 8 kHz for the command-line tests: a watch
    whose unlocking is 6 dB below its drop in a room with an echo, a clock
    8 ms out of beat, and a clip of ten beats whose tick and tock differ."""
    os.makedirs(args.dir, exist_ok=True)
    base = {"sample_rate": 8000, "jitter_us": 30.0, "two_sounds": True,
            "unlock_below_drop_db": 6.0, "hum": False, "hum_hz": 50.0, "drift": False,
            "missing": 0.0, "copies": []}
    cases = [
        dict(base, name="watch_19800_echo", bph=19800, shape="ringing", snr_db=30,
             beat_error_ms=0.0, rate_s_per_day=10.0, drop_ms=6.6, echo=True, duration_s=20.0),
        dict(base, name="clock_4800_out_of_beat", bph=4800, shape="thud", snr_db=20,
             beat_error_ms=8.0, rate_s_per_day=-14.0, drop_ms=13.4, echo=False,
             duration_s=30.0, jitter_us=200.0),
        dict(base, name="clip_5400_ten_beats", bph=5400, shape="ringing", snr_db=30,
             beat_error_ms=1.0, rate_s_per_day=10.0, drop_ms=15.0, echo=False,
             duration_s=10 * 3600 / 5400 + 0.1, jitter_us=50.0),
    ]
    truth = {}
    for k, spec in enumerate(cases):
        x, unlocks, drops, _ = recording(np.random.default_rng([args.seed, 7, k]), spec)
        write_wav(os.path.join(args.dir, spec["name"] + ".wav"), x, spec["sample_rate"])
        entry = dict(spec)
        entry["unlock_times_s"] = [round(float(t), 7) for t in unlocks]
        entry["drop_times_s"] = [round(float(t), 7) for t in drops]
        truth[spec["name"]] = entry
    with open(os.path.join(args.dir, "truth.json"), "w") as f:
        json.dump(truth, f, indent=1)
    print(f"{len(truth)} recordings in {args.dir}")


if __name__ == "__main__":
    main()
