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
    check, check_every, conclude, first_beat, half_beat, listen, shift_tocks, Checked, FirstPass,
    Heard, ListenInput, Listening, Oscillator, SideOffsets, SliceSource, ENVELOPE_BLOCK,
};
use super::detect::{
    envelope_rate, one_sound, Cleaner, Envelope, Gate, OnsetTracker, Refined, Refiner, Tick,
};
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
    /// Samples per second.
    rate: f64,
    beat: f64,
    /// The beat the windows' rates are against, s.
    nominal_beat: Option<f64>,
    oscillator: Oscillator,
    /// The ticks refined, cleaned as they come.
    cleaner: Cleaner,
    /// The ticks kept, and their offsets from the tracker's onsets.
    ticks: Vec<Tick>,
    sides: SideOffsets,
    /// Whether the two sides sound different (known once their median
    /// sounds are): the tocks are then aligned on the ticks.
    differ: Option<bool>,
    /// The shift of the tocks, and the ticks it was found from (found
    /// again when they have grown by a tenth).
    shift: (usize, f64),
    /// The windows cut so far, and the next to complete.
    windows: Vec<Window>,
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
                return Ok(self.completed());
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
        Ok(self.completed())
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
            rate,
            beat,
            nominal_beat: self.nominal_beat(beat),
            oscillator: self
                .input
                .oscillator
                .unwrap_or_else(|| Oscillator::of_beat(beat)),
            cleaner: Cleaner::new(),
            ticks: Vec::new(),
            sides: SideOffsets::default(),
            differ: None,
            shift: (0, 0.0),
            windows: Vec::new(),
            next_window: 0,
        })
    }

    /// The windows whose ticks, and the ticks the clean-up needs around
    /// them, are all refined; each kept for the end.
    fn completed(&mut self) -> Vec<Window> {
        let Stage::Following(f) = &self.stage else {
            return Vec::new();
        };
        let cutting = Cutting::of(self, f.beat, false);
        let Stage::Following(f) = &mut self.stage else {
            unreachable!("following")
        };
        let Some(cutting) = cutting else {
            // (No window needs a level.)
            f.tracker.let_go_levels(u64::MAX);
            return Vec::new();
        };
        let out = f.cut(&cutting, None);
        // (The levels of the windows cut are let go of.)
        let next = f.next_window as f64 * cutting.every / cutting.scale - cutting.reach;
        let from = f.ticks.partition_point(|t| t.time < next);
        if let Some(t) = f.ticks.get(from) {
            f.tracker.let_go_levels(t.beat);
        }
        out
    }

    /// Ends the recording: the whole of it analysed, as [`listen`] would a
    /// file of it (a recording shorter than [`LEARN_S`] is one), but for
    /// the windows, which are those cut as it went and the last.
    pub fn finish(self) -> Result<Listening, Refusal> {
        let rate = f64::from(self.sample_rate);
        let cutting = match &self.stage {
            Stage::Following(f) => Cutting::of(&self, f.beat, true),
            Stage::Learning(_) => None,
        };
        let mut f = match self.stage {
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
        let rest = f.gate.finish();
        let cuts = f.gate.spans_s();
        let Following {
            tracker, refiner, ..
        } = &mut f;
        let mut tracker = std::mem::replace(tracker, OnsetTracker::new(rate, 1.0));
        tracker.cut(&cuts);
        tracker.push(&rest);
        let coarse = tracker.finish();
        let mut refiner = std::mem::replace(
            refiner,
            Refiner::following(rate, coarse.timing, coarse.drops),
        );
        refiner.push_onsets(&coarse.onsets, 0.0);
        refiner.push(&[]);
        let (refined, _, sounds) = refiner.finish_with_sounds();
        f.differ = sounds.as_ref().map(|pair| !one_sound(pair, rate));
        f.take(refined, true);
        if let Some(c) = cutting {
            f.cut(&c, Some(&coarse));
        }
        conclude(
            Heard {
                ticks: f.ticks,
                sides: f.sides,
                windows: self.input.every.map(|_| f.windows),
                sounds,
                duration: self.samples as f64 / rate,
                beat: f.beat,
                sample_rate: self.sample_rate,
                cuts,
                quality: Some(f.quality.finish()),
                coarse,
            },
            &self.checked,
            &self.input,
        )
    }
}

/// What the windows are cut by.
#[derive(Clone, Copy)]
struct Cutting {
    every: f64,
    /// The sound card's time scale (see [`WindowInput::scale`]).
    scale: f64,
    /// The recording's length so far, rescaled, s.
    duration: f64,
    /// How long after a window's end its ticks are awaited, s.
    reach: f64,
    lift_angle: Option<f64>,
    /// Whether the recording has ended (the last windows are cut).
    end: bool,
}

impl Cutting {
    /// For `listener` at the beat `beat` s, or at its `end`, if it cuts
    /// windows.
    fn of(listener: &LiveListener, beat: f64, end: bool) -> Option<Self> {
        let scale = 1.0 / (1.0 + listener.checked.ppm * 1e-6);
        Some(Self {
            every: listener.input.every?,
            scale,
            duration: listener.duration() * scale,
            reach: ((CLEAN_REACH as f64 + 1.0) * beat).min(WINDOW_WAIT_S),
            lift_angle: listener.input.lift_angle,
            end,
        })
    }
}

