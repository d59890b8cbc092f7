//! A fit of a file's bytes, asked in JSON: the page's lab (a dropped
//! Tracker or phyphox file, a pasted table) and the Python package's
//! `fit_file` ask it. The file is fitted as `fit decay`, `fit trajectory`
//! or `fit period` fits it, by the same code (`pendulum_data::fits`).
//! The reply's `ok` is the command's `--json`; beside it `figure` (the
//! command's `--plot`, as data: panels of series, which the page draws),
//! `warnings` (as its JSON has them) and `notes` (what the
//! reader left out, its warnings on standard error).
//!
//! The options are the flags' values, each key named with its unit
//! (`length_m` for `--length`, `frame_rate_hz` for `--frame-rate`).

use crate::figure::{in_time_units, Figure};
use crate::fits::{self, DecayOptions, PeriodOptions, TrajectoryOptions};
use crate::measured::{Pivot, Positions};
use crate::request::{reply_of, Failure, Gravity};
use crate::{AngleUnit, ReadError, ReadOptions, Source};
use pendulum_theory::fitting::tracked::LengthSource;
use pendulum_theory::warning::{Warn, Warning};
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// How the file is read, as `--angle-unit`, `--columns`, `--frame-rate`
/// and `--run` say it.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Reading {
    /// The file's name (its extension tells a workbook or a Tracker
    /// project); `pasted table` for a table pasted in.
    pub file_name: String,
    /// `deg` or `rad`: for angle columns whose header has no unit.
    pub angle_unit: Option<String>,
    /// The names of a headerless file's columns, comma-separated.
    pub columns: Option<String>,
    pub frame_rate_hz: Option<f64>,
    pub run: Option<u64>,
}

/// x and y positions' pivot, as `--pivot`, `--y-down` and `--scale`.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Placing {
    /// `X,Y` in the file's units, or `fit`.
    pub pivot: Option<String>,
    #[serde(default)]
    pub y_down: bool,
    pub scale_m: Option<f64>,
}

/// One fit, named by its `fit`.
#[derive(Debug, Deserialize)]
#[serde(tag = "fit", rename_all = "snake_case")]
pub enum FitRequest {
    /// `pendulum fit decay --json`.
    Decay(DecayRequest),
    /// `pendulum fit trajectory --json`.
    Trajectory(TrajectoryRequest),
    /// `pendulum fit period --json`.
    Period(PeriodTableRequest),
}

/// `fit decay`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DecayRequest {
    #[serde(flatten)]
    pub reading: Reading,
    #[serde(flatten)]
    pub placing: Placing,
    pub model: Option<String>,
    pub period_s: Option<f64>,
    pub length_m: Option<f64>,
    pub length_uncertainty_m: Option<f64>,
    pub mass_kg: Option<f64>,
    #[serde(default)]
    pub force: bool,
    #[serde(flatten)]
    pub gravity: Gravity,
}

/// `fit trajectory`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrajectoryRequest {
    #[serde(flatten)]
    pub reading: Reading,
    #[serde(flatten)]
    pub placing: Placing,
    pub from_s: Option<f64>,
    pub to_s: Option<f64>,
    pub model: Option<String>,
    pub drag_law: Option<String>,
    pub length_m: Option<f64>,
    pub length_uncertainty_m: Option<f64>,
    #[serde(default)]
    pub force: bool,
}

/// `fit period`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PeriodTableRequest {
    #[serde(flatten)]
    pub reading: Reading,
    pub length_m: Option<f64>,
    pub length_uncertainty_m: Option<f64>,
    pub bob_radius_m: Option<f64>,
}

/// The request's key for a reading option or the library's field.
fn key_of(option: &str) -> String {
    match option {
        "length" | "pendulum_length" => "length_m",
        "length_standard_error" | "pendulum_length_standard_error" => "length_uncertainty_m",
        "period" => "period_s",
        "mass" => "mass_kg",
        "from" => "from_s",
        "to" => "to_s",
        "frame_rate" => "frame_rate_hz",
        "scale" => "scale_m",
        "bob_radius" => "bob_radius_m",
        "g" => "g_m_s2",
        "time" => "file",
        other => other,
    }
    .to_string()
}

impl From<ReadError> for Failure {
    fn from(e: ReadError) -> Self {
        Failure {
            field: e.option.map(key_of),
            flag: e.flag(),
            message: e.sentence(),
        }
    }
}

