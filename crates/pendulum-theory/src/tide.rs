//! The Earth's body tide in gravity, and the rate it gives a pendulum.
//!
//! Method: in the time domain, from the Moon's and the Sun's geocentric
//! positions (the partial ELP-2000/82 lunar theory, 10″ in longitude, and
//! VSOP87 for the Sun, both as J. Meeus, *Astronomical Algorithms*, 2nd
//! ed., chapters 47 and 32, through the `astro` crate). The tidal
//! potential of each body is expanded in degrees 2 and 3 (Laplace's
//! species for degree 2: long-period, diurnal, semidiurnal), each
//! species' gravity is multiplied by the elastic Earth's gravimetric
//! factor δ for it (1 + h − 3k/2 for degree 2), and the diurnal band's
//! one strong resonance (the free core nutation's pull on K1, δ = 1.135
//! against O1's 1.154) is applied to the K1 line, found as the year-long
//! mean of the diurnal potential's sidereal-frequency part. The
//! gravimetric factors are those of the Wahr–Dehant elastic Earth as
//! ETERNA uses them (H.-G. Wenzel, "The nanogal software", 1996; Dehant
//! 1987). No ocean loading, no polar motion, no atmosphere.
//!
//! Accuracy: against ETERNA's PREDICT (PyGTide 0.9.7, Hartmann–Wenzel
//! catalogue) over a month, hourly, at two stations: see test `tide.rs`
//! for the measured RMS difference, required below 3 nm/s².
//!
//! Sign: [`gravity_change`] is the change of the magnitude of g, positive
//! when g is larger (the Moon at the horizon); a pendulum then runs fast,
//! by `Δg / 2g` ([`rate_s_per_day`]).

use crate::analysis::{require_finite, Refusal};
use crate::error::format_significant;
use astro::{ecliptic, lunar, sun, time};

/// The Moon's gravitational parameter GM, m³/s² (DE430).
const GM_MOON: f64 = 4.902_800_066e12;
/// The Sun's, m³/s² (IAU 2015 nominal).
const GM_SUN: f64 = 1.327_124_400_18e20;
/// The astronomical unit, m (IAU 2012).
const AU: f64 = 1.495_978_707e11;
/// WGS 84 equatorial radius, m.
const A_WGS84: f64 = 6_378_137.0;
/// WGS 84 flattening.
const F_WGS84: f64 = 1.0 / 298.257_223_563;
/// TT − UTC since 2017-01-01 (37 leap seconds + 32.184 s), s; earlier
/// dates are off by at most 5 s here, 2.5″ of the Moon's motion.
const TT_MINUS_UTC: f64 = 69.184;

/// Gravimetric factors δ of the elastic Earth (Wahr–Dehant; Wenzel 1996):
/// degree 2 long-period, diurnal (O1), semidiurnal (M2); K1; degree 3.
const DELTA_20: f64 = 1.1576;
const DELTA_21: f64 = 1.1542;
const DELTA_22: f64 = 1.1617;
const DELTA_K1: f64 = 1.1346;
const DELTA_3: f64 = 1.0694;

/// A place on the Earth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Station {
    /// Geodetic latitude, degrees north (WGS 84).
    pub latitude_deg: f64,
    /// Longitude, degrees east.
    pub longitude_deg: f64,
    /// Height above the ellipsoid, m.
    pub height_m: f64,
}

impl Station {
    /// Checks the place: latitude in [−90, 90], longitude finite, height
    /// from −11 km to 100 km; refusals name `latitude`, `longitude`,
    /// `height`.
    pub fn checked(self) -> Result<Station, Refusal> {
        let lat = require_finite("latitude", self.latitude_deg)?;
        if lat.abs() > 90.0 {
            return Err(Refusal::field(
                "latitude",
                format!(
                    "must be between -90° and 90°, got {}°",
                    format_significant(lat, 6)
                ),
            ));
        }
        require_finite("longitude", self.longitude_deg)?;
        let h = require_finite("height", self.height_m)?;
        if !(-11_000.0..=100_000.0).contains(&h) {
            return Err(Refusal::field(
                "height",
                format!(
                    "must be between -11 km and 100 km, got {} m",
                    format_significant(h, 6)
                ),
            ));
        }
        Ok(self)
    }

