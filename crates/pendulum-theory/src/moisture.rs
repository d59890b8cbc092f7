//! Wood and the water in the air: how much moisture wood holds in air of a
//! given humidity and temperature, and how much longer that makes it along
//! the grain.
//!
//! Wood takes up water in its cell walls until it is in equilibrium with
//! the air (its equilibrium moisture content, EMC, in per cent of its dry
//! mass) and grows as it does, below the fibre saturation point (about 30%)
//! in proportion to the water it holds. Along the grain the growth is
//! small: from green to oven-dry normal wood shrinks 0.1% to 0.2% along its
//! length (USDA Forest Products Laboratory, *Wood Handbook*, FPL-GTR-190,
//! 2010, p. 4-5), across it 4% to 8%. A wooden pendulum rod is cut with its
//! grain along its length: its length follows the air's humidity, slowly
//! (days, through a varnish), by about a hundredth of what it follows a
//! steel rod's temperature with.

/// The fibre saturation point, % moisture content: below it wood shrinks
/// in proportion to the water it loses (Peck, *Shrinkage of Wood*, FPL
/// R1650, 1947: "about 30 per cent"; the Wood Handbook's shrinkage
/// equation takes 30).
pub const FIBRE_SATURATION_PERCENT: f64 = 30.0;

/// Normal wood's shrinkage along the grain from green to oven-dry, as a
/// fraction of its green length: 0.15%, the middle of the Wood Handbook's
/// "between 0.1% and 0.2% for most species" (FPL-GTR-190, p. 4-5; reaction
/// and juvenile wood shrink up to 2% and do not make pendulum rods).
pub const LONGITUDINAL_SHRINKAGE: f64 = 0.0015;

/// Wood's growth along the grain per percentage point of moisture content
/// below the fibre saturation point, 1/%:
/// [`LONGITUDINAL_SHRINKAGE`] / [`FIBRE_SATURATION_PERCENT`], 5e-5. Uncertain
/// by a third either way (the Handbook's 0.1% to 0.2%).
pub const WOOD_MOISTURE_EXPANSION: f64 = LONGITUDINAL_SHRINKAGE / FIBRE_SATURATION_PERCENT;

/// The equilibrium moisture content of wood, % of its oven-dry mass, in air
/// of relative humidity `humidity` (0 to 1) at `temperature_c`.
///
/// Method: the Hailwood-Horrobin two-hydrate sorption isotherm with the
/// temperature-dependent constants Simpson fitted to the sorption table of
/// USDA Handbook 72 (Simpson, Wood and Fiber 5 (1973) 41-49; the Wood
/// Handbook's equation 4-5, temperature in °F):
/// `M = 1800/W [Kh/(1 - Kh) + (K₁Kh + 2K₁K₂K²h²)/(1 + K₁Kh + K₁K₂K²h²)]`.
/// Simpson gives its mean deviation from the table as under 0.13 percentage
/// points and the largest as 0.9; against the values other programs print
/// from it (`tests/moisture.rs`) it agrees within 0.15 points from 25% to
/// 90% humidity. Wood's hysteresis (it holds 1-2 points more water drying
/// than wetting) and the species' differences are not in it. Valid from 0
/// to 100 °C; the humidity is clamped to 0 to 0.99 (at saturation the
/// fitted form diverges; wood's own limit is the fibre saturation point,
/// which is where the result is capped).
pub fn equilibrium_moisture_content(humidity: f64, temperature_c: f64) -> f64 {
    let h = humidity.clamp(0.0, 0.99);
    let t = temperature_c * 1.8 + 32.0;
    let w = 330.0 + 0.452 * t + 0.00415 * t * t;
    let k = 0.791 + 0.000463 * t - 0.000000844 * t * t;
    let k1 = 6.34 + 0.000775 * t - 0.0000935 * t * t;
    let k2 = 1.09 + 0.0284 * t - 0.0000904 * t * t;
    let kh = k * h;
    let m = 1800.0 / w
        * (kh / (1.0 - kh)
            + (k1 * kh + 2.0 * k1 * k2 * kh * kh) / (1.0 + k1 * kh + k1 * k2 * kh * kh));
    m.min(FIBRE_SATURATION_PERCENT)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dry_air_holds_no_water_and_more_humid_air_more() {
        assert_eq!(equilibrium_moisture_content(0.0, 20.0), 0.0);
        let mut before = 0.0;
        for i in 1..=99 {
            let m = equilibrium_moisture_content(i as f64 / 100.0, 20.0);
            assert!(m > before, "{i}% gives {m}");
            before = m;
        }
        assert!(before <= FIBRE_SATURATION_PERCENT);
    }
}