impl Reading {
    /// The reading options, checked as the command line checks its flags.
    fn options(&self) -> Result<ReadOptions, Failure> {
        let angle_unit = match self.angle_unit.as_deref() {
            None => None,
            Some("deg") => Some(AngleUnit::Degrees),
            Some("rad") => Some(AngleUnit::Radians),
            Some(other) => {
                return Err(Failure::from(ReadError::option(
                    "angle_unit",
                    format!("must be deg or rad, got {other}"),
                )))
            }
        };
        Ok(ReadOptions {
            angle_unit,
            columns: self
                .columns
                .as_deref()
                .map(|t| t.split(',').map(|c| c.trim().to_string()).collect()),
            frame_rate: self.frame_rate_hz.map(crate::frame_rate).transpose()?,
            run: self.run.map(crate::run_number).transpose()?,
            ..ReadOptions::default()
        })
    }
}

impl Placing {
    fn positions(&self) -> Result<Positions, Failure> {
        let pivot = self.pivot.as_deref().map(Pivot::parse).transpose()?;
        Ok(Positions::new(pivot, self.y_down, self.scale_m)?)
    }
}

/// The pendulum of a length and the request's g, refused as `--length`
/// and `--g` are.
fn pendulum(length: f64, gravity: &Gravity) -> Result<(f64, f64), Failure> {
    let g = gravity.resolve()?.g_m_s2;
    let p = pendulum_theory::Pendulum::new(length, g).map_err(|e| {
        let option = match e.quantity {
            pendulum_theory::Quantity::Gravity => "g",
            _ => "length",
        };
        Failure::from(ReadError::option(option, e.detail()))
    })?;
    Ok((p.length_m(), p.g_m_s2()))
}

/// A fit's reply beside its JSON.
#[derive(Serialize)]
struct Fitted<T: Serialize> {
    ok: T,
    /// The command's `--plot`, as data, its time axes in the unit their
    /// span suits.
    figure: Figure,
    /// The analysis's warnings, as its JSON has them (code, sentence and
    /// figure).
    warnings: Vec<Warning>,
    /// What the reader left out (a sentence each).
    notes: Vec<String>,
}

/// The reply to a fit of the file `bytes` with the options `request`.
pub fn fit(request: &[u8], bytes: &[u8]) -> String {
    let parsed: Result<FitRequest, Failure> =
        serde_json::from_slice(request).map_err(|e| Failure::request(format!("the request: {e}")));
    let reply = parsed.and_then(|r| fit_of(&r, bytes));
    match reply {
        Ok(text) => text,
        Err(e) => reply_of::<Value>(Err(e)),
    }
}

fn fit_of(request: &FitRequest, bytes: &[u8]) -> Result<String, Failure> {
    let reading = match request {
        FitRequest::Decay(r) => &r.reading,
        FitRequest::Trajectory(r) => &r.reading,
        FitRequest::Period(r) => &r.reading,
    };
    let name = reading.file_name.clone();
    let copy = bytes.to_vec();
    let open = move || {
        Ok(Source::new(
            name.clone(),
            std::io::Cursor::new(copy.clone()),
        ))
    };
    let read = reading.options()?;
    let text = match request {
        FitRequest::Decay(r) => {
            let length = r.length_m.map(|l| pendulum(l, &r.gravity)).transpose()?;
            let options = DecayOptions {
                read,
                positions: r.placing.positions()?,
                model: r.model.clone(),
                period: r.period_s,
                length,
                length_standard_error: r.length_uncertainty_m,
                mass: r.mass_kg,
                force: r.force,
            };
            let fitted = fits::decay(&open, &options, &mut |_| {})?;
            let a = &fitted.json;
            encode(a, fitted.figure(), &a.analysis.warnings, &a.format)
        }
        FitRequest::Trajectory(r) => {
            let length = r
                .length_m
                .map(|l| pendulum(l, &Gravity::default()))
                .transpose()?;
            let options = TrajectoryOptions {
                read,
                positions: r.placing.positions()?,
                from: r.from_s,
                to: r.to_s,
                model: r.model.clone(),
                drag_law: r.drag_law.clone(),
                length: length.map(|(l, _)| (l, LengthSource::Given)),
                length_standard_error: r.length_uncertainty_m,
                force: r.force,
            };
            let fitted = fits::trajectory(&open, &options, &mut |_| {})?;
            let a = &fitted.json;
            encode(a, fitted.figure(), &a.analysis.warnings, &a.format)
        }
        FitRequest::Period(r) => {
            let options = PeriodOptions {
                read,
                pendulum_length: r.length_m,
                pendulum_length_standard_error: r.length_uncertainty_m,
                bob_radius: r.bob_radius_m,
            };
            let fitted = fits::periods(&open, &options)?;
            let a = &fitted.json;
            encode(a, fitted.figure(), &a.analysis.warnings, &a.format)
        }
    };
    text.map_err(|e| Failure::request(format!("could not encode JSON: {e}")))
}

