//! The clock-log analysis against synthetic logs of known truth: a year
//! of offsets every 3 s (10.5 million samples) at the Black Forest
//! Observatory, the rate made of a constant, a drift, a compensator that
//! follows the air's temperature (daily and seasonal swings plus
//! weather) 4 hours late, a barometric error on weather-like pressure, the
//! full body tide, white and random-walk frequency noise and white phase
//! noise. Over 100 seeds every injected coefficient must lie within 2 of
//! its standard errors of its truth in at least 90 (issue 26).

use pendulum_theory::clock_log::{analyse, LogInput, LogKind, LogResult};
use pendulum_theory::tide::{gravity_change, rate_s_per_day, Station};

const STEP: f64 = 3.0;
const DAY: f64 = 86_400.0;
const BFO: Station = Station {
    latitude_deg: 48.3301,
    longitude_deg: 8.3296,
    height_m: 589.0,
};
/// 2026-01-01T00:00:00Z.
const EPOCH: f64 = 1_767_225_600.0;

/// The injected truth.
const RATE: f64 = 0.3;
const DRIFT: f64 = 0.002;
const TEMPERATURE: f64 = -0.25;
const LAG_S: f64 = 4.0 * 3600.0;
const PRESSURE: f64 = -0.01;

/// A seeded generator: xorshift64* and Box–Muller.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let v = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        ((v >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// Two independent standard normals (Box–Muller).
    fn gauss_pair(&mut self) -> (f64, f64) {
        let (u, v) = (self.uniform(), self.uniform());
        let r = (-2.0 * u.ln()).sqrt();
        let (s, c) = (std::f64::consts::TAU * v).sin_cos();
        (r * c, r * s)
    }

    fn gauss(&mut self) -> f64 {
        self.gauss_pair().0
    }
}

/// The tide's pendulum rate (s/day) every 10 minutes over the year and a
/// bit, linearly interpolated (0.1% of the tide at most).
struct Tide(Vec<f64>);

impl Tide {
    fn new(days: f64) -> Tide {
        let knots: Vec<f64> = (0..=((days + 1.0) * 144.0) as usize)
            .map(|k| EPOCH + 600.0 * k as f64)
            .collect();
        let g = pendulum_theory::gravity::normal_gravity(BFO.latitude_deg, BFO.height_m).unwrap();
        Tide(
            gravity_change(BFO, &knots)
                .unwrap()
                .into_iter()
                .map(|dg| rate_s_per_day(dg, g))
                .collect(),
        )
    }

    fn at(&self, t: f64) -> f64 {
        let k = t / 600.0;
        let i = k.floor() as usize;
        let w = k - i as f64;
        self.0[i] * (1.0 - w) + self.0[i + 1] * w
    }
}

