//! Times written rounded, rebuilt on the frame grid they came from; and
//! the gaps in a record.
//!
//! A video's frames are a constant interval apart; an export that rounds
//! their times (Tracker's table to a few digits or significant figures)
//! writes `round_q(t₀ + k Δt)`, where the quantum `q` may grow with the
//! time (`12.3` s, then `123` s: three significant figures). The rounding
//! is not noise about the motion: a stamp shared by several frames, once
//! spread or taken as it is, shifts whole stretches of the record, and a
//! shift that grows along it stretches the frequency (ω_d 0.17% low, 2.6
//! of its standard errors, on a two-minute record at 29.97 frames a
//! second rounded to three significant figures and spread by the reader;
//! rebuilt, within 0.5 of its now 1,000 times smaller error:
//! `tests/cli/fit.rs`). So the grid is rebuilt: each row is the next frame after
//! the row before it (or more, where the time jumps further than the
//! rounding allows: a frame lost), `t₀` and `Δt` are the least squares
//! of the written times against the frame numbers (each weighted by its
//! quantum) to start, then the middle of the lines every written time
//! rounds back from (each within half its quantum of its frame's time):
//! when there is none, the times are not a rounded frame grid (a logger's
//! own clock, jitter), and are left as they are.
//!
//! The quantum of a written time is read from the number itself: the
//! coarsest power of ten of which it is a multiple (to a millionth of it, so that
//! the float's own rounding, or a time origin taken off and put back, does
//! not hide it).
//!
//! A gap is a step more than [`GAP_STEPS`] times the median step (a
//! tracker that lost the bob for a while, a logger paused): the record is
//! then in pieces, and what follows a gap may not be the same swing.

/// A step longer than this many median steps is a gap in the record.
pub const GAP_STEPS: f64 = 5.0;

/// Times rebuilt on their frame grid.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameGrid {
    /// The frame interval, s.
    pub interval: f64,
    /// Each row's frame number, from 0 at the first row.
    pub frames: Vec<f64>,
    /// The rebuilt times, `t₀ + k Δt`, s (the written times' origin).
    pub time: Vec<f64>,
    /// The quantum most written times were rounded to (the median of
    /// theirs), s.
    pub quantum: f64,
    /// The largest change from a written time to its rebuilt one, s.
    pub largest_change: f64,
    /// Rows that share their written time with the row before.
    pub repeated: usize,
}

/// The coarsest power of ten (from 10³ down to 10⁻¹²) of which `t` is a
/// multiple, to a millionth of that power (and the float's own rounding);
/// 0 for a value written to more digits than that.
pub fn quantum(t: f64) -> f64 {
    if t == 0.0 {
        return 1e3;
    }
    for d in -3..=12 {
        let q = 10f64.powi(-d);
        let k = t / q;
        if (k - k.round()).abs() <= 1e-6 + 1e-15 * k.abs() {
            return q;
        }
    }
    0.0
}

