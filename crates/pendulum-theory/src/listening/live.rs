//! Listening live: the samples come as a sound card or a pipe gives them,
//! once, and are let go; the windows of the recording
//! ([`super::windows`]) come out as they complete, and the whole
//! recording's analysis at the end, as [`super::analysis::listen`] gives
//! it for a file.
//!
//! How: the first [`LEARN_S`] s are kept and analysed as a file's first
//! minutes are (the beat, and its half; whether each beat has two sounds
//! and at what spacing: [`super::detect::EventRule`]). From then on the
//! passes a file gets one after the other run side by side on each block:
//! the envelope, the tracker (each beat settled on one event by the rule
//! the first seconds gave, and handed on a few dozen beats later, when the
//! line filters have seen the beats after it), and the refiner (holding
//! the band-passed samples from the last onset handed on). The memory is
//! those samples (a few dozen beats), the first seconds while they are
//! learnt, and a few hundred bytes per tick; not the recording.
//!
//! What differs from a file: a file's beat and event rule come from its
//! first five minutes and all its beats, a live recording's from its first
//! [`LEARN_S`] s; on a steady recording the ticks are the same (see the
//! command line's pipe test, which compares the two whole).

use super::analysis::{
    check, check_every, conclude, first_beat, half_beat, listen, Checked, FirstPass, Heard,
    ListenInput, Listening, Oscillator, SliceSource, ENVELOPE_BLOCK,
};
use super::detect::{envelope_rate, Envelope, Gate, OnsetTracker, Refiner};
use super::filter::{BandPass, WIDE_HIGH_PASS_HZ};
use super::quality::Quality;
use super::windows::{window_of, Window, WindowInput, CLEAN_REACH};
use crate::analysis::Refusal;
use crate::fitting::beats::nearest_standard;

/// Seconds of sound learnt before the ticks are followed.
pub const LEARN_S: f64 = 30.0;

/// While the first [`LEARN_S`] are learnt, a provisional reading is tried
/// after this many seconds and every as many after (a watch beats 40 to
/// 160 times in them; a seconds clock's comes when the learning ends).
pub const PROVISIONAL_S: f64 = 8.0;

/// The fewest beats a provisional reading is given from.
pub const PROVISIONAL_BEATS: usize = 24;

/// How long after a window's end its ticks are awaited beyond it for the
/// clean-up (each tick checked against its side's neighbours,
/// [`CLEAN_REACH`] beats either way in a file), s, if less: past
/// its end the clean-up's predictions are carried from the ticks before
/// (on a steady clock the same to microseconds), and a window is printed
/// within a few seconds of its end, not a minute.
pub const WINDOW_WAIT_S: f64 = 0.5;

/// A first reading while the listener learns, from the envelope's onsets
/// of the seconds heard so far (each to a fraction of a millisecond, where
/// the windows and the end time each tick to microseconds): a provisional
/// beat and rate, refined as the listening goes on.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Provisional {
    /// The seconds of sound it is from.
    pub after_s: f64,
    /// Beats heard in them.
    pub beats: usize,
    /// The beat rate heard, beats an hour.
    pub beats_per_hour: f64,
    /// The rate against the nominal beat (given, or the standard one
    /// within 2%), s/day; `None` without one.
    pub rate_s_per_day: Option<f64>,
    /// Its standard error, s/day.
    pub rate_se_s_per_day: Option<f64>,
    /// The beat error, ms.
    pub beat_error_ms: f64,
}

/// A recording listened to as it comes: [`LiveListener::push`] its
/// samples, then [`LiveListener::finish`].
pub struct LiveListener {
    input: ListenInput,
    checked: Checked,
    sample_rate: u32,
    /// Samples pushed.
    samples: u64,
    stage: Stage,
    /// Provisional readings tried.
    tries: usize,
    /// A provisional reading not yet taken, and whether one was given.
    provisional: Option<Provisional>,
    read: bool,
}

/// What the first seconds give: the beat, the tracker's pass over them at
/// it, and the envelope's floor.
struct Learnt {
    beat: f64,
    coarse: super::detect::Coarse,
    floor: Option<f64>,
}

enum Stage {
    /// The first seconds, kept.
    Learning(Vec<f32>),
    Following(Box<Following>),
}

struct Following {
    env: Envelope,
    /// Sounds that are not ticks cut out before the tracker.
    gate: Gate,
    tracker: OnsetTracker,
    refiner: Refiner,
    /// Clipping and hum.
    quality: Quality,
    beat: f64,
    /// The beat the windows' rates are against, s.
    nominal_beat: Option<f64>,
    oscillator: Oscillator,
    /// The next window to complete.
    next_window: usize,
}

