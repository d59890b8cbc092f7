//! The continuous extension of one DOP853 step: a polynomial of degree 7 in
//! `x = (t - t0)/h`, in the nested form of `dop853.f`'s `CONTD8`:
//! `y(x) = y0 + x(F0 + (1-x)(F1 + x(F2 + (1-x)(F3 + x(F4 + (1-x)(F5 + x F6))))))`.
//! Its error is of order `h^8`, like the step's own.

use super::State2;

/// The interpolant of one step from `t0` to `t0 + h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseOutput {
    /// Start of the step.
    pub t0: f64,
    /// Length of the step.
    pub h: f64,
    /// State at the start.
    pub y0: State2,
    /// The seven coefficient vectors `F0..F6`.
    pub coefficients: [State2; 7],
}

impl DenseOutput {
    /// The state at `t`, which should lie within the step.
    #[inline]
    pub fn eval(&self, t: f64) -> State2 {
        let x = (t - self.t0) / self.h;
        let y = 1.0 - x;
        let f = &self.coefficients;
        let mut out = [0.0; 2];
        for (i, value) in out.iter_mut().enumerate() {
            let mut acc = f[6][i];
            acc = f[5][i] + x * acc;
            acc = f[4][i] + y * acc;
            acc = f[3][i] + x * acc;
            acc = f[2][i] + y * acc;
            acc = f[1][i] + x * acc;
            acc = f[0][i] + y * acc;
            *value = self.y0[i] + x * acc;
        }
        out
    }

    /// One component at `t`.
    #[inline]
    pub fn component(&self, t: f64, i: usize) -> f64 {
        self.eval(t)[i]
    }
}