    /// The geocentric radius (m), geocentric latitude (rad) and the angle
    /// between the geodetic and geocentric verticals (rad).
    fn geocentric(&self) -> (f64, f64, f64) {
        let phi = self.latitude_deg.to_radians();
        let e2 = F_WGS84 * (2.0 - F_WGS84);
        let n = A_WGS84 / (1.0 - e2 * phi.sin().powi(2)).sqrt();
        let p = (n + self.height_m) * phi.cos();
        let z = (n * (1.0 - e2) + self.height_m) * phi.sin();
        let r = p.hypot(z);
        let phi_c = z.atan2(p);
        (r, phi_c, phi - phi_c)
    }
}

/// A body's geocentric equatorial position: right ascension and
/// declination (rad, mean equator and equinox of date) and distance (m).
struct Body {
    gm: f64,
    ra: f64,
    dec: f64,
    distance: f64,
}

/// The Julian day (UT) of Unix time `t`.
fn julian_day(t: f64) -> f64 {
    2_440_587.5 + t / 86_400.0
}

/// The Moon and the Sun at Unix time `t` (UTC).
fn bodies(t: f64) -> [Body; 2] {
    let jde = julian_day(t + TT_MINUS_UTC);
    let eps = ecliptic::mn_oblq_IAU(jde);
    let equatorial = |lon: f64, lat: f64| {
        let (sl, cl, sb, cb) = (lon.sin(), lon.cos(), lat.sin(), lat.cos());
        let (se, ce) = (eps.sin(), eps.cos());
        let ra = (sl * ce * cb - sb * se).atan2(cl * cb);
        let dec = (sb * ce + cb * se * sl).asin();
        (ra, dec)
    };
    let (moon, moon_km) = lunar::geocent_ecl_pos(jde);
    let (sun, sun_au) = sun::geocent_ecl_pos(jde);
    let (mra, mdec) = equatorial(moon.long, moon.lat);
    let (sra, sdec) = equatorial(sun.long, sun.lat);
    [
        Body {
            gm: GM_MOON,
            ra: mra,
            dec: mdec,
            distance: moon_km * 1e3,
        },
        Body {
            gm: GM_SUN,
            ra: sra,
            dec: sdec,
            distance: sun_au * AU,
        },
    ]
}

/// The bodies' positions at knots three hours apart, interpolated by
/// four-point Lagrange polynomials in geocentric Cartesian coordinates:
/// the Moon moves 1.6° between knots and the cubic's error is below
/// 0.01″ (its fourth difference), far under the theories' 10″; it spares
/// the series' evaluation at every time asked for.
struct Ephemeris {
    start: f64,
    /// The knots' count from `start` to past the last time.
    count: usize,
    /// The knots the times need (four about each), by their index from
    /// `start`, in order: each body's x, y, z (m). Times years apart need
    /// a few knots each, not every knot between them (two times 200 years
    /// apart took 584,000 knots and 79 s).
    knots: Vec<(usize, [[f64; 3]; 2])>,
}

/// The knots' spacing, s.
const KNOT: f64 = 3.0 * 3600.0;

