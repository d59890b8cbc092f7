//! A room's daily cycle, for weather read a few times a day.
//!
//! A thermometer read every few hours does not see the day's swing
//! between its readings, and a straight line between two readings six
//! hours apart holds only cos(π/4)/sinc(π/4) = 0.79 of the swing's mean
//! over them: a clock's temperature coefficient read from it comes out
//! 1.27 times too large. When the readings are sparser than half an hour
//! the column is split into its daily cycle, the first two harmonics of
//! the day `h(t) = Σ_{k=1,2} a_k cos kωt + b_k sin kωt`, fitted by least
//! squares beside a slow trend (a linear spline with knots every two
//! days), and the rest, linear between readings. The cycle's means over
//! an interval, and after a first-order lag (its steady response,
//! `1/(1 + ikωτ)` of each harmonic), are exact. The cycle is used only
//! when the readings' times of day let it be told from the trend (the
//! harmonics' part of the normal matrix, the trend projected out, keeps
//! a tenth of its size) and when it is there (an F test at 1%).

use nalgebra::{DMatrix, DVector};
use statrs::distribution::{ContinuousCDF, FisherSnedecor};

const DAY: f64 = 86_400.0;
const OMEGA: f64 = std::f64::consts::TAU / DAY;
/// Readings sparser than this get the cycle, s.
pub(crate) const SPARSE_S: f64 = 1800.0;
const KNOT_S: f64 = 2.0 * DAY;

/// The first two harmonics of the day.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DailyCycle {
    /// `(a_k, b_k)` for k = 1, 2.
    pub coefficients: [(f64, f64); 2],
}

impl DailyCycle {
    /// The cycle at `t` (s of the log's time).
    pub fn at(&self, t: f64) -> f64 {
        self.coefficients
            .iter()
            .enumerate()
            .map(|(k, &(a, b))| {
                let (s, c) = ((k + 1) as f64 * OMEGA * t).sin_cos();
                a * c + b * s
            })
            .sum()
    }

    /// Its mean over `[t0, t1]`, after a first-order lag of `tau` s (its
    /// steady response) when `tau > 0`.
    pub fn mean(&self, t0: f64, t1: f64, tau: f64) -> f64 {
        self.lagged(tau)
            .map(|(w, al, bl)| {
                if t1 <= t0 {
                    let (s, c) = (w * t0).sin_cos();
                    return al * c + bl * s;
                }
                // ∫ (al cos wt + bl sin wt) dt / (t1 − t0).
                let (s1, c1) = (w * t1).sin_cos();
                let (s0, c0) = (w * t0).sin_cos();
                (al * (s1 - s0) - bl * (c1 - c0)) / (w * (t1 - t0))
            })
            .sum()
    }

    /// Each harmonic's angular frequency and its cosine and sine
    /// coefficients after the lag's steady response:
    /// `(a − ib)·e^{iwt}/(1 + iwτ)`.
    fn lagged(&self, tau: f64) -> impl Iterator<Item = (f64, f64, f64)> + '_ {
        self.coefficients
            .iter()
            .enumerate()
            .map(move |(k, &(a, b))| {
                let w = (k + 1) as f64 * OMEGA;
                let d = 1.0 + (w * tau).powi(2);
                (w, (a - b * w * tau) / d, (b + a * w * tau) / d)
            })
    }
}

