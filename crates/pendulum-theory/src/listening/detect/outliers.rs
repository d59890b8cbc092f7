//! Dropping ticks that sit off the clockwork.

use super::{median, Tick};

/// Neighbours of the same side on each side of a tick that predict it.
const REACH: u64 = 20;
/// The midpoints (nearest first) whose median predicts a tick.
const NEAREST: usize = 3;
/// A tick farther than this from its prediction is not the tick, s.
const OFF: f64 = 2e-3;

/// Cleans the ticks against the clockwork's regularity, in two steps:
///
/// * A tick with fewer than three ticks of its side within twenty beats
///   cannot be checked: dropped and counted.
/// * A tick more than 2 ms from where the ticks of its side around it
///   (up to ten before and ten after) put it is a drop sound or a noise
///   burst taken for the tick: dropped and counted. A clock's beats wander
///   by far less than 2 ms from one to the next (the jitter of a good clock
///   is tens of µs), so no real tick is lost.
/// * A tick timed one ringing period off (a cycle slip of the
///   cross-correlation, see [`super::Tick::alternatives`]) is moved to the
///   neighbouring peak of its correlation when that peak is nearer the
///   prediction and at least half as strong.
///
/// The prediction of beat `k` is the median of the nearest three
/// midpoints of the ticks `k - d` and `k + d` of its side (free of the
/// rate and of its slow drift, and of a wheel's periodic error to a few
/// per cent), or, near the ends of the recording, of the ticks of its side
/// carried over at the beat of all ticks (their least-squares slope).
/// Returns the ticks kept, how many were dropped, and how many moved.
pub fn clean(mut ticks: Vec<Tick>) -> (Vec<Tick>, usize, usize) {
    if ticks.len() < 8 {
        return (ticks, 0, 0);
    }
    // The beat from all ticks: least squares of time on beat number, with
    // an intercept for each side (a beat error shifts the tocks against
    // the ticks; one line through both tilts in a short record, and the
    // ticks carried over it would be moved a ringing period wrong).
    let mut sums = [(0.0, 0.0, 0.0); 2];
    for t in &ticks {
        let s = &mut sums[(t.beat % 2) as usize];
        *s = (s.0 + 1.0, s.1 + t.beat as f64, s.2 + t.time);
    }
    let (sxy, sxx) = ticks.iter().fold((0.0, 0.0), |(a, b), t| {
        let (n, sk, st) = sums[(t.beat % 2) as usize];
        let dk = t.beat as f64 - sk / n;
        (a + dk * (t.time - st / n), b + dk * dk)
    });
    if sxx <= 0.0 {
        return (ticks, 0, 0);
    }
    let beat = sxy / sxx;
    let times: std::collections::HashMap<u64, f64> =
        ticks.iter().map(|t| (t.beat, t.time)).collect();
    let predict = |t: &Tick| -> Option<f64> {
        let k = t.beat;
        // The nearest three: a wheel's periodic error bends the ticks'
        // line, and the midpoints of far neighbours (twenty beats either
        // way, a third of a seconds clock's minute) fall short of a bend's
        // top by half its height, enough to "correct" a tick by a ringing
        // period towards the straight line.
        let mut midpoints: Vec<f64> = (1..=REACH / 2)
            .filter_map(|d| {
                let d = 2 * d;
                let before = times.get(&k.checked_sub(d)?)?;
                let after = times.get(&(k + d))?;
                Some(0.5 * (before + after))
            })
            .take(NEAREST)
            .collect();
        if midpoints.len() >= 3 {
            return Some(median(&mut midpoints));
        }
        let mut carried: Vec<f64> = (1..=REACH)
            .flat_map(|d| [k.checked_sub(2 * d), Some(k + 2 * d)])
            .flatten()
            .filter_map(|j| times.get(&j).map(|&tj| tj + (k as f64 - j as f64) * beat))
            .take(2 * REACH as usize)
            .collect();
        (carried.len() >= 3).then(|| median(&mut carried))
    };
    let mut keep = vec![true; ticks.len()];
    let mut moved = 0;
    let predictions: Vec<Option<f64>> = ticks.iter().map(predict).collect();
    for ((t, prediction), keep) in ticks.iter_mut().zip(predictions).zip(&mut keep) {
        // A tick no neighbour of its side confirms is not trusted.
        let Some(p) = prediction else {
            *keep = false;
            continue;
        };
        let off = (t.time - p).abs();
        if off > OFF {
            *keep = false;
            continue;
        }
        let better = t
            .alternatives
            .iter()
            .flatten()
            .filter(|(a, r)| *r >= 0.5 && (a - p).abs() < 0.5 * off)
            .min_by(|a, b| (a.0 - p).abs().total_cmp(&(b.0 - p).abs()));
        if let Some(&(a, _)) = better {
            t.time = a;
            moved += 1;
        }
    }
    let dropped = keep.iter().filter(|k| !**k).count();
    let kept = ticks
        .into_iter()
        .zip(keep)
        .filter_map(|(t, k)| k.then_some(t))
        .collect();
    (kept, dropped, moved)
}
