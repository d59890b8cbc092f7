//! The Jacobi elliptic functions sn, cn and dn.
//!
//! Method: the descending Gauss transformation (DLMF 22.7(i)), written for
//! the ratio of sn and cn rather than for the amplitude angle. Each level
//! maps `(z, k)` to `(w, k1) = (z/(1 + k1), (1 - k')/(1 + k'))`, and
//! `k1 ≈ k²/4` shrinks quadratically, so after `N` levels (5 to 9) `k_N`
//! is below 2^-32 and `sn(w_N, k_N) = sin w_N` to working precision. Going
//! back up, from DLMF 22.7.1-22.7.3:
//!
//! * `cs(z, k) = cs(w, k1) dn(w, k1) / (1 + k1)` and
//!   `dn(z, k) = ((1 - k1) + cs²) / ((1 + k1) + cs²)`, or, where `|sc| < 1`,
//! * `sc(z, k) = sc(w, k1) (1 + k1) / dn(w, k1)` and
//!   `dn(z, k) = (1 + (1 - k1) sc²) / (1 + (1 + k1) sc²)`.
//!
//! Every step multiplies or adds positive numbers, so the ratio keeps its
//! relative accuracy; `1 - k1 = 2k'/(1 + k')` is carried separately so that
//! nothing is lost as `m -> 1`. (The textbook angle form of the same
//! transformation, A&S 16.4, takes an `asin` of numbers near 1 there and
//! loses up to 1e5 ulp in cn at `m = 1 - 1e-15`.) Finally
//! `sn = ±1/hypot(1, cs)`, `cn = cs sn` (or the same with the roles swapped).
//!
//! Special values first: `m = 0` gives `(sin u, cos u, 1)` and `m = 1` gives
//! `(tanh u, sech u, sech u)` (DLMF 22.5(ii)); NaN in any input gives NaN.
//!
//! Accuracy (`tests/all/reference.rs`, mpmath at 40 digits, `m` over `[0, 1)`
//! including `1 - 1e-15`, `|u| <= 60`): each function's error is at most
//! 4 `ε (|f| + |u f'(u)|)`: a few ulp of the value, plus the unavoidable
//! sensitivity of a periodic function to an ulp of a large argument.

use super::Modulus;

/// sn, cn and dn at one argument and parameter, computed together.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JacobiValues {
    /// `sn(u | m)`.
    pub sn: f64,
    /// `cn(u | m)`.
    pub cn: f64,
    /// `dn(u | m)`.
    pub dn: f64,
}

/// The AGM needs about log2(ln(1/k')) + 4 steps; 32 covers every double.
const MAX_LEVELS: usize = 32;

/// `sn(u|m)`, `cn(u|m)`, `dn(u|m)` for `0 <= m <= 1` (DLMF 22.2); NaN outside.
pub fn jacobi(u: f64, m: f64) -> JacobiValues {
    match Modulus::from_parameter(m) {
        Some(q) => jacobi_modulus(u, &q),
        None => JacobiValues {
            sn: f64::NAN,
            cn: f64::NAN,
            dn: f64::NAN,
        },
    }
}

/// sn, cn, dn from the modulus pair `(k, k')`, DLMF 22.20(ii).
pub fn jacobi_modulus(u: f64, modulus: &Modulus) -> JacobiValues {
    let (k, k_prime) = (modulus.k(), modulus.k_prime());
    if u.is_nan() {
        return JacobiValues {
            sn: f64::NAN,
            cn: f64::NAN,
            dn: f64::NAN,
        };
    }
    if k == 0.0 {
        let (s, c) = u.sin_cos();
        return JacobiValues {
            sn: s,
            cn: c,
            dn: 1.0,
        };
    }
    if k_prime == 0.0 {
        let sech = 1.0 / u.cosh();
        return JacobiValues {
            sn: u.tanh(),
            cn: sech,
            dn: sech,
        };
    }
    gauss_descending(u, k, k_prime)
}

/// Levels stop once `k_N` is below this: the first neglected term of
/// `sn(w, k) = sin w - (k²/4)(w - sin w cos w) cos w` (DLMF 22.10.1) is then
/// below `1.4e-20 |w|`.
const SMALL_MODULUS: f64 = 2.328_306_436_538_696_3e-10; // 2^-32

