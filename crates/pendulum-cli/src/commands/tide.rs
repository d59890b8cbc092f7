//! `pendulum tide`: the body tide's gravity and a pendulum's rate.

use crate::args::TideArgs;
use crate::error::CliError;
use crate::output::{self, num};
use pendulum_theory::tide::{series, Station};
use serde::Serialize;

/// A row as printed: the time as ISO 8601 UTC.
#[derive(Serialize)]
struct Row {
    time: String,
    gravity_change_nm_s2: f64,
    rate_s_per_day: f64,
}

#[derive(Serialize)]
struct TideJson<'a> {
    latitude_deg: f64,
    longitude_deg: f64,
    height_m: f64,
    model: &'static str,
    rows: &'a [Row],
}

/// A date or date-time (ISO 8601; UTC unless it carries an offset) as
/// Unix seconds; refusals name `flag`.
pub(crate) fn instant(text: &str, flag: &str) -> Result<f64, CliError> {
    use jiff::civil::{Date, DateTime};
    use jiff::Timestamp;
    let t = text.trim();
    let of = |ts: Timestamp| ts.as_nanosecond() as f64 * 1e-9;
    if let Ok(ts) = t.parse::<Timestamp>() {
        return Ok(of(ts));
    }
    let civil = t.parse::<DateTime>().or_else(|_| {
        t.parse::<Date>()
            .map(|d| d.to_datetime(jiff::civil::Time::midnight()))
    });
    match civil {
        Ok(dt) => jiff::tz::Offset::UTC
            .to_timestamp(dt)
            .map(of)
            .map_err(|e| CliError::flag(flag, e.to_string())),
        Err(_) => Err(CliError::flag(
            flag,
            format!(
                "must be a date or date and time (ISO 8601: 2026-01-01, 2026-01-01T06:00Z), got '{text}'"
            ),
        )),
    }
}

/// Unix seconds as `2026-01-01T06:00:00Z` (to the millisecond when not
/// whole).
pub(crate) fn iso(t: f64) -> String {
    let ms = (t * 1e3).round() as i64;
    match jiff::Timestamp::from_millisecond(ms) {
        Ok(ts) if ms % 1000 == 0 => ts.strftime("%Y-%m-%dT%H:%M:%SZ").to_string(),
        Ok(ts) => ts.strftime("%Y-%m-%dT%H:%M:%S%.3fZ").to_string(),
        Err(_) => format!("{t}"),
    }
}

pub fn run(args: &TideArgs) -> Result<String, CliError> {
    let from = instant(&args.from, "--from")?;
    let to = instant(&args.to, "--to")?;
    let station = Station {
        latitude_deg: args.latitude.0.to_degrees(),
        longitude_deg: args.longitude.0.to_degrees(),
        height_m: args.height.map_or(0.0, |h| h.0),
    };
    let rows = series(station, from, to, args.every.0, args.force).map_err(|r| {
        CliError::refused(&r, &[("time", "--from")], &|_, reason| {
            CliError::flag("--from", reason)
        })
    })?;
    let rows: Vec<Row> = rows
        .iter()
        .map(|r| Row {
            time: iso(r.time_unix_s),
            gravity_change_nm_s2: r.gravity_change_nm_s2,
            rate_s_per_day: r.rate_s_per_day,
        })
        .collect();
    if args.json {
        return output::json(&TideJson {
            latitude_deg: station.latitude_deg,
            longitude_deg: station.longitude_deg,
            height_m: station.height_m,
            model: "body tide, Sun and Moon, elastic Earth (Wahr-Dehant factors, K1 resonance); no ocean loading",
            rows: &rows,
        });
    }
    if args.csv {
        return output::csv(&rows);
    }
    let table: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                r.time.clone(),
                num(r.gravity_change_nm_s2, 5),
                format!("{:+.3}", r.rate_s_per_day * 1e3),
            ]
        })
        .collect();
    let mut out = output::table(&["time (UTC)", "Δg (nm/s²)", "rate (ms/day)"], &table);
    out.push_str(
        "Δg: the body tide (Sun and Moon, elastic Earth), positive when g is larger; the rate is \
         the pendulum's, +Δg/2g of a day. No ocean loading (up to ~10% more near coasts).\n",
    );
    Ok(out)
}
