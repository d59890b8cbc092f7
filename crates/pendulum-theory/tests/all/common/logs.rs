//! A generator of clock logs that varies what real logs vary (issue 44):
//! the span (a week to a year), the reading interval (3 s from a logger to
//! a reading a day by hand, the hand's readings a little early or late),
//! a drift of the rate or none, a room whose temperature swings daily and
//! wanders with the weather, a clock that follows it late or at once (lags
//! of 0 included), a barometric error or none, white and random-walk
//! frequency noise, and the reading's own noise. The clock's offset is
//! integrated on a fine grid (a minute or the reading interval, whichever
//! is shorter) independently of the library: the temperature lag is the
//! exact first-order response to the piecewise-linear air temperature,
//! the noises are added as increments, and the truth of the mean rate is
//! the trapezoid mean of the rate without its white noise.
#![allow(dead_code)]

use super::records::Rng;

const DAY: f64 = 86_400.0;

/// What a log is made of.
#[derive(Clone, Debug)]
pub struct LogSpec {
    pub days: f64,
    /// The reading interval, s.
    pub step_s: f64,
    /// Readings early or late by up to this fraction of the interval.
    pub jitter: f64,
    /// The rate at the log's middle and mean weather, s/day.
    pub rate: f64,
    /// s/day a day.
    pub drift: f64,
    /// s/day per °C of the lagged temperature.
    pub temperature_coefficient: f64,
    /// The daily swing's amplitude, °C.
    pub swing_c: f64,
    /// The weather's standard deviation, °C (an AR(1) of two days).
    pub weather_c: f64,
    /// The clock's thermal time constant, s (0: it follows at once).
    pub lag_s: f64,
    /// s/day per hPa, or no pressure column.
    pub pressure_coefficient: Option<f64>,
    /// White frequency noise: the rate's deviation over an hour, s/day.
    pub white_fm: f64,
    /// Random-walk frequency noise: the rate's wander in a day, s/day.
    pub random_walk: f64,
    /// The reading's noise (white phase), s.
    pub reading_noise_s: f64,
    /// The thermometer's noise, °C.
    pub thermometer_noise_c: f64,
    /// Log rates (s/day over the interval before each reading) rather
    /// than offsets.
    pub rates: bool,
    /// The full body tide at the Black Forest Observatory from
    /// [`EPOCH`] (the library's tide, checked against ETERNA on its
    /// own).
    pub tide: bool,
}

/// The Black Forest Observatory.
pub const BFO: pendulum_theory::tide::Station = pendulum_theory::tide::Station {
    latitude_deg: 48.3301,
    longitude_deg: 8.3296,
    height_m: 589.0,
};
/// 2026-01-01T00:00:00Z.
pub const EPOCH: f64 = 1_767_225_600.0;

/// The tide's pendulum rate (s/day) every 10 minutes from [`EPOCH`],
/// linear between (0.1% of the tide at most).
fn tide_rates(days: f64) -> Vec<f64> {
    use pendulum_theory::tide::{gravity_change, rate_s_per_day};
    let knots: Vec<f64> = (0..=((days + 1.0) * 144.0) as usize)
        .map(|k| EPOCH + 600.0 * k as f64)
        .collect();
    let g = pendulum_theory::gravity::normal_gravity(BFO.latitude_deg, BFO.height_m).unwrap();
    gravity_change(BFO, &knots)
        .unwrap()
        .into_iter()
        .map(|dg| rate_s_per_day(dg, g))
        .collect()
}

impl Default for LogSpec {
    fn default() -> Self {
        LogSpec {
            days: 20.0,
            step_s: 600.0,
            jitter: 0.0,
            rate: 0.5,
            drift: 0.0,
            temperature_coefficient: -0.2,
            swing_c: 1.5,
            weather_c: 0.0,
            lag_s: 0.0,
            pressure_coefficient: None,
            white_fm: 0.05,
            random_walk: 0.0,
            reading_noise_s: 0.0,
            thermometer_noise_c: 0.0,
            rates: false,
            tide: false,
        }
    }
}

/// A generated log and its truth.
#[derive(Clone, Debug, Default)]
pub struct Log {
    pub time_s: Vec<f64>,
    /// Offsets (s) or rates (s/day).
    pub values: Vec<f64>,
    pub temperature_c: Vec<f64>,
    pub pressure_hpa: Vec<f64>,
    /// The mean rate over the log, without its white noise, s/day.
    pub mean_rate: f64,
    /// The true rate (without white noise) at each reading, s/day.
    pub true_rate: Vec<f64>,
    /// The lagged temperature's mean over the interval before each
    /// reading, °C.
    pub lagged_mean: Vec<f64>,
}

