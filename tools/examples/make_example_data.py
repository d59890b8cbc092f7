#!/usr/bin/env python3
"""Example measurement files for the book's `pendulum fit` commands,
made with fixed seeds so they never change. Run from the repository root:
python3 tools/examples/make_example_data.py  (standard library only)."""
import math
import random
import time

rng = random.Random(20261122)


def rk4(acc, th, v, h, steps):
    """`steps` classical Runge-Kutta steps of h for theta'' = acc(theta, theta')."""
    for _ in range(steps):
        k1 = (v, acc(th, v))
        k2 = (v + h / 2 * k1[1], acc(th + h / 2 * k1[0], v + h / 2 * k1[1]))
        k3 = (v + h / 2 * k2[1], acc(th + h / 2 * k2[0], v + h / 2 * k2[1]))
        k4 = (v + h * k3[1], acc(th + h * k3[0], v + h * k3[1]))
        th += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        v += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    return th, v


def rundown(path):
    """A seconds pendulum running down from 3 degrees, read every minute for
    two hours to 0.01 degree: viscous damping (Q = 10,000) with a little dry
    friction (a friction angle of 1e-6 rad), the mix the fit should find."""
    omega = math.sqrt(9.80665 / 0.99362)
    lam = omega / (2 * 10000.0)          # zeta * omega
    mu = 2 * 1e-6 * omega / math.pi      # 2r per half swing of pi/omega
    with open(path, "w") as f:
        f.write("# amplitude of a seconds pendulum, read every minute\ntime_s,amplitude_deg\n")
        for i in range(121):
            t = 60.0 * i
            a = math.radians(3.0) * math.exp(-lam * t) + mu * math.expm1(-lam * t) / lam
            f.write(f"{t:.0f},{math.degrees(a) + 0.01 * rng.gauss(0, 1):.4f}\n")


def video(path):
    """A 0.5 m pendulum released at 40 degrees, tracked at 60 frames a second
    for 8 s with 0.15 degree of noise and a 0.3 degree camera tilt;
    integrated with small RK4 steps (theta'' = -w^2 sin theta - 2 zeta w theta')."""
    w = math.sqrt(9.80665 / 0.5)
    zeta = 0.003
    def acc(th, v):
        return -w * w * math.sin(th) - 2 * zeta * w * v
    th, v, h = math.radians(40.0), 0.0, 1 / 60 / 200
    with open(path, "w") as f:
        f.write("# angle from video tracking, 60 frames per second\ntime_s,angle_deg\n")
        for frame in range(481):
            f.write(f"{frame / 60:.5f},{math.degrees(th) + 0.3 + 0.15 * rng.gauss(0, 1):.3f}\n")
            th, v = rk4(acc, th, v, h, 200)


def beats(path):
    """An hour of a seconds pendulum clock (3600 beats/hour) gaining 4 s/day,
    tocks 1.5 ms late, 0.2 ms of jitter, and two beats the timer missed."""
    beat = 1.0 / (1 + 4 / 86400)
    with open(path, "w") as f:
        f.write("# beam-break timer, one line per beat\ntime_s\n")
        for i in range(3600):
            if i in (1000, 2500):
                continue
            t = i * beat + (0.0015 if i % 2 else 0.0) + 0.0002 * rng.gauss(0, 1)
            f.write(f"{t:.6f}\n")


