//! Listening as one analysis: a recording (any source of sample blocks
//! that can be read more than once) in, what a timegrapher shows out. The
//! command line's `listen` (its source decodes a sound file) and Python's
//! `listen` (its source is an array) are this call, and so are the
//! library's listening tests.
//!
//! The passes ([`super::detect`]): the beat from the envelope of the first
//! [`PERIOD_SPAN_S`] s, near the nominal beat when one is given
//! ([`NOMINAL_SLACK`]; a nominal beat that is not the recording's, half or
//! double it, is refused as `fit beats` refuses it); each beat's onset on the envelope, streamed; each
//! tick refined on the samples; outliers dropped; then the beat analysis
//! ([`crate::fitting::beats`]) of the tick times, rescaled by the sound
//! card's clock error, with missed beats filled in up to
//! [`MAX_FILLED_BEATS`]. The lift angle, if given, turns the time from the
//! unlocking to the drop into an amplitude ([`crate::lift`]).

use super::detect::{
    beat_period, clean, envelope_rate, Coarse, Envelope, Gate, MedianSound, OnsetTracker, Refined,
    Refiner, Tick, Timing,
};
use super::doctor::findings;
use super::filter::{BandPass, WIDE_HIGH_PASS_HZ};
use super::quality::{Measured, Quality};
use super::windows::{windows, Window, WindowInput, WindowTotals, MIN_WINDOW_BEATS};
use super::{check_nominal_period, BEAT_RANGE_S};
use crate::analysis::{require_finite, require_finite_sample, Refusal};
use crate::error::format_significant;
use crate::findings::Finding;
use crate::fitting::beat_log::{check_nominal, BeatWarning, Beats, Nominal, REPEATS_EXACTLY_S};
use crate::fitting::beats::{BeatAnalysis, BeatStream};
use crate::lift::amplitude_from_lift;
use crate::period::period_for_beat_rate;
use crate::warning::Warn;
use serde::Serialize;

/// Seconds of the recording the beat is found from.
pub const PERIOD_SPAN_S: f64 = 300.0;
/// How far from a nominal beat the beat is looked for, as a fraction (a
/// clock 3% off is 43 minutes a day off).
pub const NOMINAL_SLACK: f64 = 0.03;
/// Gaps of up to this many beats are missed beats, not pauses: the ticks
/// were followed beat by beat through any stretch the noise covered.
pub const MAX_FILLED_BEATS: usize = 1000;
/// The largest sound-card clock error taken, ppm.
pub const MAX_SAMPLE_RATE_ERROR_PPM: f64 = 1e4;
/// The fewest ticks analysed.
pub const MIN_TICKS: usize = 4;
/// Ticks kept on the fewer side below this fraction of the other side's
/// are every other beat: refused.
pub const ONE_SIDE: f64 = 0.25;
/// Ticks kept below this fraction of the beats between the first and the
/// last are a beat not followed: refused.
pub const HEARD_FRACTION: f64 = 0.25;
/// Envelope values the tracker is given at a time when the envelope is
/// in memory (as a decoder's packets give them).
pub(crate) const ENVELOPE_BLOCK: usize = 256;
/// Samples per block of [`SliceSource`] (as a decoder's packets).
pub const SLICE_BLOCK: usize = 4096;

/// A recording, read from its start as often as the analysis needs.
pub trait SampleSource {
    /// What reading can fail with.
    type Error;
    /// Samples per second.
    fn sample_rate(&self) -> u32;
    /// Hands `each` the samples in blocks from the start: all of them, or
    /// at least the first `seconds` (more is cut off here).
    fn read(
        &mut self,
        seconds: Option<f64>,
        each: &mut dyn FnMut(&[f32]),
    ) -> Result<(), Self::Error>;
}

/// Samples in memory as a source, in blocks of [`SLICE_BLOCK`].
pub struct SliceSource<'a> {
    /// The samples.
    pub samples: &'a [f32],
    /// Samples per second.
    pub rate: u32,
}

impl SampleSource for SliceSource<'_> {
    type Error = std::convert::Infallible;

    fn sample_rate(&self) -> u32 {
        self.rate
    }

    fn read(
        &mut self,
        seconds: Option<f64>,
        each: &mut dyn FnMut(&[f32]),
    ) -> Result<(), Self::Error> {
        let n = seconds.map_or(self.samples.len(), |s| {
            self.samples
                .len()
                .min((s * f64::from(self.rate)).ceil() as usize)
        });
        for block in self.samples[..n].chunks(SLICE_BLOCK) {
            each(block);
        }
        Ok(())
    }
}

pub use crate::oscillator::{Oscillator, BALANCE_ABOVE_BPH};

/// What to listen for.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ListenInput {
    /// The beat the clock is meant to keep (else found, and the rate
    /// against the nearest standard rate).
    pub nominal: Option<Nominal>,
    /// The sound card's clock error, ppm (positive: its clock runs fast),
    /// default 0.
    pub sample_rate_error_ppm: Option<f64>,
    /// The escapement's lift angle, rad, for the amplitude.
    pub lift_angle: Option<f64>,
    /// What swings (else chosen by the beat: [`Oscillator::of_beat`]).
    pub oscillator: Option<Oscillator>,
    /// Cut the recording into windows of this many seconds, each analysed
    /// on its own ([`super::windows`]); at least [`MIN_WINDOW_BEATS`]
    /// beats long.
    pub every: Option<f64>,
}

/// Why listening failed: the input, or the source.
#[derive(Debug)]
pub enum ListenFailure<E> {
    /// An input or the recording refused.
    Refused(Refusal),
    /// The source could not be read.
    Source(E),
}

impl<E> From<Refusal> for ListenFailure<E> {
    fn from(r: Refusal) -> Self {
        ListenFailure::Refused(r)
    }
}

/// What listening found, with the units in its keys.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Listening {
    /// Samples per second.
    pub sample_rate_hz: u32,
    /// The sound card's clock error applied to the tick times, ppm.
    pub sample_rate_error_ppm: f64,
    /// The recording's length, s.
    pub duration_s: f64,
    /// What a timegrapher shows of the tick times (its `repaired` the
    /// same as `missed` by the stream's own count and `extra`).
    #[serde(flatten)]
    pub beats: Beats,
    /// The split of the two intervals, % (50/50 is in beat).
    pub in_beat_percent: [f64; 2],
    /// Beats between the first tick kept and the last with no tick kept
    /// (no sound, or noise dropped), but for those in `cut_s`.
    pub missed: usize,
    /// Spans cut out as sounds that are not ticks (warning `sounds_cut`),
    /// s from the start: `[from, to]`.
    pub cut_s: Vec<[f64; 2]>,
    /// The clock's beats inside `cut_s` (not in `missed`).
    pub cut_beats: usize,
    /// Spans outside `cut_s` where no tick was heard (warning
    /// `clock_lost`), s from the start: `[from, to]`.
    pub lost_s: Vec<[f64; 2]>,
    /// Doubled beats dropped.
    pub extra: usize,
    /// Tick envelope peak over the envelope's median, dB.
    pub snr_db: f64,
    /// What each tick's time is: `unlocking` (two sounds a beat, every
    /// beat timed on the first, the drop from it; a beat whose second
    /// sound was not heard is left out) or `one_sound` (the one sound of
    /// each beat that stands out): never a mixture.
    pub timed_on: Timing,
    /// From each beat's unlocking to its drop, ms: ticks, tocks (null when
    /// no second sound stands out).
    pub drop_ms: [Option<f64>; 2],
    /// The lift angle given, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lift_angle_deg: Option<f64>,
    /// What swings, as given or chosen by the beat rate (a balance above
    /// [`BALANCE_ABOVE_BPH`]): it sets `amplitude_deg`.
    pub oscillator: Oscillator,
    /// Whether the oscillator was chosen by the beat rate (not given).
    pub oscillator_from_beat: bool,
    /// The amplitude: a pendulum's from its exact motion, a balance's from
    /// the harmonic motion (the first-order formula); null when no drop
    /// was heard.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplitude_deg: Option<Option<f64>>,
    /// From the first-order formula lift / (2 sin(π Δt / T)) (a balance's
    /// exact figure, a pendulum's approximation).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplitude_first_order_deg: Option<Option<f64>>,
    /// The recording in windows (with `every`), oldest first.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub windows: Vec<Window>,
    /// The windows' rates summed up.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub window_totals: Option<WindowTotals>,
    /// What the recording shows, with its evidence, meaning and remedy
    /// ([`Finding`]).
    pub findings: Vec<Finding>,
    /// The ticks kept, their times rescaled by the sound card's error.
    #[serde(skip)]
    pub ticks: Vec<Tick>,
    /// The median tick and tock sounds, band-passed.
    #[serde(skip)]
    pub sounds: Option<[MedianSound; 2]>,
}

