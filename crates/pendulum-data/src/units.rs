//! Units as people write them, shared with the command line's flags: a
//! file's header takes the units its flags take (`pressure_bar` as
//! `--pressure 1bar`), from one list.

/// A unit's spellings and its size in SI: a value `v` in it is
/// `v × si + offset` in the dimension's base unit (the offset is only
/// temperature's: kelvin and °F against °C).
#[derive(Debug)]
pub struct Unit {
    /// Its spellings, the first the one printed.
    pub names: &'static [&'static str],
    /// Its size in the base unit.
    pub si: f64,
    /// Added after the size (temperatures).
    pub offset: f64,
}

/// A unit with no offset.
pub const fn unit(names: &'static [&'static str], si: f64) -> Unit {
    Unit {
        names,
        si,
        offset: 0.0,
    }
}

/// Pressures, in pascals.
pub const PRESSURE: &[Unit] = &[
    unit(&["Pa"], 1.0),
    unit(&["hPa", "mbar"], 100.0),
    unit(&["kPa"], 1000.0),
    unit(&["bar"], 100_000.0),
    unit(&["atm"], 101_325.0),
    // The conventional inch and millimetre of mercury.
    unit(&["inHg"], 3386.389),
    unit(&["mmHg", "Torr"], 133.322_387_415),
];

/// The size in SI of `name` among `units`, in any case.
pub fn si_factor(units: &[Unit], name: &str) -> Option<f64> {
    units
        .iter()
        .find(|u| u.names.iter().any(|n| n.eq_ignore_ascii_case(name)))
        .map(|u| u.si)
}