def tracker(path):
    """A Tracker export of a 1.2 m pendulum swinging in air, released at
    15.5 degrees and tracked at 30 frames a second for two minutes: viscous
    damping (zeta = 5.5e-4) and quadratic air drag (b = 0.025 per radian,
    theta'' = -w^2 sin theta - 2 zeta w theta' - b theta'|theta'|), the bob's
    x and y in metres about the pivot (Tracker's origin), 2 mm of tracking
    noise, a few frames where tracking was lost (blank cells), a title line,
    tab separators and CRLF line ends, as Tracker writes them."""
    length, w = 1.2, math.sqrt(9.80665 / 1.2)
    zeta, b = 5.5e-4, 0.025
    def acc(th, v):
        return -w * w * math.sin(th) - 2 * zeta * w * v - b * v * abs(v)
    th, v, sub = math.radians(15.5), 0.0, 40
    h = 1 / 30 / sub
    lost = {200, 201, 1777, 2950}
    with open(path, "w", newline="") as f:
        f.write("mass_A\r\nt\tx\ty\r\n")
        for frame in range(3601):
            t = frame / 30
            x = length * math.sin(th) + 0.002 * rng.gauss(0, 1)
            y = -length * math.cos(th) + 0.002 * rng.gauss(0, 1)
            if frame in lost:
                f.write(f"{t!r}\t\t\r\n")
            else:
                f.write(f"{t!r}\t{x!r}\t{y!r}\r\n")
            th, v = rk4(acc, th, v, h, sub)


def semicolon(path):
    """The run-down of rundown() as a spreadsheet in much of Europe saves
    it: a title, semicolons, decimal commas, units in parentheses."""
    omega = math.sqrt(9.80665 / 0.99362)
    lam = omega / (2 * 10000.0)
    with open(path, "w") as f:
        f.write("Messung Pendeluhr, Ablesung jede Minute\nZeit (s);Amplitude (°)\n")
        for i in range(121):
            t = 60.0 * i
            a = math.degrees(math.radians(3.0) * math.exp(-lam * t)) + 0.01 * rng.gauss(0, 1)
            f.write(f"{t:.0f};{a:.4f}".replace(".", ",") + "\n")


def spring(path):
    """A year of a clock's drive for `pendulum clock --drive-file`: an
    eight-day mainspring wound every Sunday (the drive falling from 1.0 to
    0.8 of its mean over the week, a fusee-less spring's run), a room 15 °C
    in winter and 23 °C in summer, and a barometer wandering about
    1013 hPa (a random walk pulled back, fixed seed). One row a day; its
    own random generator, so the other files do not change."""
    walk = random.Random(20261124)
    pressure = 1013.0
    with open(path, "w") as f:
        f.write("time_s,drive_factor,temperature_c,pressure_hpa\n")
        for day in range(366):
            drive = 1.0 - 0.2 * (day % 7) / 7.0
            temperature = 19.0 - 4.0 * math.cos(2.0 * math.pi * (day - 15) / 365.25)
            pressure += -0.2 * (pressure - 1013.0) + 6.0 * walk.gauss(0, 1)
            f.write(f"{86400 * day},{drive:.4f},{temperature:.2f},{pressure:.1f}\n")


def offsets(path):
    """Two weeks of a clock's offset from GPS for `pendulum stability`, one
    reading a minute: a rate of +0.5 s/day, white frequency noise of
    3e-7 a minute (each minute's rate drawn afresh), white phase noise of
    5 µs (the timer's) and a two-hour gap on day 5. Its own seeded
    generator, so the other files do not change."""
    rng = random.Random(26)
    x = 0.0
    with open(path, "w") as f:
        f.write("time_s,offset_s\n")
        for i in range(14 * 1440):
            t = 60.0 * i
            if i > 0:
                x += 60.0 * (0.5 / 86400.0 + 3e-7 * rng.gauss(0, 1))
            if 5 * 1440 <= i < 5 * 1440 + 120:
                continue
            f.write(f"{t:.0f},{x + 5e-6 * rng.gauss(0, 1):.9f}\n")


def frequency(path):
    """A thousand hourly fractional frequencies, no header, for
    `pendulum stability --kind frequency --tau0 1h`: white frequency
    noise of 1e-7 about 5.8e-6 (0.5 s/day)."""
    rng = random.Random(27)
    with open(path, "w") as f:
        for _ in range(1000):
            f.write(f"{0.5 / 86400.0 + 1e-7 * rng.gauss(0, 1):.6e}\n")