/// Listens to samples in memory at `sample_rate` Hz (a whole number of
/// samples per second), every one a finite number (Python's `listen`).
///
/// # Examples
///
/// ```
/// use pendulum_theory::listening::analysis::{listen_to_samples, ListenInput};
/// use pendulum_theory::listening::synth::{synthesize, TickRecording};
/// use pendulum_theory::period::Nominal;
///
/// // A minute of a seconds clock gaining 12 s a day, 1.5 ms out of beat, as
/// // the library's synthetic recording makes it (44.1 kHz, 30 dB, a room).
/// let spec = TickRecording { rate_s_per_day: 12.0, beat_error_ms: 1.5, ..TickRecording::DEFAULT };
/// let recording = synthesize(&spec);
/// let input = ListenInput { nominal: Some(Nominal::BeatsPerHour(3600.0)), ..Default::default() };
/// let heard = listen_to_samples(&recording.samples, 44_100.0, &input)?;
/// assert!((heard.beats.rate_s_per_day.unwrap() - 12.0).abs() < 0.1);
/// assert!((heard.beats.beat_error_ms - 1.5).abs() < 0.05);
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn listen_to_samples(
    samples: &[f32],
    sample_rate: f64,
    input: &ListenInput,
) -> Result<Listening, Refusal> {
    let rate = require_finite("sample_rate", sample_rate)?;
    if !(rate >= 1.0 && rate <= f64::from(u32::MAX) && rate.fract() == 0.0) {
        return Err(Refusal::field(
            "sample_rate",
            format!(
                "must be a whole number of samples per second, got {}",
                format_significant(rate, 6)
            ),
        ));
    }
    if let Some(i) = samples.iter().position(|x| !x.is_finite()) {
        require_finite_sample("samples", i, f64::from(samples[i]))?;
    }
    let mut source = SliceSource {
        samples,
        rate: rate as u32,
    };
    listen(&mut source, input).map_err(|f| match f {
        ListenFailure::Refused(r) => r,
        ListenFailure::Source(never) => match never {},
    })
}

/// The nominal period, s, checked against the beats listening finds.
pub(crate) fn nominal_period(nominal: Nominal) -> Result<f64, Refusal> {
    let field = nominal.field();
    let period = match nominal {
        Nominal::Period(p) => require_finite(field, p)?,
        Nominal::BeatsPerHour(b) => period_for_beat_rate(require_finite(field, b)?)
            .map_err(|e| Refusal::input(field, &e))?,
    };
    check_nominal_period(period, matches!(nominal, Nominal::BeatsPerHour(_)))
        .map_err(|e| Refusal::input(field, &e))?;
    Ok(period)
}

/// The inputs checked: the nominal period, s, and the sound card's
/// error, ppm.
pub(crate) struct Checked {
    pub(crate) nominal: Option<f64>,
    pub(crate) ppm: f64,
}

/// Checks what to listen for (each field named in its refusal).
pub(crate) fn check(input: &ListenInput) -> Result<Checked, Refusal> {
    let nominal = input.nominal.map(nominal_period).transpose()?;
    let ppm = require_finite(
        "sample_rate_error_ppm",
        input.sample_rate_error_ppm.unwrap_or(0.0),
    )?;
    if ppm.abs() > MAX_SAMPLE_RATE_ERROR_PPM {
        return Err(Refusal::field(
            "sample_rate_error_ppm",
            format!(
                "must be within ±{MAX_SAMPLE_RATE_ERROR_PPM} ppm, got {}",
                format_significant(ppm, 6)
            ),
        ));
    }
    if let Some(every) = input.every {
        let every = require_finite("every", every)?;
        if every <= 0.0 {
            return Err(Refusal::field(
                "every",
                format!("must be positive, got {} s", format_significant(every, 6)),
            ));
        }
    }
    if let Some(lift) = input.lift_angle {
        if !(lift > 0.0 && lift < std::f64::consts::PI) {
            return Err(Refusal::field(
                "lift_angle",
                format!(
                    "must be between 0 and 180°, got {}°",
                    format_significant(lift.to_degrees(), 6)
                ),
            ));
        }
    }
    Ok(Checked { nominal, ppm })
}

/// The beat, s, from the envelope `env` (at `env_rate` values a second)
/// of the first minutes: near the nominal beat when one is given, else
/// anywhere in [`BEAT_RANGE_S`].
pub(crate) fn first_beat(
    env: &[f32],
    env_rate: f64,
    input: &ListenInput,
    checked: &Checked,
) -> Result<f64, Refusal> {
    let nominal = checked.nominal;
    // The beat as the recording has it, whatever the nominal: a nominal
    // beat double or five times it, or a fifth of it, is refused, not
    // followed (every other tick taken for the beat). A nominal beat half
    // the one found is not refused: the recording cannot tell it from a
    // clock far out of beat (tick and tock 0.18 and 0.22 s apart, found at
    // its tick-tock pair) or one whose tocks are lost in the noise (found
    // at its period): that case is [`half_beat`]'s and the checks of
    // [`conclude`].
    let free = beat_period(env, env_rate, BEAT_RANGE_S.0, BEAT_RANGE_S.1);
    let near = |b: f64| {
        beat_period(
            env,
            env_rate,
            (1.0 - NOMINAL_SLACK) * b,
            (1.0 + NOMINAL_SLACK) * b,
        )
    };
    if let (Some(n), Some(p), Some(measured)) = (input.nominal, nominal, free) {
        // A beat found that is no whole multiple or fraction of the
        // nominal one (to 3%) is not the clock's misnamed (a 0.053 s
        // rhythm of noise and echo for a 1.25 s clock): the nominal beat
        // is looked for where it was given, and refused only if it is not
        // there.
        let ratio = 0.5 * p / measured;
        let related = (1..=6).any(|k| {
            let k = f64::from(k);
            (ratio / k - 1.0).abs() < 0.03 || (ratio * k - 1.0).abs() < 0.03
        });
        if (0.5 * p / measured / 0.5 - 1.0).abs() > 0.1 && (related || near(0.5 * p).is_none()) {
            check_nominal(n, 0.5 * p, measured)?;
        }
    }
    let beat = match nominal {
        Some(p) => {
            let b = 0.5 * p;
            match near(b) {
                Some(found) => found,
                // (A search this narrow can miss a beat the wide one finds.)
                None if free.is_some() => b,
                // Nothing repeats at any beat: the ticks the tracker would
                // find at the nominal beat are the noise's crests.
                None => {
                    return Err(Refusal::data(
                        "no beat stands out of the noise at any beat from 0.05 to 2 s: the \
                         recording is noise or silence, or the clock is too faint in it; record \
                         nearer the clock",
                    ))
                }
            }
        }
        None => beat_period(env, env_rate, BEAT_RANGE_S.0, BEAT_RANGE_S.1).ok_or_else(|| {
            Refusal::data(
                "no regular ticking found (silence, noise, or fewer than four beats); give the \
                     beat rate (bph) if the clock is there",
            )
        })?,
    };
    Ok(by_period(env, env_rate, beat))
}