/// The log `spec` makes with `seed`.
pub fn generate(spec: &LogSpec, seed: u64) -> Log {
    let mut rng = Rng(seed.wrapping_mul(0x2545_F491_4F6C_DD1D) ^ 0x5DEE_CE66);
    let span = spec.days * DAY;
    let substeps = (spec.step_s / 60.0).ceil().max(1.0);
    let dt = spec.step_s / substeps;
    let fine = (span / dt).round() as usize;
    // The readings' fine-grid indices, in order.
    let mut reading = Vec::new();
    let per = substeps as usize;
    let mut k = 0usize;
    loop {
        let jitter = if spec.jitter > 0.0 && k > 0 {
            ((rng.uniform() * 2.0 - 1.0) * spec.jitter * per as f64).round() as i64
        } else {
            0
        };
        let i = (k * per) as i64 + jitter;
        if i as usize > fine {
            break;
        }
        if reading.last().is_none_or(|&l: &usize| (i as usize) > l) {
            reading.push(i as usize);
        }
        k += 1;
    }
    // Weather: AR(1) knots every hour, linear between.
    let hours = (span / 3600.0).ceil() as usize + 2;
    let ar = |rng: &mut Rng, tau_h: f64, sd: f64| -> Vec<f64> {
        let a = (-1.0 / tau_h).exp();
        let mut v = sd * rng.gaussian();
        (0..hours)
            .map(|_| {
                v = a * v + sd * (1.0 - a * a).sqrt() * rng.gaussian();
                v
            })
            .collect()
    };
    let weather = ar(&mut rng, 48.0, spec.weather_c);
    let baro = ar(&mut rng, 72.0, 8.0);
    let phase = rng.uniform() * std::f64::consts::TAU;
    let season = rng.uniform() * std::f64::consts::TAU;
    let hourly = |series: &[f64], t: f64| {
        let k = t / 3600.0;
        let i = k.floor() as usize;
        let w = k - i as f64;
        series[i] * (1.0 - w) + series[i + 1] * w
    };
    let air = |t: f64| {
        20.0 + spec.swing_c * (std::f64::consts::TAU * t / DAY + phase).sin()
            + 2.0 * (std::f64::consts::TAU * t / (365.25 * DAY) + season).sin()
            + hourly(&weather, t)
    };
    let pressure = |t: f64| 1013.0 + hourly(&baro, t);
    let tides = if spec.tide {
        tide_rates(spec.days)
    } else {
        Vec::new()
    };
    let tide = |t: f64| {
        if tides.is_empty() {
            return 0.0;
        }
        let k = t / 600.0;
        let i = k.floor() as usize;
        let w = k - i as f64;
        tides[i] * (1.0 - w) + tides[i + 1] * w
    };
    let white = spec.white_fm / DAY * (3600.0 * dt).sqrt();
    let walk = spec.random_walk * (dt / DAY).sqrt();
    let mid = span / 2.0;
    let deterministic = |t: f64, lagged: f64, p: f64| {
        spec.rate
            + spec.drift * (t - mid) / DAY
            + spec.temperature_coefficient * (lagged - 20.0)
            + spec.pressure_coefficient.map_or(0.0, |c| c * (p - 1013.0))
            + tide(t)
    };
    let mut log = Log::default();
    let (mut x, mut rw) = (0.0, 0.0);
    let mut lagged = air(0.0);
    let mut rate_before = deterministic(0.0, lagged, pressure(0.0));
    let mut next = 0;
    let (mut area, mut area_start, mut last_x) = (0.0, None, 0.0);
    let mut last_reading_t = 0.0;
    let mut lag_area = 0.0;
    for i in 0..=fine {
        let t = i as f64 * dt;
        if i > 0 {
            // The exact first-order lag of the air, linear over the step.
            let (a0, a1) = (air(t - dt), air(t));
            let lag_before = lagged;
            lagged = if spec.lag_s > 0.0 {
                let s = (a1 - a0) / dt;
                let e = (-dt / spec.lag_s).exp();
                a1 - s * spec.lag_s + (lagged - a0 + s * spec.lag_s) * e
            } else {
                a1
            };
            lag_area += 0.5 * (lag_before + lagged) * dt;
            let before_walk = rw;
            rw += walk * rng.gaussian();
            let rate_now = deterministic(t, lagged, pressure(t));
            let step_rate = 0.5 * (rate_before + rate_now) + 0.5 * (before_walk + rw);
            if area_start.is_some() && next < reading.len() {
                area += step_rate * dt;
            }
            x += step_rate / DAY * dt + white * rng.gaussian();
            rate_before = rate_now;
        }
        if next < reading.len() && reading[next] == i {
            area_start.get_or_insert(t);
            log.time_s.push(t);
            log.temperature_c
                .push(air(t) + spec.thermometer_noise_c * rng.gaussian());
            log.pressure_hpa.push(pressure(t));
            log.true_rate.push(rate_before + rw);
            log.lagged_mean.push(if t > last_reading_t {
                lag_area / (t - last_reading_t)
            } else {
                lagged
            });
            lag_area = 0.0;
            let read = x + spec.reading_noise_s * rng.gaussian();
            if spec.rates {
                if next > 0 {
                    log.values
                        .push((read - last_x) / (t - last_reading_t) * DAY);
                } else {
                    log.values.push(f64::NAN);
                }
            } else {
                log.values.push(read);
            }
            last_x = read;
            last_reading_t = t;
            next += 1;
        }
    }
    let first = log.time_s[0];
    let last = *log.time_s.last().unwrap();
    log.mean_rate = area / (last - first);
    if spec.rates {
        // The first reading has no interval before it.
        log.time_s.remove(0);
        log.values.remove(0);
        log.temperature_c.remove(0);
        log.pressure_hpa.remove(0);
        log.true_rate.remove(0);
        log.lagged_mean.remove(0);
    }
    log
}