/// One level of the transformation: `k1` and `1 - k1`.
#[derive(Clone, Copy, Default)]
struct Level {
    k: f64,
    one_minus_k: f64,
}

fn gauss_descending(u: f64, k: f64, k_prime: f64) -> JacobiValues {
    let mut levels = [Level::default(); MAX_LEVELS];
    let mut depth = 0;
    let (mut k, mut k_prime) = (k, k_prime);
    // The argument at the bottom is w_N = u / Π(1 + k_n) = u AGM(1, k')
    // (since K(k) = (1 + k1) K(k1), DLMF 22.7.1 with 19.8.5). The AGM's own
    // means carry about one ulp, where the product of the 1 + k_n would
    // carry half an ulp per level; run it alongside.
    let (mut a, mut b) = (1.0_f64, k_prime);
    while k > SMALL_MODULUS && depth < MAX_LEVELS {
        let one_plus_kp = 1.0 + k_prime;
        // k1 = (1 - k')/(1 + k') = k²/(1 + k')², without the subtraction.
        let k1 = (k / one_plus_kp) * (k / one_plus_kp);
        levels[depth] = Level {
            k: k1,
            one_minus_k: 2.0 * k_prime / one_plus_kp,
        };
        k_prime = 2.0 * k_prime.sqrt() / one_plus_kp;
        k = k1;
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
        depth += 1;
    }
    let (s, c) = (u * a).sin_cos();
    let mut dn = (1.0 - (k * s) * (k * s)).sqrt();
    let levels = &levels[..depth];
    if s.abs() <= c.abs() {
        // Carry sc = sn/cn, which grows going up.
        let mut sc = s / c;
        for level in levels.iter().rev() {
            let next = sc * (1.0 + level.k) / dn;
            dn = if sc.abs() <= 1.0 {
                let sc2 = sc * sc;
                (1.0 + level.one_minus_k * sc2) / (1.0 + (1.0 + level.k) * sc2)
            } else {
                // Divided through by sc², which may be too large to square.
                let inv = (1.0 / sc) * (1.0 / sc);
                (inv + level.one_minus_k) / (inv + 1.0 + level.k)
            };
            sc = next;
        }
        let cn = 1.0_f64.copysign(c) / 1.0_f64.hypot(sc);
        JacobiValues {
            sn: sc * cn,
            cn,
            dn,
        }
    } else {
        // Carry cs = cn/sn, which shrinks going up.
        let mut cs = c / s;
        for level in levels.iter().rev() {
            let next = cs * dn / (1.0 + level.k);
            let cs2 = cs * cs;
            dn = (level.one_minus_k + cs2) / (1.0 + level.k + cs2);
            cs = next;
        }
        let sn = 1.0_f64.copysign(s) / 1.0_f64.hypot(cs);
        JacobiValues {
            sn,
            cn: cs * sn,
            dn,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degenerate_parameters() {
        let v = jacobi(0.7, 0.0);
        assert_eq!(v.sn, 0.7_f64.sin());
        assert_eq!(v.cn, 0.7_f64.cos());
        assert_eq!(v.dn, 1.0);
        let w = jacobi(0.7, 1.0);
        assert_eq!(w.sn, 0.7_f64.tanh());
        assert_eq!(w.dn, 1.0 / 0.7_f64.cosh());
        assert!(jacobi(f64::NAN, 0.3).sn.is_nan());
        assert!(jacobi(0.3, 2.0).cn.is_nan());
    }

    #[test]
    fn at_zero() {
        for m in [0.1, 0.5, 0.9, 1.0 - 1e-12] {
            let v = jacobi(0.0, m);
            assert_eq!((v.sn, v.cn, v.dn), (0.0, 1.0, 1.0), "m = {m}");
            let w = jacobi(-0.0, m);
            assert_eq!(w.sn, 0.0);
        }
    }

    #[test]
    fn quarter_period_values() {
        // sn(K) = 1, cn(K) = 0, dn(K) = k' (DLMF 22.5.1).
        let m = 0.7;
        let k = super::super::ellipk(m);
        let v = jacobi(k, m);
        assert!((v.sn - 1.0).abs() < 4.0 * f64::EPSILON);
        assert!(v.cn.abs() < 8.0 * f64::EPSILON);
        assert!((v.dn - (1.0_f64 - m).sqrt()).abs() < 8.0 * f64::EPSILON);
    }
}