/// The beat `beat` (s) made half the period found near twice it: a clock
/// out of beat splits the autocorrelation's peak at the beat in two (tick
/// to tock and tock to tick, a beat error apart either way), and the beat
/// found lies on one of them, off by the beat error (8 ms at 18,000 beats
/// an hour read 17,309); tick to tick, a period, no beat error splits.
/// Searched within [`PERIOD_REACH`] of twice the beat.
fn by_period(env: &[f32], env_rate: f64, beat: f64) -> f64 {
    let (lo, hi) = (
        2.0 * beat * (1.0 - PERIOD_REACH),
        2.0 * beat * (1.0 + PERIOD_REACH),
    );
    match beat_period(env, env_rate, lo, hi) {
        Some(period) if (lo..=hi).contains(&period) => 0.5 * period,
        _ => beat,
    }
}

/// How far from twice the beat its period is looked for: a beat error of
/// a tenth of the beat moves each split peak by a tenth.
pub const PERIOD_REACH: f64 = 0.1;

/// The beat against its half: `Some(half the beat)` when a sound stands
/// between every tick and the next of `coarse` (followed at `beat` on the
/// first minutes' envelopes `env` and `wide`); with a nominal beat,
/// refused.
pub(crate) fn half_beat(
    env: &[f32],
    wide: &[f32],
    env_rate: f64,
    coarse: &Coarse,
    beat: f64,
    input: &ListenInput,
) -> Result<Option<f64>, Refusal> {
    // A sound that stands between every tick and the next, aligned on
    // the onsets found, says the beat followed is two of the clock's
    // (every other tick: a clock far out of beat, whose tick-to-tock lag
    // the autocorrelation splits). Followed again at half the beat; with a
    // nominal beat, refused. (Half a beat shorter than any a clock has is
    // not followed.)
    // (Ticks that hardly stand out of the floor are the noise's crests,
    // and what stands between them says nothing of the clock.)
    // (Ticks in strong noise still stand on their line, to a fraction of
    // a ms, where a noise's crests scatter over the tracker's window: a
    // clock at 6 dB, 1.7 to 2.5 dB on the envelope, was read at half its
    // beat.)
    let faint = snr(coarse.peak, coarse.floor) < HALF_BEAT_MIN_SNR_DB
        && onset_scatter(coarse).is_none_or(|s| s > HALF_BEAT_MAX_SCATTER_S);
    if 0.5 * beat < BEAT_RANGE_S.0 / (1.0 + NOMINAL_SLACK)
        || faint
        || !(sound_between_ticks(env, env_rate, coarse)
            || sound_between_ticks(wide, env_rate, coarse))
    {
        return Ok(None);
    }
    let per_hour = |b: f64| format_significant(3600.0 / b, 6);
    if let Some(n) = input.nominal {
        return Err(Refusal::field(
            n.field(),
            format!(
                "the recording beats twice as fast: a sound stands between every two ticks of {} \
                 beats an hour; give {} beats an hour",
                per_hour(beat),
                per_hour(0.5 * beat)
            ),
        ));
    }
    // (The beat followed was the clock's period, found tick to tick where
    // no beat error splits the autocorrelation: its half is the beat; a
    // search near the half would land on one of the split peaks.)
    Ok(Some(0.5 * beat))
}

/// The first pass's envelopes with the sounds that are not ticks cut out
/// ([`Gate`]), each against the floor of its own first minutes (a
/// recording may start with a strike).
pub(crate) struct FirstPass {
    /// The detector's envelope, gated.
    pub(crate) gated: Vec<f32>,
    /// The same with the loud sounds' tails cut too, for the beat search.
    pub(crate) searched: Vec<f32>,
    /// The wide band's, gated.
    pub(crate) wide: Vec<f32>,
    /// The spans cut from the detector's, s.
    pub(crate) cuts: Vec<(f64, f64)>,
    /// The detector's envelope's floor, for the gate of the later passes.
    pub(crate) floor: Option<f64>,
}

impl FirstPass {
    /// The first pass's envelope `env` and wide-band envelope `wide`, at
    /// `env_rate` values a second, gated.
    pub(crate) fn of(env: &[f32], wide: &[f32], env_rate: f64) -> Self {
        let floor = Gate::floor_of(env, env_rate);
        let (gated, cuts) = Gate::apply(env, env_rate, floor, false);
        let (searched, _) = Gate::apply(env, env_rate, floor, true);
        let (wide, _) = Gate::apply(wide, env_rate, Gate::floor_of(wide, env_rate), true);
        Self {
            gated,
            searched,
            wide,
            cuts,
            floor,
        }
    }
}

/// What the passes over a recording heard, for [`conclude`].
pub(crate) struct Heard {
    /// The tracker's onsets and levels.
    pub(crate) coarse: Coarse,
    /// The ticks refined and cleaned ([`clean`]; the sides not yet
    /// aligned).
    pub(crate) ticks: Vec<Tick>,
    /// Their offsets from the tracker's onsets, for the alignment of the
    /// sides.
    pub(crate) sides: SideOffsets,
    /// The windows, where they were cut as the recording went on (live);
    /// `None`: cut here from the ticks.
    pub(crate) windows: Option<Vec<Window>>,
    /// The median tick and tock.
    pub(crate) sounds: Option<[MedianSound; 2]>,
    /// The recording's length, s.
    pub(crate) duration: f64,
    /// The beat followed, s.
    pub(crate) beat: f64,
    /// Samples per second.
    pub(crate) sample_rate: u32,
    /// The spans cut out as not ticks ([`Gate`]), s.
    pub(crate) cuts: Vec<(f64, f64)>,
    /// Clipping and hum, where the samples were all seen.
    pub(crate) quality: Option<Measured>,
}

/// Listens to `source`: see the module notes.
pub fn listen<S: SampleSource>(
    source: &mut S,
    input: &ListenInput,
) -> Result<Listening, ListenFailure<S::Error>> {
    let checked = check(input)?;
    let sample_rate = source.sample_rate();
    let rate = f64::from(sample_rate);
    // Pass 1: the beat, from the envelope of the first minutes (cut at
    // the same sample whatever the source's blocks).
    let span = (PERIOD_SPAN_S * rate) as usize;
    let mut env = Envelope::new(rate);
    // The same in a wider band, for a beat's other side whose sound is
    // mostly below the detector's band (the check of the half beat).
    let mut wide = Envelope::with_filter(rate, BandPass::from(WIDE_HIGH_PASS_HZ, rate));
    let mut pushed = 0usize;
    source
        .read(Some(PERIOD_SPAN_S), &mut |block| {
            let keep = block.len().min(span - pushed);
            env.push(&block[..keep]);
            wide.push(&block[..keep]);
            pushed += keep;
        })
        .map_err(ListenFailure::Source)?;
    let env_rate = envelope_rate(&env, rate);
    let FirstPass {
        gated,
        searched,
        wide,
        cuts: first_cuts,
        floor,
    } = FirstPass::of(&env.values, &wide.values, env_rate);
    let beat = first_beat(&searched, env_rate, input, &checked)?;
    // Pass 2: each beat's onset on the envelope, streamed (a recording
    // within the first pass is not read again).
    let track = |source: &mut S, beat: f64| -> Result<_, ListenFailure<S::Error>> {
        let mut tracker = OnsetTracker::new(env_rate, beat);
        let (samples, cuts) = if pushed < span {
            // (In blocks, as a longer recording's come: the noise floor
            // follows the recording rather than being its last seconds'.)
            tracker.cut(&first_cuts);
            for block in gated.chunks(ENVELOPE_BLOCK) {
                tracker.push(block);
            }
            (env.samples, first_cuts.clone())
        } else {
            let mut env = Envelope::new(rate);
            let mut gate = Gate::new(env_rate, floor);
            source
                .read(None, &mut |block| {
                    env.push(block);
                    let gated = gate.push(&env.values);
                    tracker.cut(&gate.spans_s());
                    tracker.push(&gated);
                    env.values.clear();
                })
                .map_err(ListenFailure::Source)?;
            let rest = gate.finish();
            tracker.cut(&gate.spans_s());
            tracker.push(&rest);
            (env.samples, gate.spans_s())
        };
        Ok((tracker.finish(), samples, cuts))
    };
    let (mut coarse, mut samples, mut cuts) = track(source, beat)?;
    let mut beat = beat;
    if let Some(half) = half_beat(&searched, &wide, env_rate, &coarse, beat, input)? {
        beat = half;
        (coarse, samples, cuts) = track(source, beat)?;
    }
    // Pass 3: each tick refined on the samples.
    let mut refiner = Refiner::new(rate, &coarse);
    let mut quality = Quality::new(rate);
    source
        .read(None, &mut |block| {
            refiner.push(block);
            quality.push(block);
        })
        .map_err(ListenFailure::Source)?;
    // (What the refiner and the clean-up drop is counted below as missed.)
    let (refined, _, sounds) = refiner.finish_with_sounds();
    let (kept, _, _) = clean(refined);
    let mut sides = SideOffsets::default();
    let ticks = kept.iter().map(|r| sides.add(r)).collect();
    let heard = Heard {
        coarse,
        ticks,
        sides,
        windows: None,
        sounds,
        duration: samples as f64 / rate,
        beat,
        sample_rate,
        cuts,
        quality: Some(quality.finish()),
    };
    Ok(conclude(heard, &checked, input)?)
}