/// A log of `days` days with `seed`: times, offsets, temperature,
/// pressure, written into `input`'s vectors (their memory reused from
/// seed to seed: a year is 336 MB of them).
fn log(seed: u64, days: f64, tide: &Tide, input: &mut LogInput) {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let n = (days * DAY / STEP) as usize;
    let mut time = std::mem::take(&mut input.time_s);
    let mut offset = std::mem::take(&mut input.values);
    let mut temperature = input.temperature_c.take().unwrap_or_default();
    let mut pressure = input.pressure_hpa.take().unwrap_or_default();
    for v in [&mut time, &mut offset, &mut temperature, &mut pressure] {
        v.clear();
        v.reserve(n);
    }
    // Weather: AR(1) processes stepped every hour and interpolated.
    let hours = (days * 24.0) as usize + 2;
    let mut weather = |tau_h: f64, sd: f64| -> Vec<f64> {
        let a = (-1.0 / tau_h).exp();
        let mut v = sd * rng.gauss();
        (0..hours)
            .map(|_| {
                v = a * v + sd * (1.0 - a * a).sqrt() * rng.gauss();
                v
            })
            .collect()
    };
    let air = weather(48.0, 0.8);
    let baro = weather(72.0, 8.0);
    let hourly = |series: &[f64], t: f64| {
        let k = t / 3600.0;
        let i = k.floor() as usize;
        let w = k - i as f64;
        series[i] * (1.0 - w) + series[i + 1] * w
    };
    // The air's temperature: a seasonal and a daily swing and weather,
    // hour by hour, linear between.
    let air_temperature: Vec<f64> = (0..hours)
        .map(|h| {
            let d = h as f64 / 24.0;
            18.0 + 4.0 * (std::f64::consts::TAU * (d - 100.0) / 365.25).sin()
                + 1.5 * (std::f64::consts::TAU * (d - 0.375)).sin()
                + air[h]
        })
        .collect();
    let white = 0.02 * (3600.0 / STEP).sqrt();
    let walk = 0.004 * (STEP / DAY).sqrt();
    let (mut x, mut lag, mut rw) = (0.0, 18.0, 0.0);
    let decay = 1.0 - (-STEP / LAG_S).exp();
    let mut p_before = 0.0;
    for i in 0..n {
        let t = i as f64 * STEP;
        let temp = hourly(&air_temperature, t);
        let p_anomaly = hourly(&baro, t);
        let before = lag;
        lag += decay * (temp - lag);
        if i > 0 {
            // The rate over the step to this sample, at its middle (the
            // weather linear over the step).
            let mid = t - 0.5 * STEP;
            let (g1, g2) = rng.gauss_pair();
            rw += walk * g1;
            let rate = RATE
                + DRIFT * (mid / DAY - days / 2.0)
                + TEMPERATURE * (0.5 * (lag + before) - 18.0)
                + PRESSURE * 0.5 * (p_anomaly + p_before)
                + tide.at(mid)
                + rw
                + white * g2;
            x += rate / DAY * STEP;
        }
        p_before = p_anomaly;
        time.push(t);
        offset.push(x + 20e-6 * rng.gauss());
        temperature.push(temp);
        pressure.push(1013.0 + p_anomaly);
    }
    *input = LogInput {
        time_s: time,
        epoch_unix_s: Some(EPOCH),
        kind: Some(LogKind::Offset),
        values: offset,
        temperature_c: Some(temperature),
        pressure_hpa: Some(pressure),
        station: Some(BFO),
        tides: true,
        skip_stability: true,
        ..LogInput::default()
    };
}

/// (name, estimate, standard error, truth) of each injected coefficient.
fn checks(r: &LogResult) -> Vec<(&'static str, Option<f64>, Option<f64>, f64)> {
    let c = &r.coefficients;
    let e = &r.standard_errors;
    vec![
        (
            "drift",
            r.drift_s_per_day_per_day,
            r.drift_standard_error_s_per_day_per_day,
            DRIFT,
        ),
        (
            "temperature",
            c.temperature_s_per_day_per_c,
            e.temperature_s_per_day_per_c,
            TEMPERATURE,
        ),
        (
            "pressure",
            c.pressure_s_per_day_per_hpa,
            e.pressure_s_per_day_per_hpa,
            PRESSURE,
        ),
        ("tide", c.tide_admittance, e.tide_admittance, 1.0),
    ]
}

