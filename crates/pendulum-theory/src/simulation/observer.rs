//! What a run hands out as it goes: turning points, upward zero crossings,
//! samples and progress, to an [`Observer`], which answers with an
//! [`Action`] (carry on, stop, or restart from another state: the hook an
//! escapement can use).

use crate::damped::State;

/// A turning point of the swing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TurningPoint {
    /// 0 for the release, then one per half swing.
    pub index: u64,
    /// Time, s.
    pub time: f64,
    /// Signed angle, rad.
    pub angle: f64,
}

/// What an observer wants done after an event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Action {
    /// Carry on.
    Continue,
    /// End the run at the event (a terminal event).
    Stop,
    /// Carry on from this state instead, at the event's time: the hook an
    /// escapement uses to give its impulse. The integrator restarts there.
    Restart(State),
}

/// An upward zero crossing: θ passing 0 from negative to positive, where an
/// escapement usually gives its impulse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// 1 for the first crossing, and so on.
    pub index: u64,
    /// Time, s.
    pub time: f64,
    /// θ' there, rad/s.
    pub angular_velocity: f64,
}

/// Receives what a run produces, as it produces it.
pub trait Observer {
    /// A turning point (the release is index 0, whose action is ignored).
    fn turning_point(&mut self, _point: &TurningPoint) -> Action {
        Action::Continue
    }
    /// Whether to locate upward zero crossings (off by default: it costs an
    /// interpolant every half period).
    fn wants_zero_crossings(&self) -> bool {
        false
    }
    /// An upward zero crossing.
    fn zero_crossing(&mut self, _crossing: &Crossing) -> Action {
        Action::Continue
    }
    /// A sample at a multiple of the sample interval; `false` stops the run.
    fn sample(&mut self, _time: f64, _state: &State) -> bool {
        true
    }
    /// Called every few thousand steps with the time reached; `false` stops the run.
    fn progress(&mut self, _time: f64) -> bool {
        true
    }
}

/// An observer that wants nothing.
pub struct Silent;
impl Observer for Silent {}
