//! Photogate event logs: the times a light gate's beam is cut and
//! restored as the bob passes (often from several gates, in a clock's
//! ticks), turned into one time per pass, the beat log of
//! [`super::beat_log`], and the width of each shadow, which with the bob's
//! size is its speed at the gate.
//!
//! Method: the events of one gate are paired greedily, an event and the
//! next forming a pass when they are closer than the geometric mean of the
//! median short and long intervals (edges of one shadow are milliseconds
//! apart, passes half a period); an event with no partner is a lone edge,
//! counted and left out. A log of one event per pass (no shadow's two
//! edges) is recognised by its intervals, which do not alternate: each
//! event is then a pass. The pass time is the shadow's middle, where the
//! bob's centre crosses the beam for a bob that moves evenly through it
//! (its speed changes by a part in `(w/L)²` over the shadow, negligible).
//! The speed at the gate is `d / w` for a bob of diameter `d` cutting the
//! beam through its centre in the shadow's width `w`.

use super::beat_log::{analyse as beats_of, Beats, Nominal};
use super::median;
use crate::analysis::{require_finite, Refusal};
use crate::warning::Warn;
use serde::Serialize;

/// Intervals of one parity shorter than this fraction of the other's
/// median make the events pairs of edges.
pub const PAIR_RATIO: f64 = 0.25;
/// The same when the bob's diameter is given (the log is said to hold
/// both edges): a long shadow (a small swing, a large bob) is still a
/// shadow.
pub const EDGES_GIVEN_RATIO: f64 = 0.9;
/// Alternating intervals below this ratio, not paired, are said: they may
/// be the edges of long shadows.
pub const ALTERNATION_SAID: f64 = 0.6;

/// A gate log to analyse.
#[derive(Clone, Debug, Default)]
pub struct GateInput<'a> {
    /// Event times, s, in the order logged.
    pub time: &'a [f64],
    /// Each event's gate (an index into the gates' labels), when the log
    /// holds several.
    pub gate: Option<&'a [f64]>,
    /// The gate to use (an index); the first gate logged by default.
    pub select: Option<usize>,
    /// The bob's diameter, m: the speed at the gate from the shadow widths.
    pub bob_diameter: Option<f64>,
    /// The nominal rate, as for a beat log.
    pub nominal: Option<Nominal>,
}

/// What the gate log gave besides the beats.
#[derive(Clone, Debug, Serialize)]
pub struct GateLog {
    /// The gate used (index into the labels).
    pub gate: usize,
    /// Gates in the log.
    pub gates: usize,
    /// Events of the gate used.
    pub events: usize,
    /// Whether the events are the two edges of each shadow (else one event
    /// a pass).
    pub edges_paired: bool,
    /// Passes found.
    pub passes: usize,
    /// Events left out with no partner edge.
    pub unpaired_edges: usize,
    /// Mean shadow width, ms (paired edges).
    pub pulse_width_ms: Option<f64>,
    /// Mean over the first and last 16 shadows, ms.
    pub pulse_width_start_ms: Option<f64>,
    /// See [`GateLog::pulse_width_start_ms`].
    pub pulse_width_end_ms: Option<f64>,
    /// The bob's speed at the gate over the first 16 passes, m/s.
    pub gate_speed_start_m_s: Option<f64>,
    /// Over the last 16 passes, m/s.
    pub gate_speed_end_m_s: Option<f64>,
}

/// A gate log's analysis: its passes as beats, and the shadows.
#[derive(Clone, Debug, Serialize)]
pub struct GateAnalysis {
    /// The gate log.
    pub photogate: GateLog,
    /// The passes as a beat log.
    #[serde(flatten)]
    pub beats: Beats,
    /// The pass times, s (for plots).
    #[serde(skip)]
    pub pass_times: Vec<f64>,
}

/// Passes over which the start and end shadow widths are averaged.
const ENDS: usize = 16;