impl LiveListener {
    /// A listener to samples at `sample_rate` Hz, for `input` (checked as
    /// [`listen`] checks it).
    pub fn new(sample_rate: u32, input: &ListenInput) -> Result<Self, Refusal> {
        if sample_rate == 0 {
            return Err(Refusal::field("sample_rate", "must be positive, got 0"));
        }
        Ok(Self {
            input: *input,
            checked: check(input)?,
            sample_rate,
            samples: 0,
            stage: Stage::Learning(Vec::new()),
            tries: 0,
            provisional: None,
            read: false,
        })
    }

    /// The provisional reading, once, when the first seconds give one
    /// (see [`Provisional`]); `None` before and after.
    pub fn take_provisional(&mut self) -> Option<Provisional> {
        self.provisional.take()
    }

    /// The recording's length so far, s.
    pub fn duration(&self) -> f64 {
        self.samples as f64 / f64::from(self.sample_rate)
    }

    /// Takes the next samples (finite: a sample that is not is refused);
    /// returns the windows (with [`ListenInput::every`]) they complete,
    /// oldest first. A recording whose first seconds show no clock is
    /// refused here, as [`listen`] refuses it.
    pub fn push(&mut self, block: &[f32]) -> Result<Vec<Window>, Refusal> {
        if let Some(i) = block.iter().position(|x| !x.is_finite()) {
            return Err(Refusal::field(
                "samples",
                format!(
                    "must be finite, got {} at sample {}",
                    block[i],
                    self.samples + i as u64
                ),
            ));
        }
        self.samples += block.len() as u64;
        let rate = f64::from(self.sample_rate);
        let heard = match &mut self.stage {
            Stage::Learning(kept) => {
                kept.extend_from_slice(block);
                kept.len() as f64 / rate
            }
            Stage::Following(f) => {
                f.push(block);
                return Ok(self.completed(false));
            }
        };
        if heard < LEARN_S {
            if !self.read && heard >= (self.tries + 1) as f64 * PROVISIONAL_S {
                self.tries += 1;
                if let Stage::Learning(kept) = &self.stage {
                    // (Refused here is not refused: more seconds may tell.)
                    if let Ok(learnt) = self.first_seconds(kept) {
                        self.provide(&learnt, heard);
                    }
                }
            }
            return Ok(Vec::new());
        }
        let Stage::Learning(kept) = &mut self.stage else {
            unreachable!("learning until here")
        };
        let kept = std::mem::take(kept);
        let learnt = self.first_seconds(&kept)?;
        if !self.read {
            self.provide(&learnt, heard);
        }
        let mut following = self.learn(learnt)?;
        following.push(&kept);
        self.stage = Stage::Following(Box::new(following));
        Ok(self.completed(false))
    }

    /// Keeps the provisional reading of `learnt` from `heard` s, if its
    /// onsets give one ([`PROVISIONAL_BEATS`] at least).
    fn provide(&mut self, learnt: &Learnt, heard: f64) {
        let onsets = &learnt.coarse.onsets;
        // (Windows the beat refuses are refused when the learning ends:
        // nothing is said before that refusal.)
        let refused = self
            .input
            .every
            .is_some_and(|every| check_every(every, learnt.beat).is_err());
        if onsets.len() < PROVISIONAL_BEATS || refused {
            return;
        }
        let nominal = self.nominal_beat(learnt.beat);
        let Ok(a) = super::analysis::analyse_numbered(onsets, learnt.beat, nominal) else {
            return;
        };
        if !(a.mean_beat.is_finite() && a.mean_beat > 0.0) {
            return;
        }
        self.provisional = Some(Provisional {
            after_s: heard,
            beats: onsets.len(),
            beats_per_hour: 3600.0 / a.mean_beat,
            rate_s_per_day: a.rate_s_per_day.filter(|r| r.is_finite()),
            rate_se_s_per_day: a
                .rate_s_per_day
                .map(|_| a.rate_se_s_per_day)
                .filter(|s| s.is_finite()),
            beat_error_ms: a.beat_error_ms,
        });
        self.read = true;
    }

    /// The beat the rates are against: half the period given, or the
    /// standard beat near `beat`.
    fn nominal_beat(&self, beat: f64) -> Option<f64> {
        self.checked
            .nominal
            .map(|p| 0.5 * p)
            .or_else(|| nearest_standard(beat))
    }

    /// The first seconds: the beat and its half (as [`listen`] finds them
    /// on a file's first minutes) and the tracker's pass at that beat.
    fn first_seconds(&self, samples: &[f32]) -> Result<Learnt, Refusal> {
        let rate = f64::from(self.sample_rate);
        let mut env = Envelope::new(rate);
        let mut wide = Envelope::with_filter(rate, BandPass::from(WIDE_HIGH_PASS_HZ, rate));
        env.push(samples);
        wide.push(samples);
        let env_rate = envelope_rate(&env, rate);
        let FirstPass {
            gated,
            searched,
            wide,
            floor,
            cuts,
        } = FirstPass::of(&env.values, &wide.values, env_rate);
        let track = |beat: f64| {
            let mut tracker = OnsetTracker::new(env_rate, beat);
            tracker.cut(&cuts);
            for block in gated.chunks(ENVELOPE_BLOCK) {
                tracker.push(block);
            }
            tracker.finish()
        };
        let mut beat = first_beat(&searched, env_rate, &self.input, &self.checked)?;
        let mut coarse = track(beat);
        if let Some(half) = half_beat(&searched, &wide, env_rate, &coarse, beat, &self.input)? {
            beat = half;
            coarse = track(beat);
        }
        Ok(Learnt {
            beat,
            coarse,
            floor,
        })
    }

