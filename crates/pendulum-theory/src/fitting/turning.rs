//! The turning points of a tracked swing: what a run-down's amplitudes are
//! when all one has is the angle against time (a video track).
//!
//! 1. The zero of the swing is estimated (a tracked zero is never exactly
//!    the vertical): first the median angle, then, once the turning points
//!    are known, the mean of the three-point averages
//!    `(θ_k + 2θ_{k+1} + θ_{k+2})/4` of successive turning angles, which
//!    cancels a linear decay of the amplitude.
//! 2. Half swings are cut at crossings of that zero with hysteresis: a
//!    crossing counts only once the angle has gone a threshold past it (five
//!    times the noise estimated from second differences), so frame noise
//!    near the bottom makes no false turn.
//! 3. In each half swing the extreme sample is refined by the least-squares
//!    parabola through the samples within an eighth of the half swing of it
//!    (at least 2 on each side): its vertex gives the turning time and angle
//!    to a fraction of a frame.
//!
//! The first and last half swings are dropped when they are cut by the ends
//! of the record (their extreme sample lies on the record's edge), unless
//! the record starts (or ends) on the crest itself: the parabola through
//! the samples after it (or before) has its vertex within half a sample
//! interval of the edge (a swing released from rest as the record starts:
//! its first crest is the release, the largest amplitude it has).

use super::straight_line;

/// A turning point found in a track.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turn {
    /// Time, s.
    pub time: f64,
    /// Amplitude about the estimated zero, rad (positive).
    pub amplitude: f64,
    /// +1 on the positive side, -1 on the negative.
    pub side: f64,
}

/// The turning points of the track `(time, angle)` and the zero offset
/// removed from them, rad.
#[derive(Clone, Debug, PartialEq)]
pub struct Turns {
    /// The turning points, in time order.
    pub turns: Vec<Turn>,
    /// The estimated zero of the swing (the tracked angle of the vertical), rad.
    pub offset: f64,
}

impl Turns {
    /// The mean half period from the turning times (least-squares slope of
    /// time against the half-swing count, [`Self::half_swings`]), s;
    /// `None` with fewer than 3 turns.
    pub fn half_period(&self) -> Option<f64> {
        self.half_period_with_error().map(|(h, _)| h)
    }

    /// [`Self::half_period`] and its standard error (the slope's, from the
    /// times' scatter about the line), s.
    pub fn half_period_with_error(&self) -> Option<(f64, f64)> {
        if self.turns.len() < 3 {
            return None;
        }
        let n = self.half_swings();
        let t: Vec<f64> = self.turns.iter().map(|p| p.time).collect();
        let (a, b) = straight_line(&n, &t);
        let mean = n.iter().sum::<f64>() / n.len() as f64;
        let sxx: f64 = n.iter().map(|x| (x - mean).powi(2)).sum();
        let rss: f64 = n.iter().zip(&t).map(|(x, y)| (y - a - b * x).powi(2)).sum();
        let se = (rss / (n.len() - 2) as f64 / sxx).sqrt();
        Some((b, if se.is_finite() { se } else { 0.0 }))
    }

    /// The half swing each turning point ends, counted from the first
    /// (0): successive turns on opposite sides are one half swing apart,
    /// two on the same side two (the turn between was not found: a gap
    /// in the track, or a half swing cut short).
    pub fn half_swings(&self) -> Vec<f64> {
        let mut count = 0.0;
        let mut out = Vec::with_capacity(self.turns.len());
        for (i, t) in self.turns.iter().enumerate() {
            if i > 0 {
                count += if t.side == self.turns[i - 1].side {
                    2.0
                } else {
                    1.0
                };
            }
            out.push(count);
        }
        out
    }
}

/// The noise of `y`, from its second differences: for white noise of
/// standard deviation σ, `y_{i+1} - 2y_i + y_{i-1}` has 6σ²; the median
/// absolute value (over 0.6745) keeps the smooth motion out of it.
fn noise(y: &[f64]) -> f64 {
    let mut d: Vec<f64> = y
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]).abs())
        .collect();
    if d.is_empty() {
        return 0.0;
    }
    d.sort_by(f64::total_cmp);
    d[d.len() / 2] / 0.6745 / 6f64.sqrt()
}

/// Finds the turning points of the track `(time, angle)`.
pub fn turning_points(time: &[f64], angle: &[f64]) -> Turns {
    let n = time.len().min(angle.len());
    let first_zero = super::median(&mut angle[..n].to_vec());
    let turns = find(time, angle, n, first_zero);
    // Refine the zero from the turning angles, then measure again.
    let signed: Vec<f64> = turns
        .iter()
        .map(|t| first_zero + t.side * t.amplitude)
        .collect();
    let offset = if signed.len() >= 3 {
        let averages: Vec<f64> = signed
            .windows(3)
            .map(|w| 0.25 * (w[0] + 2.0 * w[1] + w[2]))
            .collect();
        averages.iter().sum::<f64>() / averages.len() as f64
    } else {
        first_zero
    };
    let turns = signed
        .iter()
        .zip(&turns)
        .map(|(&angle, t)| Turn {
            time: t.time,
            amplitude: (angle - offset).abs(),
            side: t.side,
        })
        .collect();
    Turns { turns, offset }
}