impl Ephemeris {
    /// The knots about each of `times` (finite), on the grid from the
    /// earliest with two to spare at each end.
    fn new(times: &[f64]) -> Ephemeris {
        let (from, to) = times
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
                (a.min(t), b.max(t))
            });
        let start = (from / KNOT).floor() * KNOT - 2.0 * KNOT;
        let count = ((to - start) / KNOT).ceil() as usize + 3;
        let mut needed: Vec<usize> = times
            .iter()
            .flat_map(|&t| {
                let i = Self::index(start, count, t);
                i - 1..=i + 2
            })
            .collect();
        needed.sort_unstable();
        needed.dedup();
        let knots = needed
            .into_iter()
            .map(|k| {
                let b = bodies(start + k as f64 * KNOT);
                (k, [cartesian(&b[0]), cartesian(&b[1])])
            })
            .collect();
        Ephemeris {
            start,
            count,
            knots,
        }
    }

    /// The knot before `t`'s interval: its neighbours `i - 1 ..= i + 2`
    /// interpolate it.
    fn index(start: f64, count: usize, t: f64) -> usize {
        (((t - start) / KNOT).floor() as usize).clamp(1, count - 3)
    }

    /// The bodies at `t`.
    fn at(&self, t: f64) -> [Body; 2] {
        let u = (t - self.start) / KNOT;
        let i = Self::index(self.start, self.count, t);
        let x = u - i as f64;
        // (Knots i - 1 to i + 2 were all made, so they follow each other.)
        let first = self.knots.partition_point(|(k, _)| *k < i - 1);
        let knots = &self.knots[first..first + 4];
        // Lagrange weights on the knots i-1, i, i+1, i+2.
        let w = [
            -x * (x - 1.0) * (x - 2.0) / 6.0,
            (x + 1.0) * (x - 1.0) * (x - 2.0) / 2.0,
            -(x + 1.0) * x * (x - 2.0) / 2.0,
            (x + 1.0) * x * (x - 1.0) / 6.0,
        ];
        let mut out = [[0.0; 3]; 2];
        for (k, wk) in w.iter().enumerate() {
            for (body, o) in out.iter_mut().enumerate() {
                for (c, v) in o.iter_mut().enumerate() {
                    *v += wk * knots[k].1[body][c];
                }
            }
        }
        [polar(out[0], GM_MOON), polar(out[1], GM_SUN)]
    }
}

/// A body's geocentric equatorial Cartesian position, m.
fn cartesian(b: &Body) -> [f64; 3] {
    let (sd, cd) = b.dec.sin_cos();
    let (sa, ca) = b.ra.sin_cos();
    [b.distance * cd * ca, b.distance * cd * sa, b.distance * sd]
}

/// The body at a Cartesian position.
fn polar(v: [f64; 3], gm: f64) -> Body {
    let distance = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    Body {
        gm,
        ra: v[1].atan2(v[0]),
        dec: (v[2] / distance).asin(),
        distance,
    }
}

/// The local mean sidereal angle (rad) at Unix time `t`: Greenwich mean
/// sidereal time (UT1 taken as UTC: 0.9 s at most, 0.4″ of the Moon)
/// plus the east longitude.
fn sidereal(t: f64, longitude: f64) -> f64 {
    time::mn_sidr(julian_day(t)) + longitude
}

/// The tidal acceleration along the station's upward normal (m/s²,
/// positive up: g smaller) for a rigid Earth split in parts, each to be
/// scaled by its δ: degree-2 species 0, 1, 2, and degree 3.
fn parts(station: &Station, t: f64, ephemeris: &Ephemeris) -> [f64; 4] {
    let (r, phi, zeta) = station.geocentric();
    let lst = sidereal(t, station.longitude_deg.to_radians());
    let mut out = [0.0; 4];
    for b in ephemeris.at(t) {
        let h = lst - b.ra;
        let (sd, cd) = (b.dec.sin(), b.dec.cos());
        let (sp, cp) = (phi.sin(), phi.cos());
        let k2 = b.gm * r * r / b.distance.powi(3);
        // Laplace's species of P2(cos ψ) and their φ-derivatives.
        let s0 = 0.25 * (3.0 * sp * sp - 1.0) * (3.0 * sd * sd - 1.0);
        let s1 = 0.75 * (2.0 * phi).sin() * (2.0 * b.dec).sin() * h.cos();
        let s2 = 0.75 * cp * cp * cd * cd * (2.0 * h).cos();
        let d0 = 0.25 * 3.0 * (2.0 * phi).sin() * (3.0 * sd * sd - 1.0);
        let d1 = 0.75 * 2.0 * (2.0 * phi).cos() * (2.0 * b.dec).sin() * h.cos();
        let d2 = -0.75 * (2.0 * phi).sin() * cd * cd * (2.0 * h).cos();
        // Up along the ellipsoid's normal: radial (∂W/∂r = 2W/r) by cos ζ
        // and northward ((1/r) ∂W/∂φ') by sin ζ.
        let up = |s: f64, d: f64| k2 / r * (2.0 * s * zeta.cos() + d * zeta.sin());
        out[0] += up(s0, d0);
        out[1] += up(s1, d1);
        out[2] += up(s2, d2);
        // Degree 3: W₃ = GM r³/R⁴ P₃(cos ψ), radial derivative 3W₃/r.
        let u = sp * sd + cp * cd * h.cos();
        let p3 = 0.5 * (5.0 * u.powi(3) - 3.0 * u);
        out[3] += 3.0 * b.gm * r * r / b.distance.powi(4) * p3 * zeta.cos();
    }
    out
}