/// The frame grid of times written rounded (see the module notes), or
/// `None` when they are not one, or lie on it already as near as matters
/// (no time moves by a thousandth of the interval). Needs at least 8
/// rows, the times not decreasing, and not all equal.
pub fn frame_grid(time: &[f64]) -> Option<FrameGrid> {
    let n = time.len();
    if n < 8 || time.windows(2).any(|w| w[1] < w[0] || w[1].is_nan()) {
        return None;
    }
    let span = time[n - 1] - time[0];
    if !(span > 0.0 && span.is_finite()) {
        return None;
    }
    let q: Vec<f64> = time.iter().map(|&t| quantum(t)).collect();
    let repeated = time.windows(2).filter(|w| w[1] == w[0]).count();
    // A first interval: the span over the rows (no frame lost).
    let mut interval = span / (n - 1) as f64;
    let mut frames = vec![0.0; n];
    for _ in 0..4 {
        // Each row one frame after the row before, or more where the time
        // jumps further than one frame and the rounding of both allow.
        for i in 1..n {
            let step = time[i] - time[i - 1];
            let slack = 0.5 * (q[i] + q[i - 1]);
            let count = if step > interval + slack {
                (step / interval).round().max(1.0)
            } else {
                1.0
            };
            frames[i] = frames[i - 1] + count;
        }
        // The weighted least squares of the times against the frames.
        let floor = 1e-9 * interval;
        let (mut sw, mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for i in 0..n {
            let w = 1.0 / q[i].max(floor).powi(2);
            let (x, y) = (frames[i], time[i] - time[0]);
            sw += w;
            sx += w * x;
            sy += w * y;
            sxx += w * x * x;
            sxy += w * x * y;
        }
        let det = sw * sxx - sx * sx;
        if det.is_nan() || det <= 0.0 {
            return None;
        }
        let slope = (sw * sxy - sx * sy) / det;
        if !(slope > 0.0 && slope.is_finite()) {
            return None;
        }
        interval = slope;
    }
    // The least squares placed the line; the rounding bounds it: each
    // written time lies within half its quantum of its frame's, so for an
    // interval Δt the first frame's time must lie in [L(Δt), U(Δt)], L the
    // largest of tᵢ − qᵢ/2 − kᵢΔt and U the smallest of tᵢ + qᵢ/2 − kᵢΔt.
    // U − L is concave in Δt: its greatest value (ternary search) is the
    // grid's if positive, and the middle of the Δt where it stays so is
    // taken (precise to a quantum over the record's frames, where the
    // least squares are to its square root).
    let half: Vec<f64> = (0..n)
        .map(|i| 0.5 * q[i].max(1e-12 * time[i].abs().max(interval)))
        .collect();
    let room = |dt: f64| -> (f64, f64) {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        for i in 0..n {
            let base = time[i] - frames[i] * dt;
            lo = lo.max(base - half[i]);
            hi = hi.min(base + half[i]);
        }
        (lo, hi)
    };
    let width = |dt: f64| {
        let (lo, hi) = room(dt);
        hi - lo
    };
    let last = frames[n - 1].max(1.0);
    let reach = 2.0 * half.iter().copied().fold(0.0, f64::max) / last + 1e-9 * interval;
    let (mut a, mut b) = (interval - 10.0 * reach, interval + 10.0 * reach);
    for _ in 0..200 {
        let (m1, m2) = (a + (b - a) / 3.0, b - (b - a) / 3.0);
        if width(m1) < width(m2) {
            a = m1;
        } else {
            b = m2;
        }
    }
    let best = 0.5 * (a + b);
    if width(best).is_nan() || width(best) < 0.0 {
        return None;
    }
    // The ends of the feasible intervals, by bisection either side.
    let edge = |inside: f64, outside: f64| {
        let (mut i, mut o) = (inside, outside);
        for _ in 0..200 {
            let m = 0.5 * (i + o);
            if width(m) >= 0.0 {
                i = m;
            } else {
                o = m;
            }
        }
        i
    };
    let interval = 0.5 * (edge(best, best - 10.0 * reach) + edge(best, best + 10.0 * reach));
    let (lo, hi) = room(interval);
    let t0 = 0.5 * (lo + hi);
    let rebuilt: Vec<f64> = frames.iter().map(|k| t0 + k * interval).collect();
    let mut largest: f64 = 0.0;
    for i in 0..n {
        largest = largest.max((rebuilt[i] - time[i]).abs());
    }
    if largest <= 1e-3 * interval {
        return None;
    }
    Some(FrameGrid {
        interval,
        frames,
        time: rebuilt,
        quantum: super::median(&mut q.clone()),
        largest_change: largest,
        repeated,
    })
}

/// The pieces of a record split at its gaps: the index ranges of its
/// runs of samples between steps longer than [`GAP_STEPS`] median steps.
/// One range (the whole) when there is no gap.
pub fn runs(time: &[f64]) -> Vec<std::ops::Range<usize>> {
    let n = time.len();
    if n < 3 {
        return std::iter::once(0..n).collect();
    }
    let mut steps: Vec<f64> = time.windows(2).map(|w| w[1] - w[0]).collect();
    let median = super::median(&mut steps);
    if median.is_nan() || median <= 0.0 {
        return std::iter::once(0..n).collect();
    }
    let mut out = Vec::new();
    let mut start = 0;
    for i in 1..n {
        if time[i] - time[i - 1] > GAP_STEPS * median {
            out.push(start..i);
            start = i;
        }
    }
    out.push(start..n);
    out
}

/// The longest run of [`runs`] (the first of equals), and the others.
pub fn longest_run(time: &[f64]) -> (std::ops::Range<usize>, Vec<std::ops::Range<usize>>) {
    let all = runs(time);
    let best = all
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.len().cmp(&b.1.len()).then(b.0.cmp(&a.0)))
        .map_or(0, |(i, _)| i);
    let kept = all[best].clone();
    let others = all.into_iter().filter(|r| *r != kept).collect();
    (kept, others)
}

