//! Q and the swing-to-swing scatter of the energy from a photogate's
//! amplitudes, one a half swing.
//!
//! Method: between impulses the amplitude decays as `A ∝ exp(−t/τ)`, so
//! `ln A` falls by `π/(2Q)` each half period (`Q = ωτ/2`). An impulse
//! shows as a rise of `ln A` from one half swing to the next far beyond
//! the scatter (more than 8 robust standard deviations, from the median
//! absolute deviation of the steps, above their median). The half
//! swings between impulses are fitted by least squares with one slope
//! and an intercept for each stretch, which gives `Q = π/(2·decrement)`
//! with its standard error. A clock impulsed at every swing shows no such
//! stretches: its Q cannot be seen while it goes (a run-down, `pendulum
//! fit decay`, measures it).
//!
//! The "purity" some makers quote beside Q is the steadiness of the
//! swing's energy `E ∝ 1 − cos A`: here the RMS of the relative change of
//! the energy from one half swing to the next, the steady decay and the
//! impulses taken out, over √2 (each change holds two swings' scatter).
//! It includes the gate's own timing noise, so it is an upper bound on
//! the pendulum's.

use serde::Serialize;

/// What the amplitudes tell of the swing.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Swing {
    /// Half swings read.
    pub half_swings: usize,
    /// Impulses found (rises of the amplitude beyond the scatter).
    pub impulses: usize,
    /// The mean half swings from one impulse to the next.
    pub half_swings_per_impulse: Option<f64>,
    /// The quality factor from the decay between impulses.
    pub q: Option<f64>,
    /// Its standard error.
    pub q_standard_error: Option<f64>,
    /// The relative swing-to-swing scatter of the energy, parts per
    /// million (the "purity").
    pub energy_scatter_ppm: f64,
    /// The mean amplitude, degrees.
    pub mean_amplitude_deg: f64,
}

/// Impulses lie this many robust standard deviations above the median
/// step of ln A.
const IMPULSE_SIGMAS: f64 = 8.0;

/// Q and the energy's scatter from `amplitude_deg`, one a half swing
/// (consecutive, `gap[i]` true where a half swing is missing before
/// sample `i`). `None` for fewer than 20 finite amplitudes.
pub fn swing(amplitude_deg: &[f64], gap: &dyn Fn(usize) -> bool) -> Option<Swing> {
    let ln: Vec<f64> = amplitude_deg
        .iter()
        .map(|a| {
            if *a > 0.0 {
                a.to_radians().ln()
            } else {
                f64::NAN
            }
        })
        .collect();
    // Steps of ln A between consecutive half swings.
    let steps: Vec<(usize, f64)> = (1..ln.len())
        .filter(|&i| !gap(i))
        .map(|i| (i, ln[i] - ln[i - 1]))
        .filter(|(_, d)| d.is_finite())
        .collect();
    if steps.len() < 20 {
        return None;
    }
    let median = |v: &mut Vec<f64>| {
        let h = v.len() / 2;
        *v.select_nth_unstable_by(h, f64::total_cmp).1
    };
    let mut d: Vec<f64> = steps.iter().map(|s| s.1).collect();
    let centre = median(&mut d);
    let mut dev: Vec<f64> = d.iter().map(|x| (x - centre).abs()).collect();
    let sigma = 1.4826 * median(&mut dev);
    let threshold = centre + IMPULSE_SIGMAS * sigma.max(1e-12);
    let is_impulse: Vec<bool> = steps.iter().map(|s| s.1 > threshold && s.1 > 0.0).collect();
    let impulses = is_impulse.iter().filter(|&&b| b).count();
    // The half swings from one impulse to the next: the median spacing
    // of the impulses (a gap or a missed impulse does not move it).
    let at: Vec<usize> = steps
        .iter()
        .zip(&is_impulse)
        .filter(|(_, &imp)| imp)
        .map(|(s, _)| s.0)
        .collect();
    let every = (at.len() >= 3).then(|| {
        let mut d: Vec<f64> = at.windows(2).map(|w| (w[1] - w[0]) as f64).collect();
        median(&mut d)
    });
    // Stretches: runs of half swings joined by steps that are not
    // impulses (nor gaps).
    let mut joins = vec![false; ln.len()];
    for ((i, _), &imp) in steps.iter().zip(&is_impulse) {
        joins[*i] = !imp;
    }
    let mut stretch = vec![0usize; ln.len()];
    let mut current = 0usize;
    for i in 1..ln.len() {
        if !joins[i] {
            current += 1;
        }
        stretch[i] = current;
    }
    // One slope, an intercept a stretch: the slope is the pooled
    // within-stretch regression of ln A on the half swing's index.
    let (q, q_se) = if impulses >= 2 && impulses * 4 < steps.len() {
        let mut groups = vec![(0.0f64, 0.0f64, 0.0f64); current + 1];
        for (i, &s) in stretch.iter().enumerate() {
            if ln[i].is_finite() {
                let e = &mut groups[s];
                e.0 += 1.0;
                e.1 += i as f64;
                e.2 += ln[i];
            }
        }
        let (mut sxx, mut sxy, mut n) = (0.0, 0.0, 0.0);
        for (i, &s) in stretch.iter().enumerate() {
            if let Some(g) = Some(&groups[s]).filter(|g| g.0 >= 2.0) {
                if ln[i].is_finite() {
                    let x = i as f64 - g.1 / g.0;
                    sxx += x * x;
                    sxy += x * (ln[i] - g.2 / g.0);
                    n += 1.0;
                }
            }
        }
        let k = groups.iter().filter(|g| g.0 >= 2.0).count() as f64;
        let slope = sxy / sxx;
        let mut rss = 0.0;
        for (i, &s) in stretch.iter().enumerate() {
            if let Some(g) = Some(&groups[s]).filter(|g| g.0 >= 2.0) {
                if ln[i].is_finite() {
                    let x = i as f64 - g.1 / g.0;
                    rss += (ln[i] - g.2 / g.0 - slope * x).powi(2);
                }
            }
        }
        let dof = n - k - 1.0;
        if slope < 0.0 && dof > 0.0 && sxx > 0.0 {
            let se = (rss / dof / sxx).sqrt();
            let q = std::f64::consts::PI / (2.0 * -slope);
            (Some(q), Some(q * se / -slope))
        } else {
            (None, None)
        }
    } else {
        (None, None)
    };
    // The energy's relative change from half swing to half swing, the
    // steady decay taken out.
    let energy = |i: usize| 1.0 - amplitude_deg[i].to_radians().cos();
    let changes: Vec<f64> = steps
        .iter()
        .zip(&is_impulse)
        .filter(|(_, &imp)| !imp)
        .map(|((i, _), _)| energy(*i) / energy(*i - 1) - 1.0)
        .filter(|x| x.is_finite())
        .collect();
    let m = changes.iter().sum::<f64>() / changes.len().max(1) as f64;
    let var =
        changes.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (changes.len().max(2) - 1) as f64;
    let finite: Vec<f64> = amplitude_deg
        .iter()
        .copied()
        .filter(|a| a.is_finite())
        .collect();
    Some(Swing {
        half_swings: finite.len(),
        impulses,
        half_swings_per_impulse: every,
        q,
        q_standard_error: q_se,
        energy_scatter_ppm: (var / 2.0).sqrt() * 1e6,
        mean_amplitude_deg: finite.iter().sum::<f64>() / finite.len().max(1) as f64,
    })
}