/// The K1 line's coefficients at `t`: the mean over a year (every other
/// day, centred on `t`) of the bodies' `GM sin 2δ cos α / R³` and
/// `GM sin 2δ sin α / R³`, the part of the diurnal potential's
/// declination term that does not turn with the bodies. The diurnal
/// species is `(3/4) r² sin 2φ' sin 2δ cos(T − α) GM/R³`, `T` the local
/// sidereal angle, so its K1 line is `(3/4) r² sin 2φ' (a cos T + b sin
/// T)`.
fn k1_means(t: f64) -> (f64, f64) {
    let (mut a, mut b) = (0.0, 0.0);
    const DAYS: usize = 183;
    for k in 0..DAYS {
        let tk = t + 2.0 * (k as f64 - (DAYS as f64 - 1.0) / 2.0) * 86_400.0;
        for body in bodies(tk) {
            let w = body.gm / body.distance.powi(3) * (2.0 * body.dec).sin();
            a += w * body.ra.cos();
            b += w * body.ra.sin();
        }
    }
    (a / DAYS as f64, b / DAYS as f64)
}

/// The first of the ephemerides' range, 1900-01-01, Unix s.
const FIRST_TIME: f64 = -2_208_988_800.0;
/// The last, 2100-01-01, Unix s.
const LAST_TIME: f64 = 4_102_444_800.0;

/// The K1 line's coefficients change over years (the lunar node's 18.6):
/// computed every 30 days and interpolated.
const STEP: f64 = 30.0 * 86_400.0;

/// Refuses a time that is not finite or outside 1900–2100, by its index.
fn check_times(times: &[f64]) -> Result<(), Refusal> {
    match times
        .iter()
        .position(|t| !(FIRST_TIME..=LAST_TIME).contains(t))
    {
        Some(i) => Err(Refusal::sample(
            "time",
            i,
            "must be between the years 1900 and 2100 (the ephemerides' range)",
        )),
        None => Ok(()),
    }
}

/// Computing time of a row: its bodies interpolated, its species (1.2 µs
/// measured over 3.1 million rows; 15 µs with the command line's
/// printing of it, rounded up), s.
const SECONDS_PER_ROW: f64 = 1.5e-5;
/// Of a knot of the ephemeris: the Moon's and the Sun's series (38 µs
/// measured, over 23,000 knots 15 h apart), s.
const SECONDS_PER_KNOT: f64 = 5e-5;
/// Of a month's K1 means: 183 days of both bodies (12 ms measured, over
/// 732 and 2,435 months), s.
const SECONDS_PER_MONTH: f64 = 1.5e-2;
/// The most rows of a table ([`series`]): 320 MB with their times.
pub const MAX_ROWS: f64 = 1e7;