/// The turning points about `zero`.
fn find(time: &[f64], angle: &[f64], n: usize, zero: f64) -> Vec<Turn> {
    let threshold = 5.0 * noise(&angle[..n]);
    // Segments between hysteresis crossings of the zero.
    let mut segments: Vec<(usize, usize, f64)> = Vec::new();
    let mut side = 0.0;
    let mut start = 0;
    for (i, &a) in angle.iter().enumerate().take(n) {
        let y = a - zero;
        let now = if y > threshold {
            1.0
        } else if y < -threshold {
            -1.0
        } else {
            continue;
        };
        if now != side {
            if side != 0.0 {
                segments.push((start, i, side));
            }
            side = now;
            start = i;
        }
    }
    if side != 0.0 {
        segments.push((start, n, side));
    }
    let mut turns = Vec::new();
    for (k, &(a, b, side)) in segments.iter().enumerate() {
        // The extreme sample: walk back to the crossing before to include
        // the whole half swing (the segment starts past the threshold).
        let from = if k == 0 { 0 } else { a.saturating_sub(1) };
        let (i_max, _) = (from..b).map(|i| (i, side * (angle[i] - zero))).fold(
            (from, f64::NEG_INFINITY),
            |best, c| if c.1 > best.1 { c } else { best },
        );
        // A half swing cut by an end of the record has its extreme there;
        // one the record starts or ends on has its vertex within half a
        // sample of the edge.
        let edge = i_max == 0 || i_max + 1 >= n;
        let half = ((b - from) / 8).max(2);
        // (At an edge, the samples on its one side, as many as both sides
        // would have.)
        let lo = if i_max + 1 >= n {
            i_max.saturating_sub(3 * half)
        } else {
            i_max.saturating_sub(half)
        };
        let hi = if i_max == 0 {
            (3 * half + 1).min(n)
        } else {
            (i_max + half + 1).min(n)
        };
        if hi - lo < 5 {
            continue;
        }
        let slack = if edge && n > 1 {
            let half_sample = 0.5 * (time[1] - time[0]).min(time[n - 1] - time[n - 2]);
            match edge_crest(
                &time[lo..hi],
                &angle[lo..hi],
                time[i_max],
                half_sample,
                side,
            ) {
                Some(vertex_error) => half_sample + 2.0 * vertex_error,
                None => continue,
            }
        } else {
            0.0
        };
        if let Some((t, y)) = vertex(&time[lo..hi], &angle[lo..hi], time[i_max], slack) {
            turns.push(Turn {
                time: t,
                amplitude: side * (y - zero),
                side,
            });
        }
    }
    turns
}

/// Whether the parabola through `(t, y)` about the record's edge `t0`
/// pins its vertex (a crest the record starts or ends on; `slack` is half
/// a sample interval): it opens towards the `side`'s extreme, and the
/// vertex's standard error (from the scatter about it, `σ(c₁)/|2c₂|`) is
/// within two sample intervals, so that a steep, noisy stretch the record
/// ends in is not read as a crest. Returns that standard error: the
/// vertex must then lie within half a sample and two of it of the edge.
fn edge_crest(t: &[f64], y: &[f64], t0: f64, slack: f64, side: f64) -> Option<f64> {
    let m = t.len();
    if m < 5 || slack.is_nan() || slack <= 0.0 {
        return None;
    }
    let p = Parabola::fit(t, y, t0)?;
    let [c0, c1, c2] = p.c;
    if side * c2 >= 0.0 {
        return None;
    }
    let rss: f64 = t
        .iter()
        .zip(y)
        .map(|(&ti, &yi)| {
            let u = ti - t0;
            (yi - c0 - c1 * u - c2 * u * u).powi(2)
        })
        .sum();
    // (XᵀX)⁻¹ at (1, 1): its cofactor over the determinant.
    let a = p.normal;
    let inverse_11 = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / p.det;
    let c1_se = (rss / (m - 3) as f64 * inverse_11).max(0.0).sqrt();
    let vertex_error = c1_se / (2.0 * c2.abs());
    (vertex_error <= 4.0 * slack).then_some(vertex_error)
}

/// The vertex of the least-squares parabola through `(t, y)`, in
/// coordinates centred on `t0`; `None` if it does not open towards the
/// extreme or its vertex falls outside the points by more than `slack` s.
fn vertex(t: &[f64], y: &[f64], t0: f64, slack: f64) -> Option<(f64, f64)> {
    let [c0, c1, c2] = Parabola::fit(t, y, t0)?.c;
    if c2 == 0.0 {
        return None;
    }
    let u = -c1 / (2.0 * c2);
    let (first, last) = (t[0] - t0, t[t.len() - 1] - t0);
    if !(first - slack..=last + slack).contains(&u) {
        return None;
    }
    Some((t0 + u, c0 + c1 * u + c2 * u * u))
}