/// The reply: the JSON, the figure, the warnings and the notes.
fn encode<T: Serialize, W: Warn>(
    json: &T,
    figure: Figure,
    warnings: &[W],
    format: &crate::Format,
) -> serde_json::Result<String> {
    serde_json::to_string(&Fitted {
        ok: json,
        figure: in_time_units(&figure),
        warnings: warnings.iter().map(Warning::of).collect(),
        notes: format.notes.clone(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reply(request: &str, file: &str) -> Value {
        serde_json::from_str(&fit(request.as_bytes(), file.as_bytes())).expect("a reply is JSON")
    }

    const AMPLITUDES: &str =
        "time_s,amplitude_deg\n0,10\n20,9.1\n40,8.3\n60,7.55\n80,6.9\n100,6.3\n";

    /// A pasted table fits as the command line's fit decay of the same
    /// text (pendulum_data::fits::decay), with its figure and words beside.
    #[test]
    fn a_pasted_table_is_fitted_with_its_figure() {
        let r = reply(
            r#"{"fit": "decay", "file_name": "pasted table", "length_m": 0.994}"#,
            AMPLITUDES,
        );
        assert_eq!(r["ok"]["file"], "pasted table", "{r}");
        assert_eq!(r["ok"]["format"]["rows"], 6);
        assert!(r["ok"]["preferred"].is_string());
        let panels = r["figure"]["panels"].as_array().unwrap();
        assert_eq!(panels[0]["series"][0]["style"], "dots");
        assert_eq!(
            panels[0]["series"][0]["points"].as_array().unwrap().len(),
            6
        );
        assert!(r["warnings"].is_array() && r["notes"].is_array());
    }

    /// Refusals name the request's key and the command line's flag and
    /// sentence: an option's, the file's, and a key no fit knows.
    #[test]
    fn refusals_name_the_key_and_the_flag() {
        let r = reply(
            r#"{"fit": "decay", "file_name": "t.csv", "length_uncertainty_m": 0.001}"#,
            AMPLITUDES,
        );
        assert_eq!(r["error"]["field"], "length_uncertainty_m", "{r}");
        assert_eq!(r["error"]["flag"], "--length-uncertainty");
        assert!(r["error"]["message"]
            .as_str()
            .unwrap()
            .starts_with("--length-uncertainty: is the uncertainty of --length"));
        let r = reply(
            r#"{"fit": "trajectory", "file_name": "t.csv"}"#,
            "hello\nworld\n",
        );
        assert_eq!(r["error"]["field"], Value::Null, "{r}");
        assert!(r["error"]["message"]
            .as_str()
            .unwrap()
            .starts_with("t.csv: "));
        for request in [
            r#"{"fit": "decay", "file_name": "t.csv", "lenght_m": 1}"#,
            r#"{"fit": "period", "file_name": "t.csv", "pivot": "fit"}"#,
            r#"{"fit": "spectrum", "file_name": "t.csv"}"#,
            r#"{"fit": "decay"}"#,
        ] {
            let r = reply(request, AMPLITUDES);
            assert!(
                r["error"]["message"]
                    .as_str()
                    .unwrap()
                    .starts_with("the request: "),
                "{request}: {r}"
            );
        }
        let r = reply(
            r#"{"fit": "decay", "file_name": "t.csv", "angle_unit": "grad"}"#,
            AMPLITUDES,
        );
        assert_eq!(r["error"]["flag"], "--angle-unit", "{r}");
    }

    /// A file's layout is told by its name: a workbook's bytes named
    /// .xlsx are read as one (and refused as one when they are not), a
    /// Tracker project's as XML.
    #[test]
    fn the_name_tells_the_layout() {
        let r = reply(r#"{"fit": "decay", "file_name": "run.xlsx"}"#, AMPLITUDES);
        let message = r["error"]["message"].as_str().unwrap();
        assert!(message.contains("spreadsheet workbook"), "{message}");
        let r = reply(r#"{"fit": "decay", "file_name": "run.trk"}"#, AMPLITUDES);
        let message = r["error"]["message"].as_str().unwrap();
        assert!(message.starts_with("run.trk: "), "{message}");
    }
}
