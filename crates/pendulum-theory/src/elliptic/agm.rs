//! The arithmetic-geometric mean and the two by-products of it that the
//! complete elliptic integrals need.
//!
//! Method: Gauss's AGM iteration, DLMF 19.8.1 and 19.8.6:
//! `a_{n+1} = (a_n + b_n)/2`, `b_{n+1} = sqrt(a_n b_n)`, `c_{n+1} = (a_n - b_n)/2`.
//! It converges quadratically, so at most 6 iterations are needed for
//! `k' >= 1e-3` (amplitudes up to 179.9 degrees) and about 15 for `k' = 1e-300`.
//!
//! Why start from the complementary modulus `k'`: at an amplitude close to
//! 180 degrees `k' = cos(A0/2)` is small and is known to full relative
//! precision, whereas `1 - sin^2(A0/2)` would have lost most of its digits.

/// The relative size of `c_{n+1} / a_{n+1}` below which one more arithmetic
/// mean equals the AGM to within a quarter of an ulp: the AGM and the
/// arithmetic mean differ by about `c^2 / (4 a)` (DLMF 19.8.2), and
/// `(2^-26)^2 / 4 = 2^-54`.
const CONVERGED: f64 = 1.490_116_119_384_765_6e-8; // 2^-26

/// No finite input needs more: the count grows like log2(ln(1/k')) and is
/// about 15 for the smallest subnormal `k'`. The cap only guards the loop.
const MAX_ITERATIONS: usize = 64;

/// The AGM of `1` and `b`, together with `S = sum_{n>=1} 2^(n-1) c_n^2`
/// (DLMF 19.8.6), which gives `E` and `K - E` from the same iteration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AgmWithSum {
    /// `AGM(1, b)`.
    pub mean: f64,
    /// `sum_{n>=1} 2^(n-1) c_n^2`, with `c_0` not included.
    pub sum: f64,
}

/// AGM(1, b) and its weighted sum of squared half-differences.
///
/// `b` must lie in `(0, 1]`; the callers handle `b = 0` (where the AGM is 0
/// and the iteration never meets its stopping rule) and NaN before calling.
pub(crate) fn agm_with_sum(b: f64) -> AgmWithSum {
    debug_assert!(b > 0.0 && b <= 1.0, "agm_with_sum: b = {b}");
    let (mut a, mut b) = (1.0_f64, b);
    let mut sum = 0.0;
    let mut weight = 1.0; // 2^(n-1) for n = 1
    for _ in 0..MAX_ITERATIONS {
        let c = 0.5 * (a - b);
        let a_next = 0.5 * (a + b);
        sum += weight * c * c;
        if c <= CONVERGED * a_next {
            return AgmWithSum { mean: a_next, sum };
        }
        weight *= 2.0;
        b = (a * b).sqrt();
        a = a_next;
    }
    AgmWithSum { mean: a, sum }
}

/// `AGM(1, b)` alone.
#[inline]
pub(crate) fn agm(b: f64) -> f64 {
    debug_assert!(b > 0.0 && b <= 1.0, "agm: b = {b}");
    let (mut a, mut b) = (1.0_f64, b);
    for _ in 0..MAX_ITERATIONS {
        let a_next = 0.5 * (a + b);
        if 0.5 * (a - b) <= CONVERGED * a_next {
            return a_next;
        }
        b = (a * b).sqrt();
        a = a_next;
    }
    a
}

