//! Jumps and glitches of a time-error series, found once for `log` and
//! `stability` alike.
//!
//! A clock compared with a reference shows two accidents that are not
//! the clock's rate: a *jump*, a step of the offset that stays (the
//! reference slipped a whole beat, the clock was set, the logger
//! restarted), and a *glitch*, one sample or a few read wrong and then
//! right again (a missed pulse reads a whole second late once). Either
//! raises the Allan deviation at short τ many times and moves a fitted
//! rate.
//!
//! Method: each interval's phase step `Δx_j` less what the local rate
//! (the median of the rates of the 64 intervals around it, so a rate that
//! wanders is followed) makes over it, `e_j = Δx_j − ρ_j Δt_j`, scaled
//! for white frequency noise (`e_j / sqrt(Δt_j)`), against a robust
//! scale: 1.4826 times the median absolute deviation of those. An
//! interval beyond [`SIGMAS`] of it is out of line. Two out-of-line
//! intervals within [`GLITCH_SAMPLES`] samples of each other whose steps
//! cancel (their sum within a fifth of the first, or within the scale's
//! `SIGMAS`) bound a glitch of the samples between them; an out-of-line
//! interval left alone is a jump. The robust scale is that of the
//! series' own noise: a white-noise series of a million samples has none
//! beyond [`SIGMAS`] (probability 1e-23 a sample), so nothing is found
//! in a clean log (test `a_clean_log_has_no_outliers`).

use serde::Serialize;

/// How far out of line, in robust standard deviations, an interval's
/// step must be.
pub const SIGMAS: f64 = 10.0;
/// The most samples a glitch spans.
pub const GLITCH_SAMPLES: usize = 10;

/// What kind of accident.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AccidentKind {
    /// A step of the offset that stays.
    Jump,
    /// Samples read wrong and then right again.
    Glitch,
}

/// One jump or glitch.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Accident {
    /// Which.
    pub kind: AccidentKind,
    /// The time of its first sample, s (the series' own time).
    pub time_s: f64,
    /// Its first sample's index.
    pub first_sample: usize,
    /// How many samples it moves (a jump: all after it).
    pub samples: usize,
    /// The step, s of offset (a glitch: how far its samples are off).
    pub size_s: f64,
    /// The step in robust standard deviations of the series' noise.
    pub sigmas: f64,
}

/// The median of a slice (reordered).
fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    let h = v.len() / 2;
    *v.select_nth_unstable_by(h, f64::total_cmp).1
}