def clock_log(path, events_path):
    """Sixty days of a regulator's log for `pendulum log`, one row every
    10 minutes from 2026-01-01 UTC at Cambridge (52.2 N, 0.12 E): the
    offset from GPS (white phase noise 100 µs), the room's temperature
    (a daily and a weekly swing), pressure wandering like weather,
    humidity. The rate is +0.5 s/day, drifting +0.01 s/day a day,
    -0.3 s/day per °C of the temperature lagged by 3 h (the compensator
    follows the air late), -0.012 s/day per hPa, -0.002 s/day per % RH,
    the body tide in full (from `pendulum tide`, whose model is checked
    against ETERNA on its own), a regulation of +0.3 s/day on day 20
    (examples/clock-events.csv), and white frequency noise of 0.02 s/day
    an hour. Needs the `pendulum` binary (target/release or PATH)."""
    import os
    import subprocess
    rng = random.Random(28)
    binary = "target/release/pendulum" if os.path.exists("target/release/pendulum") else "pendulum"
    step = 600.0
    rows = 60 * 144
    tide = subprocess.run([binary, "tide", "--latitude", "52.2", "--longitude", "0.12", "--from",
                           "2026-01-01T00:00Z", "--to", "2026-03-02T00:00Z", "--every", "10min",
                           "--csv", "--force"], capture_output=True, text=True, check=True).stdout
    tidal = [float(line.split(",")[2]) for line in tide.splitlines()[1:]]
    x, pressure = 0.0, 1013.0
    tau = 3 * 3600.0
    start = 1767225600  # 2026-01-01T00:00:00Z

    def air(day):
        return 18.0 + 1.5 * math.sin(2 * math.pi * (day - 0.4)) + 1.0 * math.sin(2 * math.pi * day / 7.0)

    lag = air(0.0)
    with open(path, "w") as f:
        f.write("time,offset_s,temperature_c,pressure_hpa,humidity_percent\n")
        for i in range(rows):
            t = i * step
            day = t / 86400.0
            temperature = air(day)
            # The compensator's temperature: the exact first-order lag of
            # the air, linear between rows; its mean over the 10 minutes
            # to this row.
            a = air((t - step) / 86400.0)
            s_tau = (temperature - a) / step * tau
            start_lag = lag - a + s_tau
            lagged_mean = 0.5 * (a + temperature) - s_tau + start_lag * tau / step * (1.0 - math.exp(-step / tau))
            lag = temperature - s_tau + start_lag * math.exp(-step / tau)
            pressure += -0.002 * (pressure - 1013.0) + 0.4 * rng.gauss(0, 1)
            humidity = 50.0 + 10.0 * math.sin(2 * math.pi * day / 11.0)
            # The rate over the 10 minutes to this row.
            rate = (0.5 + 0.01 * (day - 30.0) - 0.3 * (lagged_mean - 18.0) - 0.012 * (pressure - 1013.0)
                    - 0.002 * (humidity - 50.0) + tidal[i] + (0.3 if day >= 20.0 else 0.0))
            rate += 0.02 * math.sqrt(3600.0 / step) * rng.gauss(0, 1)
            if i > 0:
                x += rate / 86400.0 * step
            stamp = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime(start + t))
            f.write(f"{stamp},{x + 1e-4 * rng.gauss(0, 1):.6f},{temperature:.2f},{pressure:.1f},{humidity:.1f}\n")
    with open(events_path, "w") as f:
        f.write("time\n2026-01-21T00:00:00Z\n")