/// The least-squares parabola `y = c0 + c1 u + c2 u²`, `u = t − t0`, by
/// its 3×3 normal equations solved with Cramer's rule (centring on `t0`
/// keeps them well conditioned over a crest's few samples).
struct Parabola {
    /// `c0, c1, c2`.
    c: [f64; 3],
    /// The normal matrix `XᵀX`.
    normal: [[f64; 3]; 3],
    /// Its determinant (finite and not zero).
    det: f64,
}

impl Parabola {
    fn fit(t: &[f64], y: &[f64], t0: f64) -> Option<Self> {
        let (mut s, mut r) = ([0.0_f64; 5], [0.0_f64; 3]);
        for (&ti, &yi) in t.iter().zip(y) {
            let u = ti - t0;
            let mut p = 1.0;
            for (k, sk) in s.iter_mut().enumerate() {
                *sk += p;
                if k < 3 {
                    r[k] += p * yi;
                }
                p *= u;
            }
        }
        let normal = [[s[0], s[1], s[2]], [s[1], s[2], s[3]], [s[2], s[3], s[4]]];
        let det3 = |m: [[f64; 3]; 3]| {
            m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
        };
        let det = det3(normal);
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let solve = |k: usize| {
            let mut mk = normal;
            for row in 0..3 {
                mk[row][k] = r[row];
            }
            det3(mk) / det
        };
        Some(Self {
            c: [solve(0), solve(1), solve(2)],
            normal,
            det,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A damped swing sampled at 60 frames/s with an offset and noise.
    fn track(offset: f64, noise_rad: f64) -> (Vec<f64>, Vec<f64>) {
        let (w, zeta, a0) = (2.0 * std::f64::consts::PI / 1.7, 0.01, 0.3);
        let mut state = 7_u64;
        let mut uniform = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let t: Vec<f64> = (0..3600).map(|i| i as f64 / 60.0).collect();
        let y = t
            .iter()
            .map(|&t| {
                offset
                    + a0 * (-zeta * w * t).exp() * (w * t + 0.4).cos()
                    + noise_rad * 12f64.sqrt() * uniform()
            })
            .collect();
        (t, y)
    }

    #[test]
    fn finds_every_turn_with_its_amplitude_and_the_offset() {
        let (t, y) = track(0.03, 0.002);
        let turns = turning_points(&t, &y);
        // 60 s of a 1.7 s period: 70 or 71 turning points inside the record.
        assert!(
            (69..=71).contains(&turns.turns.len()),
            "{}",
            turns.turns.len()
        );
        assert!(
            (turns.offset - 0.03).abs() < 5e-4,
            "offset {}",
            turns.offset
        );
        let w = 2.0 * std::f64::consts::PI / 1.7;
        let mut bias = 0.0;
        for p in &turns.turns {
            // Turning points of e^{-ζωt} cos(ωt + φ) lie on the envelope to
            // O(ζ²); each vertex carries about 0.6 of the frame noise.
            let envelope = 0.3 * (-0.01 * w * p.time).exp();
            assert!(
                (p.amplitude - envelope).abs() < 0.004,
                "{p:?} vs {envelope}"
            );
            bias += (p.amplitude - envelope) / turns.turns.len() as f64;
        }
        assert!(bias.abs() < 5e-4, "mean error {bias}");
        let half = turns.half_period().unwrap();
        assert!((half / 0.85 - 1.0).abs() < 1e-3, "{half}");
    }

    /// A record that starts on its release (a crest) keeps it as its
    /// first turning point; one that ends on a steep, noisy stretch does
    /// not make a crest of it.
    #[test]
    fn a_record_that_starts_on_its_release_keeps_that_crest() {
        let (w, zeta, a0) = (2.0 * std::f64::consts::PI / 1.7, 0.01, 0.3);
        let mut state = 11_u64;
        let mut noise = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            0.002 * 12f64.sqrt() * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
        };
        let t: Vec<f64> = (0..1200).map(|i| i as f64 / 60.0).collect();
        let y: Vec<f64> = t
            .iter()
            .map(|&t| a0 * (-zeta * w * t).exp() * (w * t).cos() + noise())
            .collect();
        let turns = turning_points(&t, &y);
        let first = turns.turns[0];
        assert!(first.time.abs() < 2.5 / 60.0, "{first:?}");
        assert!((first.amplitude - a0).abs() < 0.004, "{first:?}");
        // Cut a quarter of a period short of a crest: that end is no crest.
        let end = t.partition_point(|&x| x < 1.7 * 10.0 - 0.3);
        let turns = turning_points(&t[..end], &y[..end]);
        let last = turns.turns.last().unwrap();
        assert!(last.time < t[end - 1] - 0.2, "{last:?}");
    }
}
