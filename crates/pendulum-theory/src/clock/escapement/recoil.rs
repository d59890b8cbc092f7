//! The anchor (recoil) escapement (Clement or Hooke, about 1670): the
//! impulse over the lift as in the deadbeat, but outside it the wheel
//! presses on an inclined locking face that drives it backwards as the
//! pendulum swings on, so the wheel pushes the pendulum back towards the
//! middle: a torque against the displacement that grows with the angle
//! past the lift, on the way out and on the way back. Here it grows
//! linearly, reaching `recoil` times the drive torque one lift angle past
//! the edge. Friction on the faces is left out (it only takes energy).
//! The horological texts' statement it reproduces: a recoil escapement
//! gains as the drive (and the arc) increase, a deadbeat loses
//! (Rawlings, The Science of Clocks and Watches, 3rd ed., ch. 5).

use super::Escapement;

/// An anchor (recoil) escapement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Recoil {
    /// The lift angle, rad.
    pub lift: f64,
    /// The impulse torque at the pallets, over `m g l`.
    pub torque: f64,
    /// The recoil torque one lift angle past the edge, over the drive torque.
    pub recoil: f64,
}

impl Recoil {
    fn slope(&self, drive: f64) -> f64 {
        self.recoil * self.torque * drive / self.lift
    }
}

impl Escapement for Recoil {
    fn name(&self) -> &'static str {
        "recoil"
    }
    fn edges(&self) -> Vec<f64> {
        vec![-0.5 * self.lift, 0.5 * self.lift]
    }
    fn torque(&self, zone: usize, theta: f64, drive: f64) -> f64 {
        let h = 0.5 * self.lift;
        match zone {
            // Coming back from -A: pushed towards the middle (+).
            0 => self.slope(drive) * (-h - theta),
            1 => self.torque * drive,
            // Going out past +h: pushed back (-).
            _ => -self.slope(drive) * (theta - h),
        }
    }
    fn work(&self, zone: usize, from: f64, to: f64, drive: f64) -> f64 {
        let h = 0.5 * self.lift;
        let k = self.slope(drive);
        match zone {
            0 => 0.5 * k * ((-h - from).powi(2) - (-h - to).powi(2)),
            1 => self.torque * drive * (to - from),
            _ => -0.5 * k * ((to - h).powi(2) - (from - h).powi(2)),
        }
    }
    fn unlocking_amplitude(&self) -> f64 {
        0.5 * self.lift
    }
}
