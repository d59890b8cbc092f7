#!/usr/bin/env python3
"""Example measurement files for the README's `pendulum fit` commands,
made with fixed seeds so they never change. Run from the repository root:
python3 tools/examples/make_example_data.py  (standard library only)."""
import math
import random

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


rundown("examples/rundown.csv")
video("examples/video.csv")
beats("examples/beats.csv")
tracker("examples/tracker.txt")
semicolon("examples/rundown-semicolon.csv")
spring("examples/spring.csv")
print("wrote examples/rundown.csv, examples/video.csv, examples/beats.csv, "
      "examples/tracker.txt, examples/rundown-semicolon.csv, examples/spring.csv")