/// Refuses ticks kept on one side only, every other beat of `beat` s
/// (the tocks too weak to time, or a beat half the clock's followed):
/// the refusal names the `nominal` beat's field when one was given.
fn refuse_one_side(ticks: &[Tick], beat: f64, nominal: Option<Nominal>) -> Result<(), Refusal> {
    // Both sides in proportion: ticks kept on one side only are every
    // other beat (the tocks too weak to time, or a beat half the clock's
    // followed), and the analysis would fill the other side in as missed
    // beats, with no beat error to show.
    let tocks = ticks.iter().filter(|t| t.side == 1).count();
    let sides = [ticks.len() - tocks, tocks];
    if ticks.len() >= 2 * MIN_TICKS
        && (sides[0].min(sides[1]) as f64) < ONE_SIDE * sides[0].max(sides[1]) as f64
    {
        let per_hour = |b: f64| format_significant(3600.0 / b, 6);
        let cause = match nominal {
            Some(_) => format!(
                "the tocks are too weak to time at this beat, or the clock beats at {} beats an \
                 hour (give that)",
                per_hour(2.0 * beat)
            ),
            None => format!(
                "the tocks are too weak to time, or the clock is far out of beat at {} beats an \
                 hour (give --bph to say which)",
                per_hour(0.5 * beat)
            ),
        };
        let refusal = format!(
            "only every other beat of {} beats an hour stands out ({} ticks on one side, {} on \
             the other): {cause}",
            per_hour(beat),
            sides[0].max(sides[1]),
            sides[0].min(sides[1])
        );
        return Err(match nominal {
            Some(n) => Refusal::field(n.field(), refusal),
            None => Refusal::data(refusal),
        });
    }
    Ok(())
}

/// Refuses ticks that are fewer than [`HEARD_FRACTION`] of the beats
/// between the first and the last: a beat not followed, whatever the
/// `nominal` period (s) and the signal to noise `snr_db` (dB) say.
fn refuse_unfollowed(ticks: &[Tick], nominal: Option<f64>, snr_db: f64) -> Result<(), Refusal> {
    // Most beats between the first tick kept and the last must be heard: a
    // handful of ticks over a stretch where the rest were lost is a beat
    // not followed (a nominal beat searched a percent off, noise), and
    // their rate is anything.
    if let (Some(a), Some(b)) = (ticks.first(), ticks.last()) {
        let spanned = (b.beat - a.beat + 1) as f64;
        if (ticks.len() as f64) < HEARD_FRACTION * spanned {
            let nominal_note = nominal.map_or(String::new(), |p| {
                format!(
                    ", or the clock does not beat at {} beats an hour",
                    format_significant(7200.0 / p, 6)
                )
            });
            return Err(Refusal::data(format!(
                "only {} of the {} beats between the first tick heard and the last stand out of \
                 the noise (signal to noise {} dB): the beat was not followed; record nearer \
                 the clock, or in a quieter room{nominal_note}",
                ticks.len(),
                spanned,
                format_significant(snr_db, 2)
            )));
        }
    }
    Ok(())
}

/// The beats with no tick kept, and the spans of the recording without
/// ticks: what [`Gaps::of`] counts.
struct Gaps {
    /// Beats between the first tick kept and the last with no tick kept,
    /// but for those in the spans cut.
    missed: usize,
    /// The clock's beats inside the spans cut.
    cut_beats: usize,
    /// The spans cut out as sounds that are not ticks, s from the start
    /// (rescaled by the sound card's error, as the ticks are).
    cuts: Vec<(f64, f64)>,
    /// The spans outside `cuts` where no tick was heard (a clock lost), s
    /// from the start (rescaled as `cuts`).
    lost: Vec<(f64, f64)>,
}

impl Gaps {
    /// The [`Gaps`] among `ticks` (numbered at `beat` s, their times as
    /// the samples count them) of a recording `duration` s long with the
    /// spans `cuts` cut out; the spans then rescaled by the sound card's
    /// `scale`, as the ticks are.
    fn of(ticks: &[Tick], cuts: &[(f64, f64)], beat: f64, duration: f64, scale: f64) -> Self {
        // Missed: the beats between the first tick kept and the last with no
        // tick kept (none before the first or after the last: a recording
        // starts and stops where it will).
        let missed = match (ticks.first(), ticks.last()) {
            (Some(a), Some(b)) => ((b.beat - a.beat + 1) as usize).saturating_sub(ticks.len()),
            _ => 0,
        };
        // Beats inside the spans cut are not missed: they are said with the
        // spans.
        let (in_cuts, beside_cuts) = beats_in_cuts(ticks, cuts, beat, duration);
        let missed = missed.saturating_sub(in_cuts);
        let in_cuts = in_cuts + beside_cuts;
        let lost = lost_spans(ticks, cuts, beat, duration);
        // (On the recording's clock, as the ticks are.)
        let scaled = |spans: &[(f64, f64)]| -> Vec<(f64, f64)> {
            spans.iter().map(|&(a, b)| (a * scale, b * scale)).collect()
        };
        Gaps {
            missed,
            cut_beats: in_cuts,
            cuts: scaled(cuts),
            lost: scaled(&lost),
        }
    }
}

/// The drop heard and the amplitude it gives with the lift angle.
struct Swing {
    /// From each beat's unlocking to its drop, s: ticks, tocks (`None`
    /// where no second sound stands out).
    drops: [Option<f64>; 2],
    /// The amplitude from the lift angle and the drop, where the
    /// oscillator can have it.
    amplitude: Option<crate::lift::LiftAmplitude>,
    /// What swings: given, or chosen by the beat.
    oscillator: Oscillator,
    /// An amplitude heard that the oscillator cannot have, rad.
    impossible: Option<f64>,
}

impl Swing {
    /// The [`Swing`] of the tracker's drops in `coarse` (s, rescaled by
    /// the sound card's `scale`) at a mean beat of `mean_beat` s: the
    /// amplitude from the lift angle of `input` and the mean of the two
    /// sides' drops, refused (as `lift_angle`) where no swing crosses
    /// that lift in that time.
    fn heard(
        coarse: &Coarse,
        scale: f64,
        mean_beat: f64,
        input: &ListenInput,
    ) -> Result<Self, Refusal> {
        // The drop: the mean of the two sides' (a clock's pallets may differ).
        let drops = coarse.drops.map(|d| d.map(|d| d * scale));
        let heard: Vec<f64> = drops.iter().flatten().copied().collect();
        let crossing = (!heard.is_empty()).then(|| heard.iter().sum::<f64>() / heard.len() as f64);
        let amplitude = match (input.lift_angle, crossing) {
            (Some(lift), Some(dt)) => Some(
                amplitude_from_lift(lift, dt, 2.0 * mean_beat)
                    .map_err(|e| Refusal::field("lift_angle", e.detail()))?,
            ),
            _ => None,
        };
        let oscillator = input
            .oscillator
            .unwrap_or_else(|| Oscillator::of_beat(mean_beat));
        // An amplitude the oscillator cannot have is not given: warned with
        // its figure.
        let impossible = amplitude
            .as_ref()
            .map(|x| oscillator.amplitude(x))
            .filter(|&swing| swing.is_nan() || swing > oscillator.largest_swing_rad());
        let amplitude = amplitude.filter(|_| impossible.is_none());
        Ok(Swing {
            drops,
            amplitude,
            oscillator,
            impossible,
        })
    }

