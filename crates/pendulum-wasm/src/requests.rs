//! The requests the page makes and their answers: each the library call
//! the command line makes for the same flags, answered with the same keys
//! as its `--json` (checked whole against the binary by the command
//! line's tests, `tests/cli/wasm.rs`). Quantities are numbers in the
//! units their keys name (`length_m`, `amplitude_deg`); a key the request
//! does not know is refused, as an unknown flag is.

pub use pendulum_data::request::{reply_of, Failure, Gravity};
use pendulum_theory::analysis::Refusal;
use pendulum_theory::compound::regulate::{regulate, Nut, Regulated};
use pendulum_theory::damped::analysis::{damped, Damped, DampedInput, DampingGiven};
use pendulum_theory::listening::analysis::{listen_to_samples, ListenInput, Listening, Oscillator};
use pendulum_theory::listening::live::{LiveListener, Provisional};
use pendulum_theory::listening::windows::Window;
use pendulum_theory::period::inverse::{length, LengthResult};
use pendulum_theory::period::table::{table, Amplitudes, PeriodInput, PeriodRow};
use pendulum_theory::period::Nominal;
use serde::{Deserialize, Serialize};
use serde_json::Value;

/// One request, named by its `command`.
#[derive(Debug, Deserialize)]
#[serde(tag = "command", rename_all = "snake_case")]
pub enum Request {
    /// `pendulum period --json`.
    Period(PeriodRequest),
    /// `pendulum length --json`.
    Length(LengthRequest),
    /// `pendulum regulate --json`.
    Regulate(RegulateRequest),
    /// `pendulum gravity --json`.
    Gravity(GravityRequest),
    /// `pendulum damped --json`.
    Damped(DampedRequest),
}

/// `period`: one amplitude, or a range of them.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PeriodRequest {
    pub length_m: f64,
    /// One amplitude, or the first of a range (with `to_deg`).
    pub amplitude_deg: f64,
    pub to_deg: Option<f64>,
    pub steps: Option<i64>,
    pub series_terms: Option<i64>,
    #[serde(flatten)]
    pub gravity: Gravity,
}

/// `length`: from a period or a beat rate.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LengthRequest {
    pub period_s: Option<f64>,
    pub bph: Option<f64>,
    pub amplitude_deg: Option<f64>,
    #[serde(flatten)]
    pub gravity: Gravity,
}

/// `regulate`: a rate, and the pendulum by its length or its beat.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RegulateRequest {
    pub rate_s_per_day: f64,
    pub length_m: Option<f64>,
    pub bph: Option<f64>,
    pub nut_pitch_m: Option<f64>,
    pub nut_tpi: Option<f64>,
    pub nut_divisions: Option<u32>,
    pub tray_m: Option<f64>,
}

/// `gravity`: normal gravity at a latitude and height.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GravityRequest {
    pub latitude_deg: f64,
    pub height_m: Option<f64>,
}

/// `damped`: the damped pendulum of section 1-4.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DampedRequest {
    pub length_m: f64,
    pub amplitude_deg: f64,
    /// One of the damping forms: `q`, `log_decrement`, `decay_time_s`,
    /// `damping_coefficient`, `zeta`.
    pub q: Option<f64>,
    pub log_decrement: Option<f64>,
    pub decay_time_s: Option<f64>,
    pub damping_coefficient: Option<f64>,
    pub zeta: Option<f64>,
    pub friction_angle_deg: Option<f64>,
    pub mass_kg: Option<f64>,
    pub extrema: Option<u64>,
    #[serde(flatten)]
    pub gravity: Gravity,
}

/// `period`'s JSON: where g came from, and the library's row.
#[derive(Serialize)]
pub struct PeriodJson {
    g_source: &'static str,
    #[serde(flatten)]
    row: PeriodRow,
}

/// `length`'s JSON.
#[derive(Serialize)]
pub struct LengthJson {
    #[serde(flatten)]
    result: LengthResult,
    g_source: &'static str,
}

/// `gravity`'s JSON.
#[derive(Serialize)]
pub struct GravityJson {
    g_m_s2: f64,
    latitude_deg: f64,
    height_m: f64,
    model: &'static str,
}

