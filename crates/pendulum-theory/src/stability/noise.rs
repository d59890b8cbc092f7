//! Which power-law noise dominates at an averaging time, by the lag-1
//! autocorrelation method of W. J. Riley and C. A. Greenhall, "Power law
//! noise identification using the lag 1 autocorrelation", 18th European
//! Frequency and Time Forum (2004), as SP 1065 section 5.6 describes it.
//!
//! The series at the averaging time (phase decimated to every `m`-th
//! point, or frequency averaged in groups of `m`) is detrended, then
//! differenced until its lag-1 autocorrelation `r₁` says it is stationary
//! (`δ = r₁/(1 + r₁) < 0.25`); then `α = −2(δ + d)` (+2 for phase data)
//! after `d` differences, rounded to the nearest power law. It needs 30
//! points or more. On seeded power-law series of 16,384 points (test
//! `stability.rs`) it names the noise right at over 90% of the octave
//! averaging times that leave 30 points, over white phase, white, flicker
//! and random-walk frequency noise together; flicker frequency alone, the
//! hardest, at 75%, and flicker phase, which decimation folds into white
//! phase at long τ, at under half.

use serde::Serialize;

/// Fewer points than this at an averaging time and the autocorrelation
/// cannot tell noises apart (Riley & Greenhall's limit).
pub const MIN_POINTS: usize = 30;

/// A power-law noise, `S_y(f) ∝ f^α`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Noise {
    /// `α = 2`: white phase noise (a timing jitter, a photogate's scatter).
    WhitePhase,
    /// `α = 1`: flicker phase noise.
    FlickerPhase,
    /// `α = 0`: white frequency noise (random impulses to the pendulum).
    WhiteFrequency,
    /// `α = −1`: flicker frequency noise (the floor of a good clock).
    FlickerFrequency,
    /// `α = −2`: random-walk frequency noise (temperature, pressure,
    /// ageing wandering the rate).
    RandomWalkFrequency,
    /// `α = −3`: flicker walk of frequency.
    FlickerWalkFrequency,
    /// `α = −4`: random run of frequency.
    RandomRunFrequency,
}

impl Noise {
    /// The noise of exponent `alpha` (clamped to 2 ..= −4).
    pub fn from_alpha(alpha: i32) -> Noise {
        match alpha {
            i32::MIN..=-4 => Noise::RandomRunFrequency,
            -3 => Noise::FlickerWalkFrequency,
            -2 => Noise::RandomWalkFrequency,
            -1 => Noise::FlickerFrequency,
            0 => Noise::WhiteFrequency,
            1 => Noise::FlickerPhase,
            _ => Noise::WhitePhase,
        }
    }

    /// Its exponent `α` of `S_y(f) ∝ f^α`.
    pub fn alpha(self) -> i32 {
        match self {
            Noise::WhitePhase => 2,
            Noise::FlickerPhase => 1,
            Noise::WhiteFrequency => 0,
            Noise::FlickerFrequency => -1,
            Noise::RandomWalkFrequency => -2,
            Noise::FlickerWalkFrequency => -3,
            Noise::RandomRunFrequency => -4,
        }
    }

    /// Its name in words.
    pub fn name(self) -> &'static str {
        match self {
            Noise::WhitePhase => "white phase noise",
            Noise::FlickerPhase => "flicker phase noise",
            Noise::WhiteFrequency => "white frequency noise",
            Noise::FlickerFrequency => "flicker frequency noise",
            Noise::RandomWalkFrequency => "random-walk frequency noise",
            Noise::FlickerWalkFrequency => "flicker-walk frequency noise",
            Noise::RandomRunFrequency => "random-run frequency noise",
        }
    }

    /// What averaging does against it, as the Allan deviation's slope
    /// says (SP 1065 table 3; the modified deviation tells the phase
    /// noises apart).
    pub fn meaning(self) -> &'static str {
        match self {
            Noise::WhitePhase => {
                "averaging helps as 1/τ (the measurement's scatter, not the clock)"
            }
            Noise::FlickerPhase => "averaging helps almost as 1/τ",
            Noise::WhiteFrequency => "averaging helps as 1/√τ",
            Noise::FlickerFrequency => "averaging no longer helps: the clock's floor",
            Noise::RandomWalkFrequency => "the rate wanders: longer averages get worse as √τ",
            Noise::FlickerWalkFrequency | Noise::RandomRunFrequency => {
                "the rate wanders ever faster: longer averages get worse as τ"
            }
        }
    }
}

/// The noise at averaging factor `m` of `data` (phase, s, when `phase`;
/// else fractional frequency), differencing at most `d_max` times (2 for
/// the Allan family, 3 for Hadamard), from the one series that starts at
/// the first sample: Riley & Greenhall's method as published (and as
/// allantools' `autocorr_noise_id` does it). `None` with fewer than
/// [`MIN_POINTS`] finite points at that averaging time. Gaps (NaN) are
/// left out of the fit and of the autocorrelation's pairs.
pub fn identify(data: &[f64], m: usize, phase: bool, d_max: u32) -> Option<Noise> {
    decide(&deltas(data, m, 0, phase, d_max)?, phase)
}