def photogate(path):
    """Six hours of a free pendulum timed by a photogate, as an Arduino
    timer prints it: each half swing's period and the time its 2 mm flag,
    1 m below the pivot, blocks the beam (µs). A seconds pendulum
    (simple-equivalent length 0.99362 m) impulsed every 30 s, as a
    Synchronome is by its 15-tooth count wheel (one tooth a double swing):
    between impulses the amplitude decays from 1.5° with Q = 8,000. The
    clock gains 1.2 s/day; the count wheel's eccentricity lengthens the
    beat by up to 15 µs once a turn; alternate beats differ by 200 µs (the
    gate sits off the centre); the timer's clock ticks in 4 µs. The pulse
    is the exact motion's time within the flag's angle, integrated here
    by Simpson's rule (independent of the library's elliptic integrals)."""
    rng = random.Random(29)
    g, length, radius, flag = 9.80665, 0.99362, 1.0, 0.002
    omega = math.sqrt(g / length)
    alpha = 2 * math.asin(flag / (4 * radius))   # half the flag's angle
    def pulse(a):
        # Time within +-alpha: 2 * integral over 0..alpha of
        # d(theta) / (omega sqrt(2 (cos theta - cos a))).
        n = 200
        h = alpha / n
        def f(th):
            return 1.0 / (omega * math.sqrt(2 * (math.cos(th) - math.cos(a))))
        total = f(0) + f(alpha) + sum((4 if k % 2 else 2) * f(k * h) for k in range(1, n))
        return 2 * total * h / 3
    q, a0 = 8000.0, math.radians(1.5)
    t = 0.0
    with open(path, "w") as f:
        f.write("# photogate timer: one line per half swing\ntime_s,half_period_us,pulse_width_us\n")
        for k in range(6 * 3600):
            a = a0 * math.exp(-(k % 30) * math.pi / (2 * q))
            half = (1.0 / (1 + 1.2 / 86400) * (1 + a * a / 16) + 15e-6 * math.sin(2 * math.pi * k / 30)
                    + (100e-6 if k % 2 else -100e-6))
            t += half
            tick = lambda x: 4e-6 * round(x / 4e-6 + rng.uniform(-0.5, 0.5))
            f.write(f"{tick(t):.6f},{tick(half) * 1e6:.0f},{tick(pulse(a)) * 1e6:.0f}\n")


def ticc(path):
    """Ten minutes of a TAPR TICC counter's log in its timestamp mode, as a
    serial terminal captures it: the firmware's banner (`#` lines), then
    one timestamp a line, to the picosecond, with its channel. On chA a
    seconds pendulum's photogate, gaining 2.0 s/day, its ticks 1.5 ms
    from its tocks (a beat error), 20 us of jitter; on chB a GPS
    receiver's pulse per second (5 ns of jitter), 0.3 s after each whole
    second. Its own generator, so the files above stay as they were."""
    own = random.Random(20261129)
    period = 1.0 / (1 + 2.0 / 86400)  # a beat, s
    events = [(5.0 + k * period + (7.5e-4 if k % 2 else -7.5e-4) + own.gauss(0, 20e-6), "chA")
              for k in range(600)]
    events += [(s + 0.3 + own.gauss(0, 5e-9), "chB") for s in range(6, 606)]
    with open(path, "w") as f:
        f.write("# \n# TAPR TICC Timestamping Counter\n# \n#####################\n"
                "# TICC Configuration: \n# Measurement Mode: Timestamp\n#####################\n")
        for t, channel in sorted(events):
            f.write(f"{t:.12f} {channel}\n")


rundown("examples/rundown.csv")
video("examples/video.csv")
beats("examples/beats.csv")
tracker("examples/tracker.txt")
semicolon("examples/rundown-semicolon.csv")
spring("examples/spring.csv")
offsets("examples/offsets.csv")
frequency("examples/frequency.txt")
clock_log("examples/clock-log.csv", "examples/clock-events.csv")
photogate("examples/photogate.csv")
ticc("examples/ticc.txt")
print("wrote examples/ticc.txt, examples/clock-log.csv, examples/photogate.csv, examples/clock-events.csv,  examples/offsets.csv, examples/frequency.txt,  examples/rundown.csv, examples/video.csv, examples/beats.csv, "
      "examples/tracker.txt, examples/rundown-semicolon.csv, examples/spring.csv")