/// The answer to a request of JSON bytes.
pub fn answer(request: &[u8]) -> String {
    let parsed: Result<Request, Failure> =
        serde_json::from_slice(request).map_err(|e| Failure::request(format!("the request: {e}")));
    match parsed {
        Ok(Request::Period(r)) => reply_of(period(&r)),
        Ok(Request::Length(r)) => reply_of(length_of(&r)),
        Ok(Request::Regulate(r)) => reply_of(regulated(&r)),
        Ok(Request::Gravity(r)) => reply_of(gravity(&r)),
        Ok(Request::Damped(r)) => reply_of(damped_of(&r)),
        Err(e) => reply_of::<Value>(Err(e)),
    }
}

/// `period`: a row, or a table of rows over a range.
pub fn period(r: &PeriodRequest) -> Result<Value, Failure> {
    let g = r.gravity.resolve()?;
    let amplitudes = match r.to_deg {
        Some(to) => Amplitudes::Range {
            from: r.amplitude_deg.to_radians(),
            to: to.to_radians(),
            steps: r.steps,
            step: None,
        },
        None => Amplitudes::One(r.amplitude_deg.to_radians()),
    };
    let rows = table(&PeriodInput {
        length: r.length_m,
        g: Some(g.g_m_s2),
        amplitudes,
        series_terms: r.series_terms,
        elastic_share: None,
    })?;
    let rows: Vec<PeriodJson> = rows
        .into_iter()
        .map(|row| PeriodJson {
            g_source: g.g_source,
            row,
        })
        .collect();
    let value = if r.to_deg.is_some() {
        serde_json::to_value(rows)
    } else {
        serde_json::to_value(&rows[0])
    };
    value.map_err(|e| Failure::request(e.to_string()))
}

/// `length`.
pub fn length_of(r: &LengthRequest) -> Result<LengthJson, Failure> {
    let g = r.gravity.resolve()?;
    let nominal = match (r.period_s, r.bph) {
        (Some(p), None) => Nominal::Period(p),
        (None, Some(b)) => Nominal::BeatsPerHour(b),
        _ => return Err(Failure::request("give --period or --bph")),
    };
    let result = length(
        nominal,
        r.amplitude_deg.map(f64::to_radians),
        Some(g.g_m_s2),
    )?;
    Ok(LengthJson {
        result,
        g_source: g.g_source,
    })
}

/// `regulate`.
pub fn regulated(r: &RegulateRequest) -> Result<Value, Failure> {
    let pendulum = match (r.length_m, r.bph) {
        (Some(l), _) => Regulated::Length(l),
        (None, Some(b)) => Regulated::Length(pendulum_theory::advice::length_for_bph(b)?),
        (None, None) => {
            return Err(Failure::from(Refusal::field(
                "length",
                "give --length, --design or --bph",
            )))
        }
    };
    let nut = Nut {
        pitch: r.nut_pitch_m,
        tpi: r.nut_tpi,
        divisions: r.nut_divisions,
    };
    let result = regulate(&pendulum, r.rate_s_per_day, nut, r.tray_m)?;
    serde_json::to_value(result).map_err(|e| Failure::request(e.to_string()))
}

/// `gravity`.
pub fn gravity(r: &GravityRequest) -> Result<GravityJson, Failure> {
    let height_m = r
        .height_m
        .unwrap_or(pendulum_theory::gravity::DEFAULT_HEIGHT_M);
    let g = pendulum_theory::gravity::resolve(None, Some(r.latitude_deg), Some(height_m))?;
    Ok(GravityJson {
        g_m_s2: g.g_m_s2,
        latitude_deg: r.latitude_deg,
        height_m,
        model: "WGS 84 normal gravity (Somigliana) with free-air correction",
    })
}