/// The computing time of the body tide at `n` times spanning `span` s:
/// its rows, the knots about them (four a time at most, one every 3 h at
/// least) and the K1 means of the months they fall in (two a time at
/// most, one every 30 days at least), s. Within 2.3 times of the time
/// measured for a year every 10 s (3.1 million rows: 3.96 s, estimated
/// 47 s with the printing's share), 15 h for ten years (2.4 s, estimated
/// 3.1 s) and 40 days for 200 years (29.5 s, estimated 55 s).
pub fn work_seconds(n: f64, span: f64) -> f64 {
    let knots = (4.0 * n).min(span / KNOT + 5.0);
    let months = (2.0 * n).min(span / STEP + 2.0);
    n * SECONDS_PER_ROW + knots * SECONDS_PER_KNOT + months * SECONDS_PER_MONTH
}

/// Judges the work of `n` times spanning `span` s ([`work_seconds`]),
/// a refusal naming `field`.
fn judge(field: &'static str, n: f64, span: f64, force: bool) -> Result<(), Refusal> {
    crate::analysis::judge_work(
        field,
        format_args!(
            "{} times over {} days",
            crate::analysis::count(n),
            format_significant(span / 86_400.0, 3)
        ),
        work_seconds(n, span),
        force,
    )
}

/// The change of gravity's magnitude by the body tide at `station` at
/// each Unix time in `times` (s, UTC), m/s², positive when g is larger.
/// Refuses a station out of range and times that are not finite or
/// outside the years 1900–2100 (the ephemerides' range here).
pub fn gravity_change(station: Station, times: &[f64]) -> Result<Vec<f64>, Refusal> {
    let station = station.checked()?;
    check_times(times)?;
    let (r, phi, zeta) = station.geocentric();
    let mut cache: std::collections::HashMap<i64, (f64, f64)> = std::collections::HashMap::new();
    let mut k1_at = |t: f64| -> f64 {
        let k = (t / STEP).floor();
        let mut means = |key: i64| -> (f64, f64) {
            *cache
                .entry(key)
                .or_insert_with(|| k1_means(key as f64 * STEP))
        };
        let (c0, c1) = (means(k as i64), means(k as i64 + 1));
        let w = t / STEP - k;
        let (a, b) = (c0.0 + w * (c1.0 - c0.0), c0.1 + w * (c1.1 - c0.1));
        let lst = sidereal(t, station.longitude_deg.to_radians());
        let potential = 0.75 * r * r * (a * lst.cos() + b * lst.sin());
        potential / r
            * (2.0 * (2.0 * phi).sin() * zeta.cos() + 2.0 * (2.0 * phi).cos() * zeta.sin())
    };
    let ephemeris = Ephemeris::new(times);
    Ok(times
        .iter()
        .map(|&t| {
            let p = parts(&station, t, &ephemeris);
            let up = DELTA_20 * p[0]
                + DELTA_21 * p[1]
                + DELTA_22 * p[2]
                + DELTA_3 * p[3]
                + (DELTA_K1 - DELTA_21) * k1_at(t);
            -up
        })
        .collect())
}

/// The rate a pendulum gains (s/day) when gravity changes by `dg` from
/// `g`: `T ∝ g^(−1/2)`, so the rate is `Δg / 2g` of a day (to first order:
/// the tide's Δg/g is 3e-7 at most, the second order 1e-14).
pub fn rate_s_per_day(dg: f64, g: f64) -> f64 {
    dg / (2.0 * g) * 86_400.0
}

/// One row of a tide table.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct TideRow {
    /// Unix time, s (UTC).
    pub time_unix_s: f64,
    /// The change of g's magnitude, nm/s² (positive: g larger).
    pub gravity_change_nm_s2: f64,
    /// The rate it gives a pendulum, s/day (positive: gaining).
    pub rate_s_per_day: f64,
}

