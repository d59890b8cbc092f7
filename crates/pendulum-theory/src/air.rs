//! The density of moist air, and the barometric coefficient of a clock.
//!
//! Method: the CIPM-2007 equation for the density of moist air (A. Picard,
//! R. S. Davis, M. Gläser, K. Fujii, "Revised formula for the density of
//! moist air (CIPM-2007)", Metrologia 45 (2008) 149-155):
//! `ρ = p M_a / (Z R T) (1 - x_v (1 - M_v / M_a))`, with the saturation
//! vapour pressure, the enhancement factor and the compressibility factor
//! `Z` of that paper, carbon dioxide at 400 µmol/mol. Its stated
//! uncertainty is 22 parts per million. The tests check dry air against
//! the ideal-gas law computed independently (the compressibility factor is
//! within 5e-4 of 1 at room conditions) and that moist air is lighter by
//! what its water's lower molar mass gives.

/// Molar gas constant, J/(mol K) (CIPM-2007's value).
pub(crate) const R: f64 = 8.314_472;
/// Molar mass of water, kg/mol.
const M_V: f64 = 18.015_28e-3;

/// The molar mass of dry air with a mole fraction `x_co2` of carbon
/// dioxide, kg/mol (CIPM-2007, eq. A1.2 with the oxygen it replaces).
pub(crate) fn dry_air_molar_mass(x_co2: f64) -> f64 {
    (28.965_46 + 12.011 * (x_co2 - 0.0004)) * 1e-3
}

/// The pressures CIPM-2007 holds for, Pa (600 to 1,100 hPa).
pub const PRESSURE_RANGE_PA: (f64, f64) = (60_000.0, 110_000.0);
/// The temperatures CIPM-2007 holds for, °C.
pub const TEMPERATURE_RANGE_C: (f64, f64) = (-20.0, 60.0);

/// The density of moist air, kg/m³, at pressure `p` Pa, temperature `t`
/// °C and relative humidity `h` (0 to 1), by CIPM-2007 (see the module
/// notes). NaN outside 600 to 1,100 hPa and -20 to 60 °C or for a
/// humidity outside [0, 1] (beyond the formula's range).
pub fn air_density(p: f64, t: f64, h: f64) -> f64 {
    if !(PRESSURE_RANGE_PA.0..=PRESSURE_RANGE_PA.1).contains(&p)
        || !(TEMPERATURE_RANGE_C.0..=TEMPERATURE_RANGE_C.1).contains(&t)
        || !(0.0..=1.0).contains(&h)
    {
        return f64::NAN;
    }
    cipm_density(p, t, h)
}

/// The saturation vapour pressure of water over a flat surface, Pa, at
/// `t` °C (CIPM-2007, eq. A1.6, after Davis 1992).
pub(crate) fn saturation_vapour_pressure(t: f64) -> f64 {
    let tk = t + 273.15;
    (1.237_884_7e-5 * tk * tk - 1.912_131_6e-2 * tk + 33.937_110_47 - 6.343_164_5e3 / tk).exp()
}

/// The mole fraction of water vapour in air at `p` Pa, `t` °C and
/// relative humidity `h` (CIPM-2007, eqs. A1.6 and A1.7).
pub(crate) fn vapour_fraction(p: f64, t: f64, h: f64) -> f64 {
    let f = 1.000_62 + 3.14e-8 * p + 5.6e-7 * t * t;
    h * f * saturation_vapour_pressure(t) / p
}

/// The CIPM-2007 density without its range check: its compressibility
/// terms are the first terms of a virial expansion in the pressure, which
/// vanish as the pressure falls, so below 600 hPa it tends to the ideal
/// gas it then is (see [`crate::gas`]).
pub(crate) fn cipm_density(p: f64, t: f64, h: f64) -> f64 {
    let tk = t + 273.15;
    let xv = vapour_fraction(p, t, h);
    // Compressibility (eq. A1.8).
    let z = 1.0
        - p / tk
            * (1.581_23e-6 - 2.9331e-8 * t
                + 1.1043e-10 * t * t
                + (5.707e-6 - 2.051e-8 * t) * xv
                + (1.9898e-4 - 2.376e-6 * t) * xv * xv)
        + p * p / (tk * tk) * (1.83e-11 - 0.765e-8 * xv * xv);
    let ma = dry_air_molar_mass(0.0004);
    p * ma / (z * R * tk) * (1.0 - xv * (1.0 - M_V / ma))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dry air against the ideal gas (the ISA sea-level density at 15 °C
    /// is 1.2250 kg/m³); moist air at 20 °C and 50% against dry air
    /// lightened by its water vapour (2.34 kPa saturated at 20 °C, a
    /// steam-table figure; the mole fraction 1.155% times 1 - 18.015/28.965).
    #[test]
    fn against_the_ideal_gas_and_the_steam_table() {
        for (t, ideal) in [
            (15.0, 1.2250),
            (20.0, 101_325.0 * 0.028_965 / (8.314_462 * 293.15)),
        ] {
            let rho = air_density(101_325.0, t, 0.0);
            assert!(
                (rho / ideal - 1.0).abs() < 6e-4,
                "{t} °C: {rho} against {ideal}"
            );
        }
        let dry = air_density(101_325.0, 20.0, 0.0);
        let moist = air_density(101_325.0, 20.0, 0.5);
        let expected = dry * 0.5 * 2339.0 / 101_325.0 * (1.0 - 18.015 / 28.965);
        assert!(
            ((dry - moist) / expected - 1.0).abs() < 0.01,
            "{}",
            dry - moist
        );
        assert!(air_density(10.0, 20.0, 0.5).is_nan());
    }
}