/// The daily cycle of `values` read at `times`, when the readings are
/// sparse, let it be told from the trend, and show it.
pub(crate) fn daily_cycle(times: &[f64], values: &[f64], spacing: f64) -> Option<DailyCycle> {
    if spacing <= SPARSE_S {
        return None;
    }
    let points: Vec<(f64, f64)> = times
        .iter()
        .zip(values)
        .filter(|(_, v)| v.is_finite())
        .map(|(&t, &v)| (t, v))
        .collect();
    let n = points.len();
    let (t0, t1) = (points.first()?.0, points.last()?.0);
    let knots = (((t1 - t0) / KNOT_S).ceil() as usize).max(1) + 1;
    let step = (t1 - t0).max(1.0) / (knots - 1) as f64;
    let p = knots + 4;
    if n < p + 8 {
        return None;
    }
    // Columns: the hat functions of the trend, then the harmonics.
    let row = |t: f64| -> Vec<f64> {
        let mut r = vec![0.0; p];
        let x = ((t - t0) / step).clamp(0.0, (knots - 1) as f64);
        let k = (x.floor() as usize).min(knots - 2);
        let f = x - k as f64;
        r[k] = 1.0 - f;
        r[k + 1] = f;
        for h in 0..2 {
            let (s, c) = ((h + 1) as f64 * OMEGA * t).sin_cos();
            r[knots + 2 * h] = c;
            r[knots + 2 * h + 1] = s;
        }
        r
    };
    let mut a = DMatrix::<f64>::zeros(p, p);
    let mut rhs = DVector::<f64>::zeros(p);
    let mut yy = 0.0;
    for &(t, v) in &points {
        let r = row(t);
        for i in 0..p {
            if r[i] == 0.0 {
                continue;
            }
            rhs[i] += r[i] * v;
            for j in 0..p {
                a[(i, j)] += r[i] * r[j];
            }
        }
        yy += v * v;
    }
    // The harmonics' block with the trend projected out (its Schur
    // complement) against its size without: how well the times of day
    // tell the cycle from the trend.
    let trend = a.view((0, 0), (knots, knots)).into_owned();
    let cross = a.view((0, knots), (knots, 4)).into_owned();
    let own = a.view((knots, knots), (4, 4)).into_owned();
    let trend_inv = trend.clone().pseudo_inverse(1e-12).ok()?;
    let schur = &own - cross.transpose() * &trend_inv * &cross;
    let smallest = schur.symmetric_eigenvalues().min();
    if smallest < 0.1 * n as f64 / 2.0 {
        return None;
    }
    let chol = a.clone().cholesky()?;
    let beta = chol.solve(&rhs);
    let rss_full = (yy - beta.dot(&rhs)).max(0.0);
    let trend_beta = trend.cholesky()?.solve(&rhs.rows(0, knots).into_owned());
    let rss_trend = (yy - trend_beta.dot(&rhs.rows(0, knots))).max(0.0);
    let dof = (n - p) as f64;
    if rss_full <= 0.0 {
        return None;
    }
    let f = ((rss_trend - rss_full) / 4.0) / (rss_full / dof);
    let p_value = FisherSnedecor::new(4.0, dof).ok()?.sf(f);
    (p_value < 0.01).then(|| DailyCycle {
        coefficients: [
            (beta[knots], beta[knots + 1]),
            (beta[knots + 2], beta[knots + 3]),
        ],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Readings every 6 hours (a little early or late) of a room that
    /// swings 2 °C a day and wanders slowly: the cycle is found to 1%,
    /// and its lagged mean agrees with the lag integrated step by step.
    #[test]
    fn a_swing_read_four_times_a_day() {
        let times: Vec<f64> = (0..120)
            .map(|i| i as f64 * 21_600.0 + 1800.0 * ((i * 7 % 5) as f64 - 2.0))
            .collect();
        let truth = DailyCycle {
            coefficients: [(1.2, -1.6), (0.3, 0.1)],
        };
        let values: Vec<f64> = times
            .iter()
            .map(|&t| 20.0 + 0.5 * (t / 2e6).sin() + truth.at(t))
            .collect();
        let found = daily_cycle(&times, &values, 21_600.0).unwrap();
        for k in 0..2 {
            assert!((found.coefficients[k].0 - truth.coefficients[k].0).abs() < 0.02);
            assert!((found.coefficients[k].1 - truth.coefficients[k].1).abs() < 0.02);
        }
        // The lagged mean over an interval against Euler steps of the lag
        // from far before (its steady state).
        let tau = 7200.0;
        let (t0, t1) = (100_000.0, 121_600.0);
        let h = 1.0;
        let mut level = 0.0;
        let mut t = t0 - 20.0 * tau;
        let mut area = 0.0;
        while t < t1 {
            let k1 = (truth.at(t) - level) / tau;
            let k2 = (truth.at(t + h) - (level + h * k1)) / tau;
            let next = level + 0.5 * h * (k1 + k2);
            if t >= t0 {
                area += 0.5 * h * (level + next);
            }
            level = next;
            t += h;
        }
        let expected = area / (t1 - t0);
        assert!((truth.mean(t0, t1, tau) - expected).abs() < 1e-6);
        // Readings at one time of day cannot tell the cycle.
        let daily: Vec<f64> = (0..60).map(|i| i as f64 * DAY).collect();
        let v: Vec<f64> = daily
            .iter()
            .map(|&t| truth.at(t) + (t / 1e6).sin())
            .collect();
        assert_eq!(daily_cycle(&daily, &v, DAY), None);
    }
}

#[cfg(test)]
mod interval_tests {
    use super::*;
    use crate::clock_log::series::{interval_means, lagged_interval_means};

    /// The interval means of a swing read every 5.9 h, through the cycle,
    /// against the swing's exact means.
    #[test]
    fn interval_means_through_the_cycle() {
        let times: Vec<f64> = (0..400).map(|i| i as f64 * 21_253.0).collect();
        let truth = DailyCycle {
            coefficients: [(1.0, 0.5), (0.0, 0.0)],
        };
        let slow = |t: f64| 0.8 * (t / 9e5).sin();
        let values: Vec<f64> = times
            .iter()
            .map(|&t| 20.0 + slow(t) + truth.at(t))
            .collect();
        let cycle = daily_cycle(&times, &values, 21_253.0);
        println!("{cycle:?}");
        let means = interval_means(&times, &values, cycle.as_ref());
        let plain = interval_means(&times, &values, None);
        let (mut worst, mut worst_plain) = (0.0f64, 0.0f64);
        for j in 1..times.len() {
            let exact = 20.0
                + truth.mean(times[j - 1], times[j], 0.0)
                + 0.5 * (slow(times[j - 1]) + slow(times[j]));
            worst = worst.max((means[j] - exact).abs());
            worst_plain = worst_plain.max((plain[j] - exact).abs());
        }
        println!("worst {worst} plain {worst_plain}");
        assert!(worst < 0.05, "{worst}");
        let lagged = lagged_interval_means(&times, &values, 0.0, cycle.as_ref());
        assert_eq!(lagged, means);
    }
}