    /// The listening set up from the first seconds `learnt`: the beat, the
    /// rule of one event a beat, the gate's floor.
    fn learn(&self, learnt: Learnt) -> Result<Following, Refusal> {
        let rate = f64::from(self.sample_rate);
        let env_rate = envelope_rate(&Envelope::new(rate), rate);
        let Learnt {
            beat,
            coarse,
            floor,
        } = learnt;
        if let Some(every) = self.input.every {
            check_every(every, beat)?;
        }
        Ok(Following {
            env: Envelope::new(rate),
            gate: Gate::new(env_rate, floor),
            tracker: OnsetTracker::following(env_rate, beat, coarse.rule),
            refiner: Refiner::following(rate, coarse.timing, coarse.drops),
            quality: Quality::new(rate),
            beat,
            nominal_beat: self.nominal_beat(beat),
            oscillator: self
                .input
                .oscillator
                .unwrap_or_else(|| Oscillator::of_beat(beat)),
            next_window: 0,
        })
    }

    /// The windows whose ticks, and the ticks the clean-up needs around
    /// them, are all refined (all that are left at the `end`).
    fn completed(&mut self, end: bool) -> Vec<Window> {
        let (Some(every), Stage::Following(f)) = (self.input.every, &mut self.stage) else {
            return Vec::new();
        };
        let scale = 1.0 / (1.0 + self.checked.ppm * 1e-6);
        let duration = self.samples as f64 / f64::from(self.sample_rate) * scale;
        let reach = ((CLEAN_REACH as f64 + 1.0) * f.beat).min(WINDOW_WAIT_S);
        let mut out = Vec::new();
        loop {
            let start = f.next_window as f64 * every;
            let last = (f.next_window as f64 + 1.0) * every;
            let whole = last / scale + reach <= f.refiner.refined_until();
            if !(whole || end && start < duration) {
                break;
            }
            let ticks = f.refiner.ticks();
            let from = ticks.partition_point(|t| t.time < start / scale - reach);
            let to = ticks.partition_point(|t| t.time < last / scale + reach);
            let input = WindowInput {
                ticks: &[],
                levels: f.tracker.levels(),
                spacings: f.tracker.spacings(),
                every,
                duration: if whole { last } else { duration },
                nominal_beat: f.nominal_beat,
                lift_angle: self.input.lift_angle,
                oscillator: f.oscillator,
                scale,
            };
            out.push(window_of(&input, ticks[from..to].to_vec(), f.next_window));
            f.next_window += 1;
        }
        out
    }

    /// Ends the recording: the whole of it analysed, as [`listen`] would a
    /// file of it (a recording shorter than [`LEARN_S`] is one).
    pub fn finish(self) -> Result<Listening, Refusal> {
        let rate = f64::from(self.sample_rate);
        let f = match self.stage {
            Stage::Learning(kept) => {
                let mut source = SliceSource {
                    samples: &kept,
                    rate: self.sample_rate,
                };
                return listen(&mut source, &self.input).map_err(|f| match f {
                    super::analysis::ListenFailure::Refused(r) => r,
                    super::analysis::ListenFailure::Source(never) => match never {},
                });
            }
            Stage::Following(f) => *f,
        };
        let Following {
            mut gate,
            mut tracker,
            mut refiner,
            quality,
            beat,
            ..
        } = f;
        let rest = gate.finish();
        let cuts = gate.spans_s();
        tracker.cut(&cuts);
        tracker.push(&rest);
        let given = tracker.handed();
        let coarse = tracker.finish();
        refiner.push_onsets(&coarse.onsets[given..], 0.0);
        refiner.push(&[]);
        let (ticks, _, sounds) = refiner.finish_with_sounds();
        conclude(
            Heard {
                coarse,
                ticks,
                sounds,
                duration: self.samples as f64 / rate,
                beat,
                sample_rate: self.sample_rate,
                cuts,
                quality: Some(quality.finish()),
            },
            &self.checked,
            &self.input,
        )
    }
}

impl Following {
    /// A block through the envelope, the tracker and the refiner.
    fn push(&mut self, block: &[f32]) {
        self.env.push(block);
        let gated = self.gate.push(&self.env.values);
        self.tracker.cut(&self.gate.spans_s());
        self.tracker.push(&gated);
        self.env.values.clear();
        let onsets = self.tracker.take_onsets();
        self.refiner.push_onsets(&onsets, self.tracker.horizon());
        self.refiner.push(block);
        self.quality.push(block);
    }
}