/// `damped`.
pub fn damped_of(r: &DampedRequest) -> Result<Damped, Failure> {
    let g = r.gravity.resolve()?;
    let forms = [
        ("q", r.q),
        ("log_decrement", r.log_decrement),
        ("decay_time", r.decay_time_s),
        ("damping_coefficient", r.damping_coefficient),
        ("zeta", r.zeta),
    ];
    let mut given = forms
        .iter()
        .filter_map(|(f, v)| v.map(|v| DampingGiven::parse(f, v)));
    let damping = given.next().transpose()?;
    if given.next().is_some() {
        return Err(Failure::request(
            "give one of q, log_decrement, decay_time_s, damping_coefficient, zeta",
        ));
    }
    Ok(damped(&DampedInput {
        length: r.length_m,
        g: Some(g.g_m_s2),
        amplitude: r.amplitude_deg.to_radians(),
        damping,
        friction_angle: r.friction_angle_deg.map(f64::to_radians),
        mass: r.mass_kg,
        extrema: r.extrema,
        force: false,
    })?)
}

/// What `listen` takes beside the samples, as its flags give it.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ListenOptions {
    pub bph: Option<f64>,
    pub period_s: Option<f64>,
    pub every_s: Option<f64>,
    pub lift_angle_deg: Option<f64>,
    pub sample_rate_error_ppm: Option<f64>,
    /// `"pendulum"` or `"balance"`.
    pub oscillator: Option<String>,
}

impl ListenOptions {
    fn parse(json: &[u8]) -> Result<ListenInput, Failure> {
        let o: Self = if json.is_empty() {
            Self::default()
        } else {
            serde_json::from_slice(json)
                .map_err(|e| Failure::request(format!("the options: {e}")))?
        };
        let nominal = Nominal::given(o.bph, o.period_s)?;
        let oscillator = match o.oscillator.as_deref() {
            None => None,
            Some("pendulum") => Some(Oscillator::Pendulum),
            Some("balance") => Some(Oscillator::Balance),
            Some(other) => {
                return Err(Failure::from(Refusal::field(
                    "oscillator",
                    format!("must be pendulum or balance, got {other}"),
                )))
            }
        };
        Ok(ListenInput {
            nominal,
            sample_rate_error_ppm: o.sample_rate_error_ppm,
            lift_angle: o.lift_angle_deg.map(f64::to_radians),
            oscillator,
            every: o.every_s,
        })
    }
}

/// The sentences the command line's text ends with, beside the JSON's
/// codes: the warnings, what the recording shows, and what to do.
#[derive(Serialize)]
pub struct Words {
    pub warnings: Vec<String>,
    pub findings: Vec<String>,
    pub advice: Vec<String>,
}

impl Words {
    fn of(l: &Listening) -> Self {
        Self {
            warnings: l.beats.warnings.iter().map(ToString::to_string).collect(),
            findings: l.findings.iter().map(|f| f.sentence()).collect(),
            advice: l.beats.advice.iter().map(|a| a.sentence()).collect(),
        }
    }
}

/// The ticks kept, by column (the command line's `--ticks` file's
/// numbers, and each tick's beat), for the page's paper strip and its
/// ticks file.
#[derive(Serialize)]
pub struct TickColumns {
    pub beat: Vec<u64>,
    pub time_s: Vec<f64>,
    pub side: Vec<u8>,
    /// The band-passed sound's peak, full scale 1.
    pub sound_level: Vec<f64>,
}

impl TickColumns {
    fn of(l: &Listening) -> Self {
        Self {
            beat: l.ticks.iter().map(|t| t.beat).collect(),
            time_s: l.ticks.iter().map(|t| t.time).collect(),
            side: l.ticks.iter().map(|t| t.side).collect(),
            sound_level: l.ticks.iter().map(|t| t.amplitude).collect(),
        }
    }
}

/// A listening's reply: `{"ok": …, "words": …, "ticks": …}` (see
/// [`Words`], [`TickColumns`]).
pub fn heard_reply(heard: Result<Listening, Failure>) -> String {
    match heard {
        Ok(l) => serde_json::to_string(&serde_json::json!({
            "ok": l,
            "words": Words::of(&l),
            "ticks": TickColumns::of(&l),
        }))
        .unwrap_or_else(|e| reply_of::<Value>(Err(Failure::request(e.to_string())))),
        Err(e) => reply_of::<Value>(Err(e)),
    }
}