/// Analyses a gate log (see the module notes).
pub fn analyse(input: &GateInput<'_>) -> Result<GateAnalysis, Refusal> {
    let n = input.time.len();
    if let Some(g) = input.gate {
        if g.len() != n {
            return Err(Refusal::field(
                "gate",
                format!("has {} values and time {n}: give one of each", g.len()),
            ));
        }
    }
    if let Some(d) = input.bob_diameter {
        require_finite("bob_diameter", d)?;
        if d <= 0.0 {
            return Err(Refusal::field(
                "bob_diameter",
                format!("must be positive, got {d} m"),
            ));
        }
    }
    let labels = |g: &[f64]| {
        let mut seen: Vec<usize> = Vec::new();
        for &v in g {
            let v = v as usize;
            if !seen.contains(&v) {
                seen.push(v);
            }
        }
        seen
    };
    let gates = input.gate.map_or(vec![0], labels);
    let gate = match input.select {
        Some(s) if !gates.contains(&s) => {
            return Err(Refusal::field(
                "gate",
                format!("{s} is not a gate of the log (it has {})", gates.len()),
            ))
        }
        Some(s) => s,
        None => gates[0],
    };
    let events: Vec<(usize, f64)> = input
        .time
        .iter()
        .enumerate()
        .filter(|(i, _)| input.gate.is_none_or(|g| g[*i] as usize == gate))
        .map(|(i, &t)| (i, t))
        .collect();
    for (k, &(i, t)) in events.iter().enumerate() {
        require_finite("time", t).map_err(|r| Refusal::sample("time", i, r.reason))?;
        if k > 0 && t <= events[k - 1].1 {
            return Err(Refusal::sample(
                "time",
                i,
                format!(
                    "the time {t} is not after the gate's previous {}; sort by time",
                    events[k - 1].1
                ),
            ));
        }
    }
    let times: Vec<f64> = events.iter().map(|e| e.1).collect();
    // A bob's diameter says the log holds both edges of each shadow: any
    // alternation of the intervals is then a shadow and a gap.
    let ratio = if input.bob_diameter.is_some() {
        EDGES_GIVEN_RATIO
    } else {
        PAIR_RATIO
    };
    let (passes, widths, unpaired) = pair(&times, ratio);
    if input.bob_diameter.is_some() && widths.is_empty() {
        return Err(Refusal::field(
            "bob_diameter",
            "is for a log of both edges of each shadow; this log's intervals do not \
             alternate short and long, so it holds one event a pass",
        ));
    }
    let analysis = beats_of(&passes, input.nominal).map_err(|r| match r.place {
        crate::analysis::Place::Sample(f, i) => {
            Refusal::sample(f, events.get(i).map_or(i, |e| e.0), r.reason)
        }
        _ => r,
    })?;
    let mut analysis = analysis;
    if widths.is_empty() {
        if let Some((short, long)) = alternation(&times) {
            if short < ALTERNATION_SAID * long {
                let w = super::beat_log::BeatWarning::EdgesUnpaired { short, long };
                analysis.warning_codes.push(w.code());
                analysis.warnings.push(w);
            }
        }
    }
    let mean = |w: &[f64]| (!w.is_empty()).then(|| w.iter().sum::<f64>() / w.len() as f64);
    let start = &widths[..widths.len().min(ENDS)];
    let end = &widths[widths.len().saturating_sub(ENDS)..];
    let speed = |w: Option<f64>| input.bob_diameter.zip(w).map(|(d, w)| d / w);
    Ok(GateAnalysis {
        photogate: GateLog {
            gate,
            gates: gates.len(),
            events: times.len(),
            edges_paired: !widths.is_empty(),
            passes: passes.len(),
            unpaired_edges: unpaired,
            pulse_width_ms: mean(&widths).map(|w| 1e3 * w),
            pulse_width_start_ms: mean(start).map(|w| 1e3 * w),
            pulse_width_end_ms: mean(end).map(|w| 1e3 * w),
            gate_speed_start_m_s: speed(mean(start)),
            gate_speed_end_m_s: speed(mean(end)),
        },
        beats: analysis,
        pass_times: passes,
    })
}

/// Pairs a gate's events into shadows: `(pass times, widths, lone
/// edges)`; one pass an event (no widths) when the median intervals of
/// the two parities are not in a ratio below `pair_ratio`.
pub fn pair(times: &[f64], pair_ratio: f64) -> (Vec<f64>, Vec<f64>, usize) {
    let Some((short, long)) = alternation(times) else {
        return (times.to_vec(), Vec::new(), 0);
    };
    if !(short > 0.0 && short < pair_ratio * long) {
        return (times.to_vec(), Vec::new(), 0);
    }
    let threshold = (short * long).sqrt();
    let (mut passes, mut widths, mut lone) = (Vec::new(), Vec::new(), 0);
    let mut i = 0;
    while i < times.len() {
        match times.get(i + 1) {
            Some(&next) if next - times[i] < threshold => {
                passes.push(0.5 * (times[i] + next));
                widths.push(next - times[i]);
                i += 2;
            }
            _ => {
                lone += 1;
                i += 1;
            }
        }
    }
    (passes, widths, lone)
}