#[test]
fn every_coefficient_within_two_standard_errors_in_ninety_of_a_hundred_years() {
    let days = 365.0;
    let tide = Tide::new(days);
    let seeds: Vec<u64> = (1..=100).collect();
    let results: Vec<Vec<(&str, bool, String)>> = std::thread::scope(|scope| {
        let handles: Vec<_> = seeds
            .chunks(50)
            .map(|chunk| {
                let tide = &tide;
                scope.spawn(move || {
                    let mut input = LogInput::default();
                    chunk
                        .iter()
                        .map(|&seed| {
                            log(seed, days, tide, &mut input);
                            let r = analyse(&input).unwrap();
                            checks(&r)
                                .into_iter()
                                .map(|(name, v, se, truth)| match (v, se) {
                                    (Some(v), Some(se)) => (
                                        name,
                                        (v - truth).abs() <= 2.0 * se,
                                        format!("seed {seed}: {v} ± {se}"),
                                    ),
                                    _ => (name, false, format!("seed {seed}: term left out")),
                                })
                                .collect()
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });
    for name in ["drift", "temperature", "pressure", "tide"] {
        let rows: Vec<&(&str, bool, String)> =
            results.iter().flatten().filter(|r| r.0 == name).collect();
        let covered = rows.iter().filter(|r| r.1).count();
        let misses: Vec<&str> = rows.iter().filter(|r| !r.1).map(|r| r.2.as_str()).collect();
        println!("{name}: {covered} of {} within 2 SE", rows.len());
        assert!(
            covered >= 90,
            "{name}: {covered} of 100 within 2 standard errors; misses {misses:?}"
        );
    }
}

/// The pulse a flag makes, by direct quadrature of the exact motion:
/// `Δt = ∫_{−α}^{α} dθ / (ω_n sqrt(2 (cos θ − cos A)))`, composite
/// five-point Gauss–Legendre over 4,000 panels; independent of the
/// elliptic-function route the library takes.
fn pulse_by_quadrature(amplitude: f64, flag: f64, radius: f64, length: f64, g: f64) -> f64 {
    let alpha = 2.0 * (flag / (4.0 * radius)).asin();
    let omega = (g / length).sqrt();
    let nodes = [
        (0.0, 128.0 / 225.0),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let panels = 4000;
    let h = 2.0 * alpha / panels as f64;
    let mut sum = 0.0;
    for p in 0..panels {
        let centre = -alpha + (p as f64 + 0.5) * h;
        for (x, w) in nodes {
            let theta = centre + 0.5 * h * x;
            sum += 0.5 * h * w / (omega * (2.0 * (theta.cos() - amplitude.cos())).sqrt());
        }
    }
    sum
}

/// The amplitude from a pulse's width, against the exact motion
/// integrated independently: 1e-9 relative from 1° to 60°, for a
/// seconds pendulum's bob flag and a gate near the pivot.
#[test]
fn pulse_width_gives_the_amplitude_of_the_exact_motion() {
    use pendulum_theory::clock_log::amplitude_from_pulse;
    let g = 9.81;
    for (flag, radius, length) in [
        (0.01_f64, 1.0_f64, 0.994),
        (0.005, 0.3, 0.994),
        (0.02, 0.25, 0.2485),
    ] {
        for degrees in [1.0_f64, 2.0, 3.0, 5.0, 10.0, 30.0, 60.0] {
            let a = degrees.to_radians();
            let alpha = 2.0 * (flag / (4.0 * radius)).asin();
            if alpha > 0.8 * a {
                continue;
            }
            let pulse = pulse_by_quadrature(a, flag, radius, length, g);
            let got = amplitude_from_pulse(pulse, flag, radius, length, g).unwrap();
            assert!(
                (got / a - 1.0).abs() < 1e-9,
                "{degrees}° (flag {flag} m at {radius} m): got {}°",
                got.to_degrees()
            );
        }
    }
    // To first order the speed at the bottom: w/Δt = 2 ω r sin(A/2).
    let (flag, radius, length) = (0.001, 1.0, 1.0);
    let a = 3f64.to_radians();
    let v = 2.0 * (g / length).sqrt() * radius * (a / 2.0).sin();
    let got = amplitude_from_pulse(flag / v, flag, radius, length, g).unwrap();
    assert!((got / a - 1.0).abs() < 1e-3);
    // A pulse no swing that clears the flag makes is refused.
    assert!(amplitude_from_pulse(10.0, 0.01, 1.0, 1.0, g).is_err());
    assert!(amplitude_from_pulse(-1.0, 0.01, 1.0, 1.0, g).is_err());
}

/// A photogate's flag width or gate radius without its pulse widths was
/// ignored (a new user's find): refused by name.
#[test]
fn a_photogates_sizes_without_its_pulses_are_refused() {
    let time: Vec<f64> = (0..200).map(|i| i as f64 * 3600.0).collect();
    let values: Vec<f64> = time.iter().map(|t| 1e-6 * t).collect();
    for (flag, radius, field) in [
        (Some(0.01), None, "flag_width"),
        (None, Some(1.0), "gate_radius"),
    ] {
        let e = analyse(&LogInput {
            time_s: time.clone(),
            kind: Some(LogKind::Offset),
            values: values.clone(),
            flag_width_m: flag,
            gate_radius_m: radius,
            ..LogInput::default()
        })
        .unwrap_err();
        assert_eq!(e.field_name(), Some(field), "{e}");
        assert!(e.to_string().contains("pulse_width"), "{e}");
    }
}
