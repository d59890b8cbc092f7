//! Events: a scalar function of the state changing sign over a step,
//! filtered by direction, with its root located on the dense output.
//!
//! The root is found by the Illinois variant of regula falsi (Dowell &
//! Jarratt 1971), which keeps a bracket and converges superlinearly, until
//! the bracket is a few ulp of `t` wide: the event time is then as good as
//! the interpolant (order `h^8`).

/// Which sign changes count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// From negative to positive.
    Rising,
    /// From positive to negative.
    Falling,
    /// Either way.
    Either,
}

/// Whether `g` went from `g0` to `g1` through zero in `direction`. A start
/// exactly at zero does not count (it is the previous event).
pub fn crossed(g0: f64, g1: f64, direction: Direction) -> bool {
    let rising = g0 < 0.0 && g1 >= 0.0;
    let falling = g0 > 0.0 && g1 <= 0.0;
    match direction {
        Direction::Rising => rising,
        Direction::Falling => falling,
        Direction::Either => rising || falling,
    }
}

/// The most iterations the root finder takes (each halves the bracket at
/// worst once in three).
const MAX_ITERATIONS: usize = 200;

/// A root of `g` in `[a, b]` where `g(a) = ga` and `g(b) = gb` differ in sign.
pub fn locate_root(mut g: impl FnMut(f64) -> f64, a: f64, b: f64, ga: f64, gb: f64) -> f64 {
    let (mut a, mut b, mut ga, mut gb) = (a, b, ga, gb);
    if gb == 0.0 {
        return b;
    }
    let mut side = 0_i8;
    for _ in 0..MAX_ITERATIONS {
        let width = (b - a).abs();
        if width <= 4.0 * f64::EPSILON * a.abs().max(b.abs()) {
            break;
        }
        let mut t = (a * gb - b * ga) / (gb - ga);
        if !(t > a.min(b) && t < a.max(b)) {
            t = 0.5 * (a + b);
        }
        let gt = g(t);
        if gt == 0.0 {
            return t;
        }
        if (gt < 0.0) == (gb < 0.0) {
            b = t;
            gb = gt;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        } else {
            a = t;
            ga = gt;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        }
    }
    if ga.abs() < gb.abs() {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions() {
        assert!(crossed(-1.0, 1.0, Direction::Rising));
        assert!(!crossed(-1.0, 1.0, Direction::Falling));
        assert!(crossed(1.0, -1.0, Direction::Either));
        assert!(!crossed(0.0, 1.0, Direction::Either));
    }

    #[test]
    fn finds_cosine_zero() {
        let t = locate_root(f64::cos, 1.0, 2.0, 1f64.cos(), 2f64.cos());
        assert!((t - std::f64::consts::FRAC_PI_2).abs() <= 4.0 * f64::EPSILON * 2.0);
    }
}