    /// The amplitude `f` takes from the lift amplitude, degrees, when a
    /// lift angle was given (`lift_angle`, rad): `Some(None)` when no drop
    /// was heard or the oscillator cannot have it.
    fn lifted(
        &self,
        lift_angle: Option<f64>,
        f: &dyn Fn(&crate::lift::LiftAmplitude) -> f64,
    ) -> Option<Option<f64>> {
        lift_angle.map(|_| self.amplitude.as_ref().map(|x| f(x).to_degrees()))
    }
}

/// Refuses a beat error of [`OUT_OF_BEAT`] of the beat or more in the
/// analysis `a`: no running clock's (its escapement would not unlock on
/// that side), so the ticks were numbered on a beat not the clock's.
fn refuse_out_of_beat(a: &BeatAnalysis) -> Result<(), Refusal> {
    // A beat error of a fifth of the beat or more is no running clock's
    // (its escapement would not unlock on that side): the ticks were
    // numbered on a beat not the clock's (a gap misread, a loop).
    if a.beat_error_ms * 1e-3 >= OUT_OF_BEAT * a.mean_beat {
        return Err(Refusal::data(format!(
            "the ticks give a beat error of {} ms, {}% of the beat of {} s, which no running \
             clock has: the beat was not followed; give the beat rate (bph), or record longer",
            format_significant(a.beat_error_ms, 3),
            format_significant(100.0 * a.beat_error_ms * 1e-3 / a.mean_beat, 2),
            format_significant(a.mean_beat, 4)
        )));
    }
    Ok(())
}

/// Adds the warning `w` to `beats`, with its code.
fn warn(beats: &mut Beats, w: BeatWarning) {
    beats.warning_codes.push(w.code());
    beats.warnings.push(w);
}

/// Adds to `beats` the warnings of what was heard beside the beat, in
/// order: ticks and tocks that sound different (`differ`), `ticks` that
/// repeat exactly (a loop of sound), the spans cut and the clock lost
/// (`gaps`), and an amplitude the oscillator cannot have (`swing`).
fn warn_of_sounds(beats: &mut Beats, differ: bool, ticks: &[Tick], gaps: &Gaps, swing: &Swing) {
    if differ {
        warn(beats, BeatWarning::SoundsDiffer);
    }
    if let Some((after_beats, spread_s)) = repeats(ticks) {
        let w = BeatWarning::RepeatsExactly {
            after_beats,
            spread_s,
        };
        warn(beats, w);
    }
    if !gaps.cuts.is_empty() {
        let w = BeatWarning::SoundsCut {
            spans: gaps.cuts.clone(),
            beats: gaps.cut_beats,
        };
        warn(beats, w);
    }
    if !gaps.lost.is_empty() {
        let w = BeatWarning::ClockLost {
            spans: gaps.lost.clone(),
        };
        warn(beats, w);
    }
    if let Some(swing_rad) = swing.impossible {
        let oscillator = swing.oscillator;
        let w = BeatWarning::AmplitudeImpossible {
            amplitude_deg: swing_rad.to_degrees(),
            largest_deg: oscillator.largest_swing_rad().to_degrees(),
            pendulum: oscillator == Oscillator::Pendulum,
        };
        warn(beats, w);
    }
}

/// The recording in windows of `window.every` s: those cut as it went on
/// (live), else cut here from the ticks; with their totals, and the
/// warnings they give added to `beats` (a rate that wanders, windows
/// whose mean rate is not the whole recording's).
fn windowed(
    cut: Option<Vec<Window>>,
    window: &WindowInput<'_>,
    beats: &mut Beats,
) -> (Vec<Window>, WindowTotals) {
    let (w, totals) = match cut {
        Some(w) => {
            let totals = super::windows::totals(&w, window.every);
            (w, totals)
        }
        None => windows(window),
    };
    if let Some(ratio) = totals.rate_scatter_over_se.filter(|&r| r > RATE_WANDERS) {
        warn(beats, BeatWarning::RateWanders { ratio });
    }
    if let Some(w) = windows_biased(&totals, beats.rate_s_per_day, beats.rate_se_s_per_day) {
        warn(beats, w);
    }
    (w, totals)
}

/// The ticks heard, checked and analysed: the clean-up, the checks that
/// the beat was followed (both sides in proportion, most beats heard, a
/// beat error a running clock can have), the beat analysis, the drop and
/// the amplitude, and the windows.
pub(crate) fn conclude(
    heard: Heard,
    checked: &Checked,
    input: &ListenInput,
) -> Result<Listening, Refusal> {
    let Heard {
        coarse,
        mut ticks,
        sides,
        windows: cut,
        sounds,
        duration,
        beat,
        sample_rate,
        cuts,
        quality,
    } = heard;
    let (nominal, ppm) = (checked.nominal, checked.ppm);
    let rate = f64::from(sample_rate);
    let snr_db = snr(coarse.peak, coarse.floor);
    let differ = sounds
        .as_ref()
        .is_some_and(|pair| !super::detect::one_sound(pair, rate));
    if differ {
        sides.align(&mut ticks);
    }
    if ticks.len() < MIN_TICKS {
        return Err(too_few(ticks.len(), duration, beat, snr_db));
    }
    refuse_one_side(&ticks, beat, input.nominal)?;
    refuse_unfollowed(&ticks, nominal, snr_db)?;
    let scale = 1.0 / (1.0 + ppm * 1e-6);
    let gaps = Gaps::of(&ticks, &cuts, beat, duration, scale);
    for t in &mut ticks {
        t.time *= scale;
    }
    let a = analyse_ticks(&ticks, beat, nominal.map(|p| 0.5 * p))
        .map_err(|e| Refusal::data(e.to_string()))?;
    let swing = Swing::heard(&coarse, scale, a.mean_beat, input)?;
    let oscillator = swing.oscillator;
    refuse_out_of_beat(&a)?;
    let in_beat_percent = crate::advice::split_percent(a.beat_error_ms * 1e-3, a.mean_beat);
    let (mean_beat, doubled) = (a.mean_beat, a.repaired.doubled);
    let mut beats = Beats::of(a);
    warn_of_sounds(&mut beats, differ, &ticks, &gaps, &swing);
    let (windows, window_totals) = match input.every {
        Some(every) => {
            check_every(every, mean_beat)?;
            let window = WindowInput {
                ticks: &ticks,
                levels: &coarse.levels,
                spacings: &coarse.spacings,
                every,
                duration: duration * scale,
                nominal_beat: beats.nominal_beat_s,
                lift_angle: input.lift_angle,
                oscillator,
                scale,
            };
            let (w, totals) = windowed(cut, &window, &mut beats);
            (w, Some(totals))
        }
        None => (Vec::new(), None),
    };
    let mut listening = Listening {
        sample_rate_hz: sample_rate,
        sample_rate_error_ppm: ppm,
        duration_s: duration,
        in_beat_percent,
        // The beats from the first tick kept to the last, less the ticks
        // kept: missed, whether no sound was there or it was dropped as
        // noise (counted once, though the analysis fills the same gaps).
        missed: gaps.missed,
        cut_s: gaps.cuts.iter().map(|&(a, b)| [a, b]).collect(),
        cut_beats: gaps.cut_beats,
        lost_s: gaps.lost.iter().map(|&(a, b)| [a, b]).collect(),
        extra: doubled,
        beats,
        snr_db,
        timed_on: coarse.timing,
        drop_ms: swing.drops.map(|d| d.map(|d| d * 1e3)),
        lift_angle_deg: input.lift_angle.map(f64::to_degrees),
        oscillator,
        oscillator_from_beat: input.oscillator.is_none(),
        amplitude_deg: swing.lifted(input.lift_angle, &|x| oscillator.amplitude(x)),
        amplitude_first_order_deg: swing.lifted(input.lift_angle, &|x| x.first_order),
        windows,
        window_totals,
        findings: Vec::new(),
        ticks,
        sounds,
    };
    listening.findings = findings(&listening, &coarse.spacings, quality);
    listening.advise(&crate::advice::Known::default())?;
    Ok(listening)
}