/// As [`identify`], with the autocorrelation's `δ` at each difference
/// averaged over up to eight of the `m` series an averaging time offers
/// (starting at offsets `0, m/8, 2m/8, …`): at long τ, where one series
/// has few points, the average scatters less. Over 20 seeds of 16,384
/// points it names flicker frequency noise right at 150 of 200 octave τ
/// (one series: 143), random-walk frequency at 190 (186), white
/// frequency at 194 (193), white phase at all 200. This is what
/// [`stability`](super::stability()) uses.
pub fn identify_pooled(data: &[f64], m: usize, phase: bool, d_max: u32) -> Option<Noise> {
    let m = m.max(1);
    let offsets = m.min(8);
    let mut sum = vec![0.0; d_max as usize + 1];
    for k in 0..offsets {
        let each = deltas(data, m, k * m / offsets, phase, d_max)?;
        for (s, d) in sum.iter_mut().zip(each) {
            *s += d;
        }
    }
    decide(
        &sum.iter().map(|s| s / offsets as f64).collect::<Vec<_>>(),
        phase,
    )
}

/// The rule: the first difference order `d` whose `δ` is below 0.25 (or
/// the last), and `α = −2(δ + d)` (+2 for phase), rounded.
fn decide(deltas: &[f64], phase: bool) -> Option<Noise> {
    let d = deltas
        .iter()
        .position(|&delta| delta < 0.25)
        .unwrap_or(deltas.len() - 1);
    let offset = if phase { 2 } else { 0 };
    let alpha = -(2.0 * deltas[d]).round() as i32 - 2 * d as i32 + offset;
    Some(Noise::from_alpha(alpha))
}

/// `δ = r₁/(1 + r₁)` of the series at averaging factor `m` starting at
/// sample `start`, detrended, then after each of `d_max` differences.
fn deltas(data: &[f64], m: usize, start: usize, phase: bool, d_max: u32) -> Option<Vec<f64>> {
    let m = m.max(1);
    let data = data.get(start..)?;
    let mut z: Vec<f64> = if phase {
        data.iter().step_by(m).copied().collect()
    } else {
        data.chunks_exact(m)
            .map(|c| c.iter().sum::<f64>() / m as f64)
            .collect()
    };
    if z.iter().filter(|v| v.is_finite()).count() < MIN_POINTS {
        return None;
    }
    detrend(&mut z, if phase { 2 } else { 1 });
    let mut out = Vec::with_capacity(d_max as usize + 1);
    for d in 0..=d_max {
        if d > 0 {
            z = z.windows(2).map(|w| w[1] - w[0]).collect();
        }
        let r1 = lag1(&z)?;
        out.push(r1 / (1.0 + r1));
    }
    Some(out)
}

/// The lag-1 autocorrelation about the mean (Riley & Greenhall eq. 2),
/// over the finite values and finite pairs.
fn lag1(z: &[f64]) -> Option<f64> {
    let finite = z.iter().filter(|v| v.is_finite());
    let n = finite.clone().count();
    let mean = finite.sum::<f64>() / n as f64;
    let var: f64 = z
        .iter()
        .filter(|v| v.is_finite())
        .map(|v| (v - mean).powi(2))
        .sum();
    let cov: f64 = z
        .windows(2)
        .map(|w| (w[0] - mean) * (w[1] - mean))
        .filter(|p| p.is_finite())
        .sum();
    let r = cov / var;
    r.is_finite().then_some(r)
}

/// Subtracts the least-squares polynomial of `degree` (1 or 2) in the
/// index from the finite values of `z`, in Legendre-like centred powers
/// so that a long series loses no digits.
fn detrend(z: &mut [f64], degree: usize) {
    let n = z.len() as f64;
    let centre = (n - 1.0) / 2.0;
    let scale = centre.max(1.0);
    let basis = |i: usize| {
        let t = (i as f64 - centre) / scale;
        [1.0, t, t * t]
    };
    let k = degree + 1;
    let mut normal = nalgebra::DMatrix::<f64>::zeros(k, k);
    let mut rhs = nalgebra::DVector::<f64>::zeros(k);
    for (i, v) in z.iter().enumerate().filter(|(_, v)| v.is_finite()) {
        let b = basis(i);
        for r in 0..k {
            rhs[r] += b[r] * v;
            for c in 0..k {
                normal[(r, c)] += b[r] * b[c];
            }
        }
    }
    let Some(coef) = normal.lu().solve(&rhs) else {
        return;
    };
    for (i, v) in z.iter_mut().enumerate() {
        let b = basis(i);
        *v -= (0..k).map(|r| coef[r] * b[r]).sum::<f64>();
    }
}
