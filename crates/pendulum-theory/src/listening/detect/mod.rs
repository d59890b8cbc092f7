//! The ticks of a recording, in passes over the samples, each in memory
//! bounded by a few beats but for what it keeps per tick:
//!
//! 1. [`Envelope`] ([`envelope`]): band-pass ([`super::filter::BandPass`]),
//!    then the RMS over 1 ms, one value per 0.5 ms (an energy detector:
//!    a tick twice the noise's RMS still stands out of the floor); then
//!    [`Gate`] ([`gate`]): sounds that are not ticks (a strike, a chime,
//!    handling) found by their loudness over 0.25 s and cut out.
//! 2. [`beat_period`] ([`period`]): the autocorrelation of the first five
//!    minutes of envelope, by FFT; its highest peak between 50 ms and 2 s
//!    that stands five robust standard deviations out of the noise, then
//!    the shortest whole fraction of it where the autocorrelation peaks
//!    nearly as high (the beat, not two or three beats), to a fraction of
//!    a lag by a parabola.
//! 3. [`OnsetTracker`] ([`onsets`]): each beat's onset on the envelope, to
//!    its 0.5 ms, streamed: the first tick from the envelope folded at the
//!    beat, then each beat the sound nearest its prediction from the last
//!    tick of the same side at the local beat, in a window of a few ms
//!    (the unlocking sound, not the later drop or the room's echo).
//! 4. [`Refiner`] ([`refine`]): the band-passed samples around each onset;
//!    the median tick and the median tock (started from the loudest
//!    window, aligned three times); each onset moved by the peak of its
//!    normalised cross-correlation with its side's median, to a fraction
//!    of a sample. A window that stands out of the quiet before the ticks
//!    neither by its correlation nor by its loudness is noise: dropped and
//!    counted as missed.
//! 5. [`clean`] ([`outliers`]): a tick 2 ms off the line its neighbours
//!    of the same side draw is a drop sound or a noise burst: dropped,
//!    counted; a tick timed a ringing period off is moved back.
//!
//! Measured on the library's synthetic recordings (tests/all/listening.rs and
//! a grid of 36 more seeds; 20 dB, 0.3 s of reverberation, 1,800 to
//! 72,000 beats per hour, 44.1 and 8 kHz): tick times within 0.01 to
//! 0.04 ms RMS of the truth, none invented, none missed. In strong noise
//! (a tick's peak 2 to 2.5 times the noise's RMS) a third to all of the
//! ticks are found, the rest reported missed, none invented.

pub mod envelope;
pub mod gate;
pub mod onsets;
pub mod outliers;
pub mod period;
pub mod refine;

pub use envelope::{envelope_rate, Envelope, ENVELOPE_RATE};
pub use gate::Gate;
pub use onsets::{second_sound, EventRule, OnsetTracker, Timing};
pub use outliers::{clean, Cleaner};
pub use period::beat_period;
pub use refine::{one_sound, MedianSound, Refined, Refiner, Tick};

/// Coarse onsets, s, with the beat numbers they belong to.
#[derive(Clone, Debug, PartialEq)]
pub struct Coarse {
    /// `(beat number from the first tick, onset s)`.
    pub onsets: Vec<(u64, f64)>,
    /// Beats with no tick found.
    pub missed: usize,
    /// The envelope's noise floor (its median).
    pub floor: f64,
    /// The typical tick peak of the envelope (median over ticks).
    pub peak: f64,
    /// The time from the tick's onset to the beat's second sound (the
    /// drop), s, for ticks and for tocks: see [`onsets::second_sound`].
    pub drops: [Option<f64>; 2],
    /// What each onset is: the unlocking, or the beat's one sound.
    pub timing: Timing,
    /// Each beat's envelope peak and the noise floor then: (beat number,
    /// peak, floor), for the signal to noise over time.
    pub levels: Vec<(u64, f64, f64)>,
    /// Each beat's time from the unlocking to the drop (timed on the
    /// unlocking, both sounds heard): (beat number, s).
    pub spacings: Vec<(u64, f64)>,
    /// The rule each beat was settled on one event by (`None`: one sound
    /// a beat), for a live tracker to follow ([`OnsetTracker::following`]).
    pub rule: Option<EventRule>,
}

pub(crate) use crate::fitting::median;

/// The median of `values` (copied).
pub(crate) fn median_of(values: &[f64]) -> f64 {
    median(&mut values.to_vec())
}