/// The median intervals of the two parities, shorter first; `None` for
/// fewer than four events.
fn alternation(times: &[f64]) -> Option<(f64, f64)> {
    let d: Vec<f64> = times.windows(2).map(|w| w[1] - w[0]).collect();
    if d.len() < 3 {
        return None;
    }
    let mut even: Vec<f64> = d.iter().step_by(2).copied().collect();
    let mut odd: Vec<f64> = d.iter().skip(1).step_by(2).copied().collect();
    let (e, o) = (median(&mut even), median(&mut odd));
    Some((e.min(o), e.max(o)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two gates side by side under a pendulum of 1.172 s period, beat
    /// error 1 ms: each pass cuts gate 0 then gate 1 going one way, gate 1
    /// then gate 0 coming back, each shadow 26.5 ms wide (the layout of
    /// grahamwwilson/PendDataSimComp's Run76).
    fn two_gates(passes: usize) -> (Vec<f64>, Vec<f64>) {
        let (beat, error, width, apart) = (0.586, 1e-3, 0.0265, 0.05);
        let mut events: Vec<(f64, f64)> = Vec::new();
        for k in 0..passes {
            let centre = k as f64 * beat + if k % 2 == 0 { error } else { -error };
            let (first, second) = if k % 2 == 0 { (0.0, 1.0) } else { (1.0, 0.0) };
            for (gate, at) in [
                (first, centre - apart / 2.0),
                (second, centre + apart / 2.0),
            ] {
                events.push((at - width / 2.0, gate));
                events.push((at + width / 2.0, gate));
            }
        }
        events.sort_by(|a, b| a.0.total_cmp(&b.0));
        events.into_iter().unzip()
    }

    #[test]
    fn two_gates_give_passes_and_shadows() {
        let (t, g) = two_gates(200);
        let r = analyse(&GateInput {
            time: &t,
            gate: Some(&g),
            bob_diameter: Some(0.05),
            ..Default::default()
        })
        .unwrap();
        let p = &r.photogate;
        assert_eq!((p.gates, p.passes, p.unpaired_edges), (2, 200, 0));
        assert!(p.edges_paired);
        assert!((p.pulse_width_ms.unwrap() - 26.5).abs() < 1e-9);
        assert!((p.gate_speed_start_m_s.unwrap() - 0.05 / 0.0265).abs() < 1e-9);
        // Gate 0 is cut 25 ms before the centre one way and 25 ms after it
        // the other: its intervals are 586 - 2 + 50 and 586 + 2 - 50 ms,
        // a beat error (half their difference) of 48 ms.
        assert!(
            (r.beats.mean_beat_s - 0.586).abs() < 1e-6,
            "{}",
            r.beats.mean_beat_s
        );
        assert!(
            (r.beats.beat_error_ms - 48.0).abs() < 1e-6,
            "{}",
            r.beats.beat_error_ms
        );
    }

    #[test]
    fn a_lost_edge_is_left_out_and_counted() {
        let (mut t, mut g) = two_gates(100);
        // Drop the second edge of gate 0's 40th shadow.
        let idx: Vec<usize> = (0..t.len()).filter(|&i| g[i] == 0.0).collect();
        let lost = idx[2 * 40 + 1];
        t.remove(lost);
        g.remove(lost);
        let r = analyse(&GateInput {
            time: &t,
            gate: Some(&g),
            ..Default::default()
        })
        .unwrap();
        assert_eq!(r.photogate.unpaired_edges, 1);
        assert_eq!(r.beats.repaired.missed, 1);
        assert!((r.beats.mean_beat_s - 0.586).abs() < 1e-6);
    }

    /// A seconds pendulum at 3° with a 5 cm bob: each shadow lasts 306 ms
    /// of a 1 s beat. With the diameter given they are paired; without,
    /// the alternation is said.
    #[test]
    fn long_shadows_are_paired_when_the_bob_is_given() {
        let (beat, width) = (1.000362, 0.306);
        let mut t = Vec::new();
        for k in 0..60 {
            let centre = k as f64 * beat + if k % 2 == 0 { 0.004 } else { -0.004 };
            t.extend([centre - width / 2.0, centre + width / 2.0]);
        }
        let r = analyse(&GateInput {
            time: &t,
            bob_diameter: Some(0.05),
            ..Default::default()
        })
        .unwrap();
        assert_eq!(r.photogate.passes, 60);
        assert!((r.beats.mean_beat_s - beat).abs() < 1e-9);
        assert!(
            (r.beats.beat_error_ms - 8.0).abs() < 1e-6,
            "{}",
            r.beats.beat_error_ms
        );
        let r = analyse(&GateInput {
            time: &t,
            ..Default::default()
        })
        .unwrap();
        // (Both edges taken for beats also scatter each side's intervals.)
        assert!(
            r.beats.warning_codes.contains(&"edges_unpaired"),
            "{:?}",
            r.beats.warning_codes
        );
    }

    #[test]
    fn one_event_a_pass_is_a_beat_log() {
        let t: Vec<f64> = (0..100).map(|k| k as f64 * 0.5).collect();
        let r = analyse(&GateInput {
            time: &t,
            ..Default::default()
        })
        .unwrap();
        assert!(!r.photogate.edges_paired);
        assert_eq!(r.photogate.passes, 100);
        assert!(r.photogate.pulse_width_ms.is_none());
    }

    #[test]
    fn refusals_name_the_field() {
        let (t, g) = two_gates(20);
        let bad = |input: GateInput<'_>| analyse(&input).unwrap_err().field_name();
        assert_eq!(
            bad(GateInput {
                time: &t,
                gate: Some(&g[1..]),
                ..Default::default()
            }),
            Some("gate")
        );
        assert_eq!(
            bad(GateInput {
                time: &t,
                gate: Some(&g),
                select: Some(5),
                ..Default::default()
            }),
            Some("gate")
        );
        assert_eq!(
            bad(GateInput {
                time: &t,
                bob_diameter: Some(-1.0),
                ..Default::default()
            }),
            Some("bob_diameter")
        );
        let mut back = t.clone();
        back[7] = back[3];
        assert_eq!(
            bad(GateInput {
                time: &back,
                ..Default::default()
            }),
            Some("time")
        );
    }
}
