//! Escapements as torques over windows of the swing.
//!
//! An escapement in beat is symmetric: what it does to a half swing
//! travelling towards `+θ` it does, mirrored, to the one travelling back.
//! So each is described for a half swing from `-A` to `+A` only, by
//! the angles where its torque changes ([`Escapement::edges`], ascending),
//! the torque in each zone between them, its work over part of a zone
//! (closed forms, for the long-run method), and instantaneous impulses at
//! an edge.
//!
//! Units are the pendulum's own: angles in radians, torques over the
//! largest gravity torque `m g l` (for a compound pendulum `M g d`), which
//! is the acceleration in units of `ω_n²`; energies over `m g l`. A torque
//! of 1e-5 is a hundred-thousandth of the bob's weight at the end of a
//! horizontal arm.
//!
//! One out of beat ([`OutOfBeat`]) sits off the pendulum's rest by an
//! angle `δ`: in the frame of each half swing its edges and torques are
//! moved by `+δ` on even beats and `-δ` on odd ones
//! ([`Escapement::offset`]), and every caller reads them through
//! [`Escapement::edges_on`], [`Escapement::torque_on`] and
//! [`Escapement::work_on`].
//!
//! The drive factor multiplies what the train delivers (a mainspring
//! running down, a dirtier train): 1 is the escapement as specified.
//!
//! Adding an escapement is adding one file with a type that implements
//! [`Escapement`] and its [`spec::Entry`] (name, help, how it is built
//! from a description), its `mod` line here and its line in
//! [`spec::ESCAPEMENTS`]: the command line's choices and help, Python's
//! names and the refusal's list read that list.

mod constant_force;
mod deadbeat;
mod free;
mod impulse;
mod out_of_beat;
mod recoil;
pub mod spec;

pub use constant_force::ConstantForce;
pub use deadbeat::Deadbeat;
pub use free::FreePendulum;
pub use impulse::Impulse;
pub use out_of_beat::OutOfBeat;
pub use recoil::Recoil;

/// An escapement's action on a half swing travelling from `-A` to `+A`
/// (see the module notes for the units).
pub trait Escapement: Send + Sync + std::fmt::Debug {
    /// Its name on the command line and in JSON.
    fn name(&self) -> &'static str;
    /// The angles where its torque changes, ascending, rad.
    fn edges(&self) -> Vec<f64>;
    /// The torque in zone `zone` (0 below the first edge, `i` between edge
    /// `i-1` and edge `i`) at `theta`, over `m g l`, with the drive
    /// multiplied by `drive`.
    fn torque(&self, zone: usize, theta: f64, drive: f64) -> f64;
    /// Its work over zone `zone` from `from` to `to` (either order), over
    /// `m g l`: the integral of [`Escapement::torque`].
    fn work(&self, zone: usize, from: f64, to: f64, drive: f64) -> f64;
    /// The energy given instantly at edge `edge` on beat `beat` (0 for
    /// escapements that push over a window), over `m g l`.
    fn kick(&self, _edge: usize, _beat: u64, _drive: f64) -> f64 {
        0.0
    }
    /// The beats in one cycle of its pattern: 1, or N for a free pendulum
    /// impulsed every N beats.
    fn cycle(&self) -> u64 {
        1
    }
    /// Whether its torque is even in `θ` (the same either side of the
    /// bottom, impulses only at the bottom): then it cannot move the period
    /// at first order (Airy), and the long-run method skips that term.
    fn symmetric(&self) -> bool {
        false
    }
    /// The smallest amplitude at which it can work (the pendulum must
    /// carry the escapement through its lift), rad.
    fn unlocking_amplitude(&self) -> f64;
    /// How far the escapement sits from the pendulum's rest in the frame
    /// of the half swing on beat `beat`, rad: 0 in beat, `+δ` and `-δ` on
    /// alternate beats for one out of beat by `δ`.
    fn offset(&self, _beat: u64) -> f64 {
        0.0
    }
    /// The edges on beat `beat`: [`Escapement::edges`] moved by the
    /// beat's [`Escapement::offset`].
    fn edges_on(&self, beat: u64) -> Vec<f64> {
        let s = self.offset(beat);
        self.edges().into_iter().map(|e| e + s).collect()
    }
    /// The torque in zone `zone` at `theta` on beat `beat`.
    fn torque_on(&self, zone: usize, theta: f64, beat: u64, drive: f64) -> f64 {
        self.torque(zone, theta - self.offset(beat), drive)
    }
    /// The work over zone `zone` from `from` to `to` on beat `beat`.
    fn work_on(&self, zone: usize, from: f64, to: f64, beat: u64, drive: f64) -> f64 {
        let s = self.offset(beat);
        self.work(zone, from - s, to - s, drive)
    }
    /// The energy it gives a half swing whose ends are `-a1` and `+a2`, on
    /// beat `beat`, over `m g l`: the work of each zone between the ends
    /// and the kicks at the edges passed.
    fn energy(&self, a1: f64, a2: f64, beat: u64, drive: f64) -> f64 {
        let edges = self.edges_on(beat);
        let (start, end) = (-a1, a2);
        let mut total = 0.0;
        let mut from = start;
        let mut zone = edges.iter().filter(|&&e| e <= start).count();
        for (i, &e) in edges.iter().enumerate().skip(zone) {
            if e >= end {
                break;
            }
            total += self.work_on(zone, from, e, beat, drive) + self.kick(i, beat, drive);
            from = e;
            zone = i + 1;
        }
        total + self.work_on(zone, from, end, beat, drive)
    }
}

/// An escapement in one of its zones, as a term of the equation of motion
/// ([`crate::forces::Term`]), in the frame travelling
/// towards `+θ`.
pub struct InZone<'a> {
    /// The escapement.
    pub escapement: &'a dyn Escapement,
    /// The zone.
    pub zone: usize,
    /// The beat.
    pub beat: u64,
    /// The drive factor.
    pub drive: f64,
}

impl crate::forces::Term for InZone<'_> {
    #[inline]
    fn acceleration(&self, y: crate::integrate::State2, _direction: f64) -> f64 {
        self.escapement
            .torque_on(self.zone, y[0], self.beat, self.drive)
    }
}

/// The zone of `theta` among `edges` (ascending).
pub fn zone_of(edges: &[f64], theta: f64) -> usize {
    edges.iter().filter(|&&e| e <= theta).count()
}