/// `AGM(1, b)` and its derivative `d AGM(1, b) / db`, by differentiating
/// each step of the iteration (forward-mode differentiation):
/// `a'_{n+1} = (a'_n + b'_n)/2`, `b'_{n+1} = (a_n b'_n + b_n a'_n) / (2 b_{n+1})`,
/// from `a'_0 = 0`, `b'_0 = 1`. Every term is non-negative, so the derivative
/// keeps its relative accuracy; the closed form `dK/dk = (E - k'²K)/(k k'²)`
/// (DLMF 19.4.1) would need a difference of integrals and a division by `k'`.
pub(crate) fn agm_with_derivative(b: f64) -> (f64, f64) {
    debug_assert!(b > 0.0 && b <= 1.0, "agm_with_derivative: b = {b}");
    let (mut a, mut b) = (1.0_f64, b);
    let (mut da, mut db) = (0.0_f64, 1.0_f64);
    for _ in 0..MAX_ITERATIONS {
        let a_next = 0.5 * (a + b);
        let da_next = 0.5 * (da + db);
        // The derivative of the neglected c²/(4a) is of relative size c/a,
        // first order: it needs c/a below a quarter ulp, not its square root.
        if 0.5 * (a - b) <= 0.25 * f64::EPSILON * a_next {
            return (a_next, da_next);
        }
        let g = (a * b).sqrt();
        db = 0.5 * (a * db + b * da) / g;
        b = g;
        a = a_next;
        da = da_next;
    }
    (a, da)
}

/// `1 - AGM(1, k')` computed without cancellation, from the modulus `k` and
/// its complement `k'` (with `k^2 + k'^2 = 1`).
///
/// Instead of the means `a_n`, `b_n` it iterates their deficits from one,
/// `u_n = 1 - a_n` and `v_n = 1 - b_n`, which are all non-negative:
/// `u_{n+1} = (u_n + v_n)/2` and, since `1 - a b = u + a v`,
/// `v_{n+1} = (u_n + a_n v_n) / (1 + sqrt(a_n b_n))`. The start is
/// `u_0 = 0`, `v_0 = 1 - k' = k^2 / (1 + k')`. Every operation adds or
/// divides non-negative numbers, so the result keeps its relative accuracy
/// even when it is 1e-14 (an amplitude of 1e-6 rad), where `1 - AGM`
/// computed as a difference would keep about two digits.
pub(crate) fn agm_deficit(k: f64, k_prime: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, k_prime);
    let (mut u, mut v) = (0.0_f64, k * k / (1.0 + k_prime));
    for _ in 0..MAX_ITERATIONS {
        let d = v - u;
        let u_next = u + 0.5 * d;
        // The true deficit exceeds u_next by about d^2 / 16 (DLMF 19.8.2);
        // stop once that is below a quarter ulp of u_next.
        if d * d <= 4.0 * f64::EPSILON * u_next {
            return u_next;
        }
        let g = (a * b).sqrt();
        v = (u + a * v) / (1.0 + g);
        u = u_next;
        a = 0.5 * (a + b);
        b = g;
    }
    u
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agm_of_equal_arguments_is_the_argument() {
        assert_eq!(agm(1.0), 1.0);
        assert_eq!(
            agm_with_sum(1.0),
            AgmWithSum {
                mean: 1.0,
                sum: 0.0
            }
        );
        assert_eq!(agm_deficit(0.0, 1.0), 0.0);
    }

    #[test]
    fn agm_of_one_and_root_two_half_is_gauss_constant_related() {
        // AGM(1, 1/sqrt 2) = 0.8472130847939790866064991234821916... (Gauss).
        let m = agm(std::f64::consts::FRAC_1_SQRT_2);
        assert!((m - 0.847_213_084_793_979).abs() <= 2.0 * f64::EPSILON);
    }

    #[test]
    fn deficit_matches_difference_where_that_is_accurate() {
        for &b in &[0.9_f64, 0.5, 0.1, 1e-3, 1e-12] {
            let k = (1.0 - b * b).sqrt();
            let direct = 1.0 - agm(b);
            let deficit = agm_deficit(k, b);
            assert!((direct - deficit).abs() <= 4.0 * f64::EPSILON, "b = {b}");
        }
    }

    #[test]
    fn tiny_subnormal_complement_terminates() {
        let m = agm(f64::from_bits(1));
        assert!(m > 0.0 && m < 0.01);
    }
}