/// For people: which samples a fit of the longest run left out, and why
/// (`kept`: the run's first and last times, s; `left`: each run left out,
/// its first and last times and its samples).
pub fn left_out_message(kept: [f64; 2], left: &[[f64; 3]]) -> String {
    use crate::error::format_significant as sig;
    let samples: f64 = left.iter().map(|l| l[2]).sum();
    let spans: Vec<String> = left
        .iter()
        .take(3)
        .map(|l| format!("{} to {} s", sig(l[0], 5), sig(l[1], 5)))
        .collect();
    format!(
        "the record has gaps (steps of more than {} median steps): every figure is from its \
         longest run, {} to {} s; {} samples beyond a gap are left out ({}{}), as what follows \
         a gap may not be the same swing (fit them on their own with --from and --to)",
        sig(GAP_STEPS, 2),
        sig(kept[0], 5),
        sig(kept[1], 5),
        samples,
        spans.join(", "),
        if left.len() > 3 { ", …" } else { "" }
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three significant figures, as `format!("{:.*}")` by magnitude.
    fn three_figures(t: f64) -> f64 {
        if t == 0.0 {
            return 0.0;
        }
        let digits = 2 - t.abs().log10().floor() as i32;
        let q = 10f64.powi(-digits);
        (t / q).round() * q
    }

    #[test]
    fn the_quantum_of_a_written_time() {
        assert_eq!(quantum(12.3), 0.1);
        assert_eq!(quantum(0.083), 1e-3);
        assert_eq!(quantum(120.0), 10.0);
        assert_eq!(quantum(1.0 / 30.0), 0.0);
        // A time origin taken off and put back keeps it.
        assert_eq!(quantum((12.591 - 12.558) + 12.558), 1e-3);
    }

    #[test]
    fn times_rounded_to_three_figures_are_rebuilt() {
        let dt = 1.0 / 29.97;
        let truth: Vec<f64> = (0..3600).map(|k| 0.5 + k as f64 * dt).collect();
        let written: Vec<f64> = truth.iter().map(|&t| three_figures(t)).collect();
        let grid = frame_grid(&written).unwrap();
        assert!((grid.interval / dt - 1.0).abs() < 1e-6, "{}", grid.interval);
        for (a, b) in grid.time.iter().zip(&truth) {
            assert!((a - b).abs() < 1e-3, "{a} vs {b}");
        }
        assert!(grid.repeated > 2000, "{}", grid.repeated);
        assert_eq!(grid.quantum, 0.1);
    }

    #[test]
    fn a_lost_frame_and_three_decimals() {
        let dt = 1.0 / 12.0;
        let frames: Vec<f64> = (0..400)
            .filter(|&k| k != 100 && k != 101)
            .map(f64::from)
            .collect();
        let written: Vec<f64> = frames
            .iter()
            .map(|k| (k * dt * 1000.0).round() / 1000.0)
            .collect();
        let grid = frame_grid(&written).unwrap();
        assert_eq!(grid.frames[100], 102.0);
        assert!((grid.interval / dt - 1.0).abs() < 1e-7);
        assert!(grid.largest_change <= 5e-4 + 1e-12);
    }

    #[test]
    fn times_that_are_no_grid_are_left() {
        // A logger's jittered clock written to the microsecond.
        let mut state = 3_u64;
        let times: Vec<f64> = (0..500)
            .map(|k| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let jitter = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2e-3;
                ((k as f64 * 0.01 + jitter) * 1e6).round() / 1e6
            })
            .collect();
        assert!(frame_grid(&times).is_none());
        // Exact frame times need nothing.
        let exact: Vec<f64> = (0..500).map(|k| k as f64 / 30.0).collect();
        assert!(frame_grid(&exact).is_none());
    }

    #[test]
    fn gaps_split_a_record() {
        let mut t: Vec<f64> = (0..100).map(|k| k as f64 * 0.01).collect();
        t.extend((0..30).map(|k| 2.0 + k as f64 * 0.01));
        t.remove(50); // one lost frame is no gap
        let (kept, others) = longest_run(&t);
        assert_eq!(kept, 0..99);
        assert_eq!(others, vec![99..129]);
    }
}