impl Listening {
    /// Fills the advice ([`Beats::advise`]) from what was heard and
    /// `known`: the swing heard is used where a clock can have it.
    pub fn advise(&mut self, known: &crate::advice::Known) -> Result<(), Refusal> {
        let largest = self.oscillator.largest_swing_rad();
        let heard = self
            .amplitude_deg
            .flatten()
            .map(f64::to_radians)
            .filter(|&a| a > 0.0 && a <= largest);
        self.beats.advise(
            known,
            Some(self.oscillator),
            heard,
            self.lift_angle_deg.map(f64::to_radians),
        )
    }
}

/// The windows' mean rate differs from the whole recording's by more than
/// this many standard errors of the difference (`windows_biased`).
pub const WINDOWS_BIASED_SIGMA: f64 = 4.0;

/// A warning when the windows' mean rate stands [`WINDOWS_BIASED_SIGMA`]
/// standard errors (the two's, added in quadrature: they share their
/// ticks, so this errs towards silence) from the whole recording's: a
/// periodic error whose period the windows share (an escape wheel turning
/// once a window) biases every window's slope alike, where the whole
/// recording's regression averages it out.
fn windows_biased(
    totals: &WindowTotals,
    whole: Option<f64>,
    whole_se: Option<f64>,
) -> Option<BeatWarning> {
    let (mean, mean_se) = (totals.rate_mean_s_per_day?, totals.rate_mean_se_s_per_day?);
    let (whole, whole_se) = (whole?, whole_se.unwrap_or(0.0));
    let sigma = (mean_se * mean_se + whole_se * whole_se).sqrt();
    (totals.windows_with_rate >= 3
        && sigma > 0.0
        && (mean - whole).abs() > WINDOWS_BIASED_SIGMA * sigma)
        .then_some(BeatWarning::WindowsBiased {
            windows_mean: mean,
            whole,
            sigma: (mean - whole).abs() / sigma,
            every_s: totals.every_s,
        })
}

/// Windows of `every` s must hold [`MIN_WINDOW_BEATS`] beats of `beat` s.
pub(crate) fn check_every(every: f64, beat: f64) -> Result<(), Refusal> {
    if every >= MIN_WINDOW_BEATS * beat {
        return Ok(());
    }
    Err(Refusal::field(
        "every",
        format!(
            "a window must hold at least {MIN_WINDOW_BEATS} beats ({} s at this clock's beat of \
             {} s), got {} s",
            format_significant(MIN_WINDOW_BEATS * beat, 3),
            format_significant(beat, 4),
            format_significant(every, 6)
        ),
    ))
}

/// Whether the ticks repeat exactly: the fewest beats `n` (up to
/// [`LOOP_BEATS`], and a third of the ticks) after which the times from
/// each tick to the tick `n` beats later (three at least) scatter by less
/// than [`REPEATS_EXACTLY_S`] (their standard deviation): `(n, scatter)`.
/// A loop of sound repeats its ticks to rounding; a clock's wander by
/// microseconds.
fn repeats(ticks: &[Tick]) -> Option<(u64, f64)> {
    let times: std::collections::HashMap<u64, f64> =
        ticks.iter().map(|t| (t.beat, t.time)).collect();
    let most = (ticks.len() as u64 / 3).min(LOOP_BEATS);
    (1..=most).find_map(|n| {
        let gaps: Vec<f64> = ticks
            .iter()
            .filter_map(|t| Some(times.get(&(t.beat + n))? - t.time))
            .collect();
        if gaps.len() < 3 {
            return None;
        }
        let mean = gaps.iter().sum::<f64>() / gaps.len() as f64;
        let sd =
            (gaps.iter().map(|g| (g - mean).powi(2)).sum::<f64>() / (gaps.len() - 1) as f64).sqrt();
        (sd < REPEATS_EXACTLY_S).then_some((n, sd))
    })
}

/// The longest loop looked for, beats.
pub const LOOP_BEATS: u64 = 256;

/// Ticks and tocks that sound different, each refined on its own median
/// sound's start, put on one definition of the start where the two
/// disagree: the tracker's onsets (the crossing of 30% of each beat's own
/// rise on the envelope, the same rule for both sides), against which the
/// tocks are moved so that their median offset from them is the ticks'.
/// The start of a median sound is a fifth of its peak: on a slow sound
/// whose median is smeared, that fell 1.6 ms early on the tocks of a
/// generated clock (its beat error read 6.3 ms for 8), while the tracker's
/// onsets were within 0.1 ms of the truth on both sides. Moved only when
/// the sides' median offsets differ by more than three standard errors (a
/// sound's start on the envelope has its own bias of a tenth of a ms or
/// so, which the median sounds' starts need not take). A shift common to
/// both sides changes neither the rate nor the beat error; nor does it
/// change which ticks the clean-up keeps (each tick is predicted from its
/// own side's), so the offsets are those of the ticks kept, gathered as
/// they are (4 bytes a tick: listening live keeps them for the hours).
#[derive(Clone, Debug, Default)]
pub(crate) struct SideOffsets([Vec<f32>; 2]);

impl SideOffsets {
    /// Takes the offset of a tick kept, and gives the tick.
    pub(crate) fn add(&mut self, r: &Refined) -> Tick {
        self.0[usize::from(r.tick.side.min(1))].push((r.tick.time - r.onset) as f32);
        r.tick
    }

    /// The shift of the tocks that aligns them on the ticks (see
    /// [`SideOffsets`]), s: 0 where the sides agree within three standard
    /// errors.
    pub(crate) fn shift(&self) -> f64 {
        if self.0.iter().any(|o| o.len() < MIN_TICKS) {
            return 0.0;
        }
        // Each side's median offset and its standard error (1.25 times the
        // mean's, from the median absolute deviation).
        let [(tick, a), (tock, b)] = [0, 1].map(|side| {
            let o: Vec<f64> = self.0[side].iter().map(|&x| f64::from(x)).collect();
            let m = super::detect::median_of(&o);
            let deviations: Vec<f64> = o.iter().map(|x| (x - m).abs()).collect();
            let mad = super::detect::median_of(&deviations);
            (m, 1.25 * 1.4826 * mad / (o.len() as f64).sqrt())
        });
        let shift = tick - tock;
        if shift.abs() <= 3.0 * a.hypot(b) {
            0.0
        } else {
            shift
        }
    }

    /// Ticks kept so far.
    pub(crate) fn len(&self) -> usize {
        self.0[0].len() + self.0[1].len()
    }

    /// Moves the tocks of `ticks` by [`Self::shift`].
    pub(crate) fn align(&self, ticks: &mut [Tick]) {
        shift_tocks(ticks, self.shift());
    }
}

/// Moves the tocks of `ticks` by `shift` s.
pub(crate) fn shift_tocks(ticks: &mut [Tick], shift: f64) {
    if shift != 0.0 {
        for t in ticks.iter_mut().filter(|t| t.side == 1) {
            t.time += shift;
        }
    }
}

/// The longest stretch with no tick heard that is not a clock lost: the
/// longer of this, s, and [`LOST_BEATS`] beats.
pub const LOST_S: f64 = 5.0;
/// See [`LOST_S`].
pub const LOST_BEATS: f64 = 8.0;