/// The robust standard deviation of `deviations` about `centre`: 1.4826
/// times their median absolute deviation, or, where that is no more than
/// the values' rounding (more than half of them equal to the last bits: a
/// short log, or readings to a few digits, whose scale by the median is
/// zero or 1e-17 and makes every other value an outlier), their standard
/// deviation. `None` when both are nothing (all the values equal).
fn robust_scale(deviations: &mut [f64], centre: f64) -> Option<f64> {
    let finite = || deviations.iter().copied().filter(|d| d.is_finite());
    let size = finite().fold(centre.abs(), |m, d| m.max(d.abs()));
    let n = finite().count() as f64;
    let sd = (finite().map(|d| (d - centre).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let mut spread: Vec<f64> = finite().map(|d| (d - centre).abs()).collect();
    let mad = 1.4826 * median(&mut spread);
    let scale = if mad > 1e-12 * size { mad } else { sd };
    (scale.is_finite() && scale > 1e-12 * size).then_some(scale)
}

/// Blocks of this many samples make the local level.
const BLOCK: usize = 64;

/// Each sample's local level: the median of the medians of its block of
/// [`BLOCK`] samples and the blocks on either side (non-finite samples
/// skipped), so a level follows a slow change and no accident moves it.
fn local_medians(values: &[f64]) -> Vec<f64> {
    let blocks: Vec<f64> = values
        .chunks(BLOCK)
        .map(|c| {
            median(
                &mut c
                    .iter()
                    .copied()
                    .filter(|v| v.is_finite())
                    .collect::<Vec<_>>(),
            )
        })
        .collect();
    (0..values.len())
        .map(|i| {
            let b = i / BLOCK;
            let mut three: Vec<f64> = [
                b.checked_sub(1),
                Some(b),
                (b + 1 < blocks.len()).then_some(b + 1),
            ]
            .into_iter()
            .flatten()
            .map(|k| blocks[k])
            .filter(|v| v.is_finite())
            .collect();
            median(&mut three)
        })
        .collect()
}

/// The jumps and glitches of offsets `x` (s) at `times` (s, increasing).
/// Non-finite offsets are skipped over.
pub fn find_accidents(times: &[f64], x: &[f64]) -> Vec<Accident> {
    let idx: Vec<usize> = (0..x.len()).filter(|&i| x[i].is_finite()).collect();
    if idx.len() < 8 {
        return Vec::new();
    }
    let m = idx.len() - 1;
    let dt: Vec<f64> = (0..m).map(|k| times[idx[k + 1]] - times[idx[k]]).collect();
    let dx: Vec<f64> = (0..m).map(|k| x[idx[k + 1]] - x[idx[k]]).collect();
    let rate: Vec<f64> = (0..m).map(|k| dx[k] / dt[k]).collect();
    // The local rate: each interval's block of 64 and its neighbours'.
    let level = local_medians(&rate);
    let local = |k: usize| level[k];
    let mut median_dt = dt.clone();
    let typical_dt = median(&mut median_dt);
    let scaled: Vec<f64> = (0..m)
        .map(|k| (dx[k] - local(k) * dt[k]) / (dt[k] / typical_dt).sqrt())
        .collect();
    let stride = (m / 200_000).max(1);
    let mut sample: Vec<f64> = scaled.iter().step_by(stride).copied().collect();
    let centre = median(&mut sample);
    let Some(scale) = robust_scale(&mut sample, centre) else {
        return Vec::new();
    };
    let out_of_line: Vec<usize> = (0..m)
        .filter(|&k| ((scaled[k] - centre) / scale).abs() > SIGMAS)
        .collect();
    let excess = |k: usize| dx[k] - local(k) * dt[k];
    let mut accidents = Vec::new();
    let mut used = vec![false; out_of_line.len()];
    for a in 0..out_of_line.len() {
        if used[a] {
            continue;
        }
        let k = out_of_line[a];
        let step = excess(k);
        // A later interval that takes the step back.
        let back = (a + 1..out_of_line.len())
            .take_while(|&b| out_of_line[b] - k <= GLITCH_SAMPLES)
            .find(|&b| {
                let s = excess(out_of_line[b]);
                let sum = (step + s).abs();
                !used[b] && (sum < 0.2 * step.abs() || sum < SIGMAS * scale)
            });
        let sigmas = ((scaled[k] - centre) / scale).abs();
        match back {
            Some(b) => {
                used[b] = true;
                accidents.push(Accident {
                    kind: AccidentKind::Glitch,
                    time_s: times[idx[k + 1]],
                    first_sample: idx[k + 1],
                    samples: idx[out_of_line[b] + 1] - idx[k + 1],
                    size_s: step,
                    sigmas,
                });
            }
            None => accidents.push(Accident {
                kind: AccidentKind::Jump,
                time_s: times[idx[k + 1]],
                first_sample: idx[k + 1],
                samples: x.len() - idx[k + 1],
                size_s: step,
                sigmas,
            }),
        }
        used[a] = true;
    }
    accidents
}

/// `x` with its accidents taken out: a glitch's samples set to NaN (a
/// gap), a jump's step taken back from every later sample.
pub fn remove_accidents(x: &mut [f64], accidents: &[Accident]) {
    for a in accidents {
        match a.kind {
            AccidentKind::Glitch => {
                for v in &mut x[a.first_sample..a.first_sample + a.samples] {
                    *v = f64::NAN;
                }
            }
            AccidentKind::Jump => {
                for v in &mut x[a.first_sample..] {
                    *v -= a.size_s;
                }
            }
        }
    }
}

/// The values of a frequency series (a rate, any unit; NaN a gap) out of
/// line with their neighbours:
/// beyond [`SIGMAS`] robust standard deviations (1.4826 times the median
/// absolute deviation of each rate from the median of the 64 around it)
/// of the local median: each one's index and how far it is off.
pub fn frequency_outliers(rates: &[f64]) -> Vec<(usize, f64)> {
    let n = rates.len();
    if n < 8 {
        return Vec::new();
    }
    let deviation: Vec<f64> = rates
        .iter()
        .zip(local_medians(rates))
        .map(|(r, l)| r - l)
        .collect();
    let stride = (n / 200_000).max(1);
    let mut spread: Vec<f64> = deviation.iter().step_by(stride).copied().collect();
    let Some(scale) = robust_scale(&mut spread, 0.0) else {
        return Vec::new();
    };
    (0..n)
        .filter(|&i| (deviation[i] / scale).abs() > SIGMAS)
        .map(|i| (i, deviation[i]))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_noise::normals as noise;

    /// White frequency noise with a wandering rate: a phase walk.
    fn offsets(n: usize, seed: u64) -> (Vec<f64>, Vec<f64>) {
        let times: Vec<f64> = (0..n).map(|i| 10.0 * i as f64).collect();
        let e = noise(n, seed);
        let mut x = 0.0;
        let offsets = (0..n)
            .map(|i| {
                x += 1e-4 * e[i] + 1e-5 * 10.0 * (i as f64 / 5e4).sin();
                x
            })
            .collect();
        (times, offsets)
    }

    #[test]
    fn a_clean_log_has_no_outliers() {
        for seed in [3, 5, 7] {
            let (t, x) = offsets(1_000_000, seed);
            assert_eq!(find_accidents(&t, &x), vec![], "seed {seed}");
        }
    }

    #[test]
    fn a_missed_pulse_is_a_glitch_and_a_slip_a_jump() {
        let (t, mut x) = offsets(50_000, 11);
        x[1000] += 1.0;
        for v in &mut x[30_000..] {
            *v -= 0.5;
        }
        let found = find_accidents(&t, &x);
        assert_eq!(found.len(), 2, "{found:?}");
        assert_eq!(found[0].kind, AccidentKind::Glitch);
        assert_eq!((found[0].first_sample, found[0].samples), (1000, 1));
        assert!((found[0].size_s - 1.0).abs() < 1e-3);
        assert_eq!(found[1].kind, AccidentKind::Jump);
        assert_eq!(found[1].first_sample, 30_000);
        assert!((found[1].size_s + 0.5).abs() < 1e-3);
        let mut cleaned = x.clone();
        remove_accidents(&mut cleaned, &found);
        assert!(cleaned[1000].is_nan());
        assert!((cleaned[30_000] - cleaned[29_999]).abs() < 1e-2);
    }
}