/// The body tide at `station` at each Unix time of `times` (s, UTC), with
/// the pendulum's rate against the station's normal gravity (WGS 84).
/// Times whose work ([`work_seconds`]) is more than a few seconds need
/// `force` (ten million took 50 s, with nothing to stop them).
pub fn at(station: Station, times: &[f64], force: bool) -> Result<Vec<TideRow>, Refusal> {
    let station = station.checked()?;
    check_times(times)?;
    let (first, last) = times
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
            (a.min(t), b.max(t))
        });
    let span = if times.is_empty() { 0.0 } else { last - first };
    judge("time", times.len() as f64, span, force)?;
    let g = crate::gravity::normal_gravity(station.latitude_deg, station.height_m)
        .map_err(|e| Refusal::input("height", &e))?;
    Ok(gravity_change(station, times)?
        .into_iter()
        .zip(times)
        .map(|(dg, &t)| TideRow {
            time_unix_s: t,
            gravity_change_nm_s2: dg * 1e9,
            rate_s_per_day: rate_s_per_day(dg, g),
        })
        .collect())
}

/// The body tide at `station` from Unix time `from` to `to` (s, both
/// included when the steps reach `to`) every `every` s, with each row's
/// pendulum rate against the station's normal gravity (WGS 84). Refuses
/// a step that is not positive, `to` before `from`, times outside
/// 1900–2100, and more than [`MAX_ROWS`]; a table whose work
/// ([`work_seconds`]) is more than a few seconds (3·10⁵ rows, or a row a
/// month or fewer over decades) needs `force`.
///
/// # Examples
///
/// ```
/// use pendulum_theory::tide::{series, Station};
///
/// // A day of the body tide at Greenwich, hourly from 2024-01-01 00:00 UTC.
/// let greenwich = Station { latitude_deg: 51.4779, longitude_deg: 0.0, height_m: 46.0 };
/// let rows = series(greenwich, 1_704_067_200.0, 1_704_153_600.0, 3600.0, false)?;
/// assert_eq!(rows.len(), 25);
/// let dg = rows.iter().map(|r| r.gravity_change_nm_s2);
/// let range = dg.clone().fold(f64::MIN, f64::max) - dg.fold(f64::MAX, f64::min);
/// // A tide's range is a few µm/s² at most; a pendulum's rate is Δg/2g of a day.
/// assert!(range > 500.0 && range < 3500.0);
/// assert!(rows.iter().all(|r| r.rate_s_per_day.abs() < 0.02));
/// # Ok::<(), pendulum_theory::analysis::Refusal>(())
/// ```
pub fn series(
    station: Station,
    from: f64,
    to: f64,
    every: f64,
    force: bool,
) -> Result<Vec<TideRow>, Refusal> {
    let station = station.checked()?;
    let every = require_finite("every", every)?;
    if every <= 0.0 {
        return Err(Refusal::field(
            "every",
            format!("must be positive, got {} s", format_significant(every, 6)),
        ));
    }
    if to < from {
        return Err(Refusal::field("to", "is before --from"));
    }
    check_times(&[from, to])?;
    let steps = ((to - from) / every * (1.0 + 1e-12)).floor();
    if steps + 1.0 > MAX_ROWS {
        return Err(Refusal::field(
            "every",
            format!(
                "{} rows: more than the {} a table may have; give a longer step",
                crate::analysis::count(steps + 1.0),
                crate::analysis::count(MAX_ROWS)
            ),
        ));
    }
    // Judged as Python's times are: over the span of the rows made.
    judge("every", steps + 1.0, steps * every, force)?;
    let times: Vec<f64> = (0..=steps as u64)
        .map(|k| from + k as f64 * every)
        .collect();
    let g = crate::gravity::normal_gravity(station.latitude_deg, station.height_m)
        .map_err(|e| Refusal::input("height", &e))?;
    Ok(gravity_change(station, &times)?
        .into_iter()
        .zip(&times)
        .map(|(dg, &t)| TideRow {
            time_unix_s: t,
            gravity_change_nm_s2: dg * 1e9,
            rate_s_per_day: rate_s_per_day(dg, g),
        })
        .collect())
}