/// The beats missing between consecutive `ticks` (numbered by the
/// tracker), and before the first and after the last within the
/// recording's `duration` s, whose times, at `beat` s from the tick
/// heard beside them, fall in a span of `cuts` (a strike at the start is
/// cut before the tracker takes the clock up): (between the ticks, before
/// and after them).
fn beats_in_cuts(ticks: &[Tick], cuts: &[(f64, f64)], beat: f64, duration: f64) -> (usize, usize) {
    let cut = |t: f64| cuts.iter().any(|&(a, b)| t >= a && t <= b);
    let between: usize = ticks
        .windows(2)
        .map(|w| {
            (w[0].beat + 1..w[1].beat)
                .filter(|&k| cut(w[0].time + (k - w[0].beat) as f64 * beat))
                .count()
        })
        .sum();
    let (Some(first), Some(last)) = (ticks.first(), ticks.last()) else {
        return (0, 0);
    };
    let before = (1..=(first.time / beat).floor() as usize)
        .filter(|&m| cut(first.time - m as f64 * beat))
        .count();
    let after = (1..=((duration - last.time) / beat).floor() as usize)
        .filter(|&m| cut(last.time + m as f64 * beat))
        .count();
    (between, before + after)
}

/// The stretches of a recording `duration` s long, after its first tick,
/// with no tick heard for longer than [`LOST_S`] and [`LOST_BEATS`] beats,
/// less what `cuts` covers: a clock lost (stopped, faded, drowned), s.
fn lost_spans(ticks: &[Tick], cuts: &[(f64, f64)], beat: f64, duration: f64) -> Vec<(f64, f64)> {
    let longest = LOST_S.max(LOST_BEATS * beat);
    let mut gaps: Vec<(f64, f64)> = ticks
        .windows(2)
        .map(|w| (w[0].time + beat, w[1].time - beat))
        .collect();
    if let Some(last) = ticks.last() {
        gaps.push((last.time + beat, duration));
    }
    let mut lost = Vec::new();
    for (a, b) in gaps {
        // The gap less the spans cut: what is left in pieces.
        let mut pieces = vec![(a, b)];
        for &(c, d) in cuts {
            pieces = pieces
                .into_iter()
                .flat_map(|(x, y)| [(x, y.min(c)), (x.max(d), y)])
                .filter(|(x, y)| y > x)
                .collect();
        }
        lost.extend(pieces.into_iter().filter(|(x, y)| y - x > longest));
    }
    lost
}

/// The ticks' signal to noise on the envelope below which the sound
/// between them is not looked at, dB (followed at twice its beat, a watch
/// at 12 dB showed 5.9 dB, noise 1.3 to 1.8).
pub const HALF_BEAT_MIN_SNR_DB: f64 = 3.0;

/// The onsets' scatter about their line (see `onset_scatter`) under
/// which ticks too faint for [`HALF_BEAT_MIN_SNR_DB`] are still the
/// clock's, s: the envelope's crests of noise followed in a window of
/// ±3 to ±4 ms scatter 1.5 to 2.3 ms (a uniform spread's σ); synthetic
/// ticks at 5 to 7 dB (1.3 to 4 dB on the envelope), 1,800 to 28,800
/// beats an hour, 0.2 to 0.8 ms.
pub const HALF_BEAT_MAX_SCATTER_S: f64 = 1e-3;

/// The scatter of the tracker's onsets about the line of their side, s:
/// 1.4826 median absolute second differences of each side's onsets five
/// beats in a row (k, k + 2, k + 4), over √6 (a second difference of
/// three independent times). `None` for fewer than eight.
fn onset_scatter(coarse: &Coarse) -> Option<f64> {
    let times: std::collections::HashMap<u64, f64> = coarse.onsets.iter().copied().collect();
    let mut seconds: Vec<f64> = coarse
        .onsets
        .iter()
        .filter_map(|&(k, t)| {
            let (b, c) = (times.get(&(k + 2))?, times.get(&(k + 4))?);
            Some((c - 2.0 * b + t).abs())
        })
        .collect();
    if seconds.len() < 8 {
        return None;
    }
    Some(1.4826 * super::detect::median(&mut seconds) / 6f64.sqrt())
}

/// A sound between two ticks this large against a tick's rise over the
/// floor is the other side of a beat half as long: a quarter.
pub const HALF_BEAT_RISE: f64 = 0.25;

/// A sound between two ticks from this much of a tick's rise up to
/// [`HALF_BEAT_RISE`] is the other side of the beat (a weak tock) when it
/// is the one sound of its size between them ([`HALF_BEAT_ALONE`]) and
/// stands where a beat error under [`OUT_OF_BEAT`] puts it: an eighth.
/// Measured: tocks 10-14 dB under their ticks, 3,600 to 28,800 beats an
/// hour, stand 0.16-0.26 of the rise at 0.50-0.505 of the way with no
/// other sound over 0.20 of theirs; a room's echoes and a phone codec's
/// smear stand 0.12-0.21 of the rise at 0.36-0.52 of the way, with other
/// echoes 0.40-0.81 of them (a reflection is a copy of the tick: its level
/// and shape alone cannot tell it from a tock; that it comes with others
/// can).
pub const HALF_BEAT_WEAK_RISE: f64 = 0.125;

/// See [`HALF_BEAT_WEAK_RISE`]: every other sound between the ticks
/// (away from the candidate and its own drop) under this fraction of it.
pub const HALF_BEAT_ALONE: f64 = 0.45;

/// See [`HALF_BEAT_WEAK_RISE`]: a weak sound between the ticks is taken
/// for the other side of the beat only where a beat error under this
/// fraction of the beat puts it (from 45% to 55% of the way): a clock
/// out of beat by a tenth of its beat is near stopping, and a room's
/// echoes fall anywhere.
pub const HALF_BEAT_WEAK_OUT_OF_BEAT: f64 = 0.1;

/// Whether a sound stands between consecutive ticks: the envelope (the
/// first pass's, at `rate` values a second: the detector's band, or the
/// wide band) from 30% to 70% of the way from each onset to the next
/// (`coarse`'s, consecutive beats only), averaged over the pairs on the
/// fraction of the way, peaks six robust standard deviations above that
/// average's median and more than [`HALF_BEAT_RISE`] of the ticks' rise
/// over it (the ticks' rise: the mean of the envelope's largest value
/// within 10 ms of each onset), or more than [`HALF_BEAT_WEAK_RISE`] of it
/// alone and near the middle; and not within 3 ms of a beat's own second
/// sound (the drop, 16 ms after the unlocking: a third of the way at
/// 72,000 beats an hour). Aligned on the onsets, the other side of a clock
/// out of beat stays at one fraction whatever the rate; noise and a room's
/// reverberation average flat.
fn sound_between_ticks(envelope: &[f32], rate: f64, coarse: &super::detect::Coarse) -> bool {
    let pairs: Vec<(f64, f64)> = coarse
        .onsets
        .windows(2)
        .filter(|w| w[1].0 == w[0].0 + 1)
        .map(|w| (w[0].1, w[1].1))
        .filter(|&(_, b)| ((b * rate) as usize) < envelope.len())
        .collect();
    if pairs.len() < 8 {
        return false;
    }
    let typical = pairs.iter().map(|(a, b)| b - a).sum::<f64>() / pairs.len() as f64;
    let bins = ((0.4 * typical * rate).round() as usize).clamp(8, 20_000);
    // Bin j's fraction of the way from one onset to the next.
    let fraction = |j: usize| 0.3 + 0.4 * j as f64 / (bins - 1) as f64;
    let mut profile = vec![0.0; bins];
    let mut tick = 0.0;
    let reach = (0.01 * rate).ceil() as usize;
    for &(a, b) in &pairs {
        for (j, p) in profile.iter_mut().enumerate() {
            let i = ((a + fraction(j) * (b - a)) * rate).round() as usize;
            *p += f64::from(envelope[i.min(envelope.len() - 1)]);
        }
        let i = ((a * rate).round().max(0.0) as usize).min(envelope.len() - 1);
        tick += envelope[i..(i + reach).min(envelope.len())]
            .iter()
            .fold(0.0_f64, |m, &v| m.max(f64::from(v)));
    }
    profile.iter_mut().for_each(|p| *p /= pairs.len() as f64);
    tick /= pairs.len() as f64;
    let centre = super::detect::median_of(&profile);
    let rise = tick - centre;
    if rise.is_nan() || rise <= 0.0 {
        return false;
    }
    let spread = 1.4826
        * super::detect::median_of(
            &profile
                .iter()
                .map(|p| (p - centre).abs())
                .collect::<Vec<_>>(),
        );
    let Some((at, &top)) = profile.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)) else {
        return false;
    };
    let after = fraction(at) * typical;
    let drop = coarse
        .drops
        .iter()
        .flatten()
        .any(|d| (after - d).abs() < 0.003);
    let peak = top - centre;
    if drop || peak < 6.0 * spread || peak < HALF_BEAT_WEAK_RISE * rise {
        return false;
    }
    if peak >= HALF_BEAT_RISE * rise {
        return true;
    }
    // Weak: where a beat error under OUT_OF_BEAT of the half beat puts the
    // other side, and no other sound near its size (away from it and from
    // where its own drop follows it).
    let delays: Vec<f64> = coarse.drops.iter().flatten().copied().collect();
    let near = |t: f64| {
        let from = (t - after).abs();
        from <= 0.003 || delays.iter().any(|d| (from - d).abs() <= 0.003)
    };
    let others = profile
        .iter()
        .enumerate()
        .filter(|&(j, _)| !near(fraction(j) * typical))
        .fold(0.0_f64, |m, (_, &p)| m.max(p - centre));
    (after / typical - 0.5).abs() < 0.5 * HALF_BEAT_WEAK_OUT_OF_BEAT
        && others < HALF_BEAT_ALONE * peak
}