impl Following {
    /// A block through the envelope, the tracker, the refiner and the
    /// clean-up.
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
        let refined = self.refiner.take_ticks();
        self.take(refined, false);
    }

    /// The windows `c` completes (with the levels and spacings of the
    /// tracker's end, if `given`, else the tracker's so far), each kept
    /// for the end.
    fn cut(&mut self, c: &Cutting, given: Option<&super::detect::Coarse>) -> Vec<Window> {
        let mut out = Vec::new();
        loop {
            let start = self.next_window as f64 * c.every;
            let last = (self.next_window as f64 + 1.0) * c.every;
            let whole = last / c.scale + c.reach <= self.refiner.refined_until();
            if !(whole || c.end && start < c.duration) {
                break;
            }
            // The ticks kept, and those the clean-up has not decided yet,
            // decided as if none came after them.
            let from = self
                .ticks
                .partition_point(|t| t.time < start / c.scale - c.reach);
            let to = self
                .ticks
                .partition_point(|t| t.time < last / c.scale + c.reach);
            let mut ticks = self.ticks[from..to].to_vec();
            if to == self.ticks.len() {
                ticks.extend(self.cleaner.provisional().iter().map(|r| r.tick));
            }
            if self.differ == Some(true) {
                if c.end || self.sides.len() * 10 > self.shift.0 * 11 {
                    self.shift = (self.sides.len(), self.sides.shift());
                }
                shift_tocks(&mut ticks, self.shift.1);
            }
            let (levels, spacings) = match given {
                Some(coarse) => (&coarse.levels[..], &coarse.spacings[..]),
                None => (self.tracker.levels(), self.tracker.spacings()),
            };
            let input = WindowInput {
                ticks: &[],
                levels,
                spacings,
                every: c.every,
                duration: if whole && !c.end {
                    last
                } else {
                    c.duration.min(last)
                },
                nominal_beat: self.nominal_beat,
                lift_angle: c.lift_angle,
                oscillator: self.oscillator,
                scale: c.scale,
            };
            let window = window_of(&input, &ticks, self.next_window);
            self.windows.push(window.clone());
            out.push(window);
            self.next_window += 1;
        }
        out
    }

    /// Ticks refined, through the clean-up (all decided at the `end`);
    /// those kept are kept.
    fn take(&mut self, refined: Vec<Refined>, end: bool) {
        for r in refined {
            self.cleaner.push(r);
        }
        if end {
            self.cleaner.finish();
        }
        for r in self.cleaner.take() {
            self.ticks.push(self.sides.add(&r));
        }
        if self.differ.is_none() {
            self.differ = self
                .refiner
                .sounds()
                .map(|pair| !one_sound(&pair, self.rate));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A watch's ticks, cheaply: a 3 kHz burst falling by e every 0.4 ms
    /// each beat, its tocks 0.3 ms late, in a little noise.
    fn watch(rate: u32, bph: f64, seconds: f64) -> Vec<f32> {
        let beat = 3600.0 / bph;
        let mut noise = 0x2545_f491_4f6c_dd1d_u64;
        (0..(seconds * f64::from(rate)) as usize)
            .map(|i| {
                let t = i as f64 / f64::from(rate);
                let k = (t / beat).floor();
                let late = if k as u64 % 2 == 1 { 3e-4 } else { 0.0 };
                let u = t - k * beat - late;
                noise ^= noise << 13;
                noise ^= noise >> 7;
                noise ^= noise << 17;
                let hiss = (noise >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
                let tick = if u >= 0.0 {
                    (u * 3e3 * std::f64::consts::TAU).sin() * (-u / 4e-4).exp()
                } else {
                    0.0
                };
                (0.5 * tick + 0.01 * hiss) as f32
            })
            .collect()
    }

    /// What is held a beat (the tracker's onsets and levels, the refiner's
    /// onsets, the clean-up's ticks) does not grow with the recording: the
    /// most over 36,000 beats is the most over the first 18,000 (before
    /// the clean-up and the trimming of the tracker, six entries a beat
    /// were held to the end); only what the end needs of each tick kept
    /// grows.
    #[test]
    fn what_is_held_does_not_grow_with_the_hours() {
        let rate = 8000;
        let samples = watch(rate, 72_000.0, 1800.0);
        for every in [None, Some(60.0)] {
            let input = ListenInput {
                every,
                ..ListenInput::default()
            };
            let mut listener = LiveListener::new(rate, &input).expect("input");
            let mut most = [0; 2];
            let half = samples.len() / 2;
            for (i, block) in samples.chunks(4000).enumerate() {
                listener.push(block).expect("push");
                if let Stage::Following(f) = &listener.stage {
                    let held = f.tracker.held() + f.refiner.held() + f.cleaner.held();
                    let m = &mut most[usize::from(i * 4000 >= half)];
                    *m = (*m).max(held);
                }
            }
            let end = listener.finish().expect("finish");
            assert!(
                end.ticks.len() > 35_000,
                "{every:?}: {} ticks",
                end.ticks.len()
            );
            assert!(
                most[1] <= most[0] + most[0] / 10,
                "{every:?}: at most {} entries held in the first 15 minutes, {} in the next",
                most[0],
                most[1]
            );
        }
    }
}
