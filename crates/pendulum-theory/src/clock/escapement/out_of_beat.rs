//! A clock out of beat: its escapement sits off the pendulum's rest by an
//! angle `δ` (the crutch bent, the case leaning), so the pendulum meets
//! the lift `δ` late on its swings one way and `δ` early on its swings
//! back. The two beats differ: the ticks come unevenly (tick ... tock,
//! tick ... tock), the beat error a timegrapher or `listen` measures, half
//! the difference of the two intervals. For a free harmonic swing of
//! amplitude `A` whose ticks fall at the lift's far edge `h`, the ticks
//! are at `θ = δ + h` going out and `δ - h` coming back, so the beat error
//! is `|acos((δ - h)/A) + acos((δ + h)/A) - π| / ω`, about
//! `2δ / (ω sqrt(A² - h²))` (the clockmaker's rule that a beat error is
//! the offset over the swing's speed through the lift).

use super::Escapement;

/// An escapement sitting `offset` rad off the pendulum's rest, towards
/// the side the even beats travel to.
#[derive(Debug)]
pub struct OutOfBeat {
    /// The escapement, as it would be in beat.
    pub inner: Box<dyn Escapement>,
    /// How far it sits off the rest, rad.
    pub offset: f64,
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

impl Escapement for OutOfBeat {
    fn name(&self) -> &'static str {
        self.inner.name()
    }
    fn edges(&self) -> Vec<f64> {
        self.inner.edges()
    }
    fn torque(&self, zone: usize, theta: f64, drive: f64) -> f64 {
        self.inner.torque(zone, theta, drive)
    }
    fn work(&self, zone: usize, from: f64, to: f64, drive: f64) -> f64 {
        self.inner.work(zone, from, to, drive)
    }
    fn kick(&self, edge: usize, beat: u64, drive: f64) -> f64 {
        self.inner.kick(edge, beat, drive)
    }
    /// Two beats at least, and a whole number of the inner escapement's
    /// cycles.
    fn cycle(&self) -> u64 {
        let n = self.inner.cycle().max(1);
        n * 2 / gcd(n, 2)
    }
    fn symmetric(&self) -> bool {
        false
    }
    fn unlocking_amplitude(&self) -> f64 {
        self.inner.unlocking_amplitude() + self.offset.abs()
    }
    fn offset(&self, beat: u64) -> f64 {
        if beat % 2 == 0 {
            self.offset
        } else {
            -self.offset
        }
    }
}