/// The beat analysis of ticks numbered by the tracker: its stream given
/// the beat the ticks' own numbers give (the tracker followed the clock
/// beat by beat, so a gap's beats are counted, not guessed from the
/// intervals: with many ticks lost the median interval is not a beat), or
/// `fallback` for fewer than two beats; against `nominal` (s).
pub(crate) fn analyse_ticks(
    ticks: &[Tick],
    fallback: f64,
    nominal: Option<f64>,
) -> Result<BeatAnalysis, crate::fitting::beats::BeatError> {
    let numbered: Vec<(u64, f64)> = ticks.iter().map(|t| (t.beat, t.time)).collect();
    analyse_numbered(&numbered, fallback, nominal)
}

/// [`analyse_ticks`] of `(beat number, time s)` pairs (a tracker's
/// onsets, or ticks).
pub(crate) fn analyse_numbered(
    beats: &[(u64, f64)],
    fallback: f64,
    nominal: Option<f64>,
) -> Result<BeatAnalysis, crate::fitting::beats::BeatError> {
    let numbered = match (beats.first(), beats.last()) {
        (Some(a), Some(b)) if b.0 > a.0 => (b.1 - a.1) / (b.0 - a.0) as f64,
        _ => fallback,
    };
    let mut stream = BeatStream::filling_up_to(MAX_FILLED_BEATS).with_beat(numbered);
    for &(k, t) in beats {
        stream.push_numbered(k, t)?;
    }
    stream.finish(nominal)
}

/// The largest signal to noise said, dB: a floor of digital silence (a
/// recording quantised to zero between its ticks) has none to speak of,
/// and 16-bit sound spans 96 dB.
pub const MAX_SNR_DB: f64 = 120.0;

/// A peak over a floor, dB, at most [`MAX_SNR_DB`] (and -inf for no
/// peak: silence).
pub fn snr(peak: f64, floor: f64) -> f64 {
    (20.0 * (peak / floor.max(f64::MIN_POSITIVE)).log10()).min(MAX_SNR_DB)
}

/// A beat error of this fraction of the beat or more is refused: no
/// running clock's (the tick and tock intervals 70/30).
pub const OUT_OF_BEAT: f64 = 0.2;

/// The windows' rates scattered this many times what their standard
/// errors allow say the rate wanders (`rate_wanders`).
pub const RATE_WANDERS: f64 = 3.0;

/// A signal to noise at which a recording is not too noisy to follow, dB.
pub const LOUD_DB: f64 = 25.0;

/// Fewer than [`MIN_TICKS`] ticks: too short a recording, or too noisy.
fn too_few(found: usize, duration: f64, beat: f64, snr_db: f64) -> Refusal {
    let expected = (duration / beat).round();
    if expected < MIN_TICKS as f64 {
        return Refusal::data(format!(
            "{} s of sound holds fewer than four beats of {} s; record at least a minute",
            format_significant(duration, 3),
            format_significant(beat, 4)
        ));
    }
    // Loud sounds that do not repeat at the beat found: the beat is not
    // the clock's (a short clip, a ringing taken for a rhythm), not noise.
    if snr_db.is_finite() && snr_db >= LOUD_DB {
        return Refusal::data(format!(
            "{found} of about {expected} beats of {} s stand out, though the sounds are loud \
             (signal to noise {} dB): the beat found is not the clock's; give the beat rate \
             (bph), or record longer (a minute at least)",
            format_significant(beat, 4),
            format_significant(snr_db, 2)
        ));
    }
    // Silence has no signal to noise ratio to speak of.
    let snr = if snr_db.is_finite() {
        format!(" (signal to noise {} dB)", format_significant(snr_db, 2))
    } else {
        " (the recording is silent)".to_string()
    };
    Refusal::data(format!(
        "{found} of about {expected} beats stand out of the noise{snr}; record nearer the clock, \
         or in a quieter room"
    ))
}

/// A sound card's clock error measured on a reference that ticks once a
/// second (a quartz watch, or a GPS receiver's 1 PPS made audible).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Calibration {
    /// The card's clock error, ppm (positive: it runs fast, so that a
    /// second of the reference spans more than `sample_rate` samples):
    /// what `sample_rate_error_ppm` takes.
    pub sample_rate_error_ppm: f64,
    /// Its standard error, ppm, from the reference ticks' scatter (the
    /// reference's own error is not in it: a quartz watch keeps a second
    /// to a few ppm, ±0.5 s/day; a GPS 1 PPS to far better).
    pub sample_rate_error_se_ppm: Option<f64>,
    /// Ticks of the reference heard.
    pub beats: usize,
    /// The reference's length, s.
    pub duration_s: f64,
}

/// The reference's beat, s: one tick a second.
pub const REFERENCE_BEAT_S: f64 = 1.0;

/// Measures a sound card's clock error on `source`, a recording through
/// it of a reference ticking once a second ([`REFERENCE_BEAT_S`]): the
/// reference's ticks are heard as a clock's are ([`listen`], at 3,600
/// beats an hour), and its mean beat in the card's samples, against one
/// second, is the card's error. Refused when the reference does not tick
/// once a second.
pub fn sound_card_error<S: SampleSource>(
    source: &mut S,
) -> Result<Calibration, ListenFailure<S::Error>> {
    let heard = listen(
        source,
        &ListenInput {
            nominal: Some(Nominal::BeatsPerHour(3600.0 / REFERENCE_BEAT_S)),
            ..ListenInput::default()
        },
    )?;
    let beat = heard.beats.mean_beat_s;
    let ppm = (beat / REFERENCE_BEAT_S - 1.0) * 1e6;
    if ppm.abs() > MAX_SAMPLE_RATE_ERROR_PPM {
        return Err(Refusal::field(
            "reference",
            format!(
                "ticks {} s apart, not once a second: the reference must be a quartz watch or a \
                 1 PPS click",
                format_significant(beat, 6)
            ),
        )
        .into());
    }
    Ok(Calibration {
        sample_rate_error_ppm: ppm,
        // The rate's standard error, s/day, is the beat's relative one
        // times 86,400.
        sample_rate_error_se_ppm: heard.beats.rate_se_s_per_day.map(|se| se / 86_400.0 * 1e6),
        beats: heard.beats.beats,
        duration_s: heard.duration_s,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A floor of digital silence (quantised to zero between the ticks)
    /// gives the largest figure said, not 6,000 dB; silence gives none.
    #[test]
    fn signal_to_noise_is_bounded() {
        assert_eq!(snr(0.3, 0.0), MAX_SNR_DB);
        assert!((snr(1.0, 0.1) - 20.0).abs() < 1e-12);
        assert_eq!(snr(0.0, 0.0), f64::NEG_INFINITY);
    }
}