/// `listen` of a whole recording's samples.
pub fn listen(options: &[u8], samples: &[f32], sample_rate: u32) -> String {
    let heard = ListenOptions::parse(options)
        .and_then(|input| Ok(listen_to_samples(samples, f64::from(sample_rate), &input)?));
    heard_reply(heard)
}

/// The clearest of the channels laid one after another in `all`, each
/// `frames` long ([`pendulum_theory::listening::channels::clearest_channel`],
/// as the command line chooses for a file).
pub fn clearest(all: &[f32], frames: usize, sample_rate: u32) -> String {
    let channels: Vec<Vec<f32>> = all.chunks(frames.max(1)).map(<[f32]>::to_vec).collect();
    let channel =
        pendulum_theory::listening::channels::clearest_channel(&channels, f64::from(sample_rate));
    reply_of::<Value>(Ok(serde_json::json!({ "channel": channel })))
}

/// A live listener.
pub fn live_new(options: &[u8], sample_rate: u32) -> Result<LiveListener, Failure> {
    let input = ListenOptions::parse(options)?;
    Ok(LiveListener::new(sample_rate, &input)?)
}

/// What a block of samples completes.
#[derive(Serialize)]
pub struct Pushed {
    pub windows: Vec<Window>,
    pub provisional: Option<Provisional>,
}

/// The next samples to a live listener.
pub fn live_push(listener: &mut LiveListener, samples: &[f32]) -> Result<Pushed, Failure> {
    let windows = listener.push(samples)?;
    Ok(Pushed {
        windows,
        provisional: listener.take_provisional(),
    })
}

/// A live listener's end.
pub fn live_finish(listener: LiveListener) -> Result<Listening, Failure> {
    Ok(listener.finish()?)
}

/// A handle that holds no listener.
pub fn no_listener(handle: usize) -> Failure {
    Failure::request(format!(
        "no live listener {handle} (finished, or never made)"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reply(request: &str) -> Value {
        serde_json::from_str(&answer(request.as_bytes())).expect("a reply is JSON")
    }

    /// A refusal is the command line's sentence, with its field and flag.
    #[test]
    fn a_refusal_is_the_command_lines_sentence() {
        let r = reply(r#"{"command": "period", "length_m": -1, "amplitude_deg": 2}"#);
        assert_eq!(r["error"]["field"], "length");
        assert_eq!(r["error"]["flag"], "--length");
        let message = r["error"]["message"].as_str().unwrap();
        assert!(
            message.starts_with("--length: must be positive, got -1"),
            "{message}"
        );
    }

    /// A key no request knows is refused, as an unknown flag is, not
    /// ignored; so is a command.
    #[test]
    fn unknown_keys_are_refused() {
        for request in [
            r#"{"command": "period", "length_m": 1, "amplitude_deg": 2, "lenght_m": 1}"#,
            r#"{"command": "gravity", "latitude_deg": 1, "hieght_m": 3}"#,
            r#"{"command": "periodic"}"#,
            r#"not json"#,
        ] {
            let r = reply(request);
            assert!(r["error"]["message"].is_string(), "{request}: {r}");
            assert!(r.get("ok").is_none(), "{request}");
        }
    }

    /// The answer is the library's result: a seconds pendulum at 2° loses
    /// 6.5797 s/day to its circular error (the README's figure).
    #[test]
    fn the_period_is_the_librarys() {
        let r = reply(r#"{"command": "period", "length_m": 0.99362, "amplitude_deg": 2}"#);
        let ce = r["ok"]["circular_error_s_per_day"].as_f64().unwrap();
        assert!((ce - 6.5797).abs() < 5e-5, "{ce}");
        assert_eq!(r["ok"]["g_source"], "standard");
    }

    /// Listening takes its options as the flags, and refuses both a beat
    /// rate and a period.
    #[test]
    fn listening_refuses_a_beat_given_twice() {
        let r: Value = serde_json::from_str(&listen(
            br#"{"bph": 3600, "period_s": 2}"#,
            &[0.0; 8000],
            8000,
        ))
        .unwrap();
        assert!(
            r["error"]["message"]
                .as_str()
                .unwrap()
                .contains("give bph or period, not both"),
            "{r}"
        );
    }
}
