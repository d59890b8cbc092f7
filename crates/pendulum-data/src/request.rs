//! A request in JSON and its reply, for the front ends that speak JSON
//! (the page's WebAssembly, the Python package): `{"ok": …}` with the
//! command line's `--json`, or `{"error": …}` with the field, the flag
//! and the command line's sentence.

use pendulum_theory::analysis::{Place, Refusal};
use serde::{Deserialize, Serialize};

/// What went wrong, as the command line says it.
#[derive(Debug, PartialEq, Serialize)]
pub struct Failure {
    /// The request's key it is about (none: the data as a whole).
    pub field: Option<String>,
    /// The command line's flag for it.
    pub flag: Option<String>,
    /// The command line's sentence, without its `error: `.
    pub message: String,
}

impl From<Refusal> for Failure {
    fn from(r: Refusal) -> Self {
        match r.place {
            Place::Field(field) | Place::Sample(field, _) => {
                let flag = format!("--{}", field.replace('_', "-"));
                Self {
                    field: Some(field.to_string()),
                    message: match r.place {
                        Place::Sample(_, i) => format!("{flag}: sample {i}: {}", r.reason),
                        _ => format!("{flag}: {}", r.reason),
                    },
                    flag: Some(flag),
                }
            }
            Place::Data => Self {
                field: None,
                flag: None,
                message: r.reason,
            },
        }
    }
}

impl Failure {
    /// A refusal of the request itself (its JSON).
    pub fn request(message: impl Into<String>) -> Self {
        Self {
            field: None,
            flag: None,
            message: message.into(),
        }
    }
}

/// A reply: `{"ok": …}` or `{"error": …}`.
pub fn reply_of<T: Serialize>(result: Result<T, Failure>) -> String {
    let value = match result {
        Ok(ok) => serde_json::to_value(ok).map(|ok| serde_json::json!({ "ok": ok })),
        Err(error) => serde_json::to_value(error).map(|e| serde_json::json!({ "error": e })),
    };
    value.map_or_else(
        |e| {
            format!(
                r#"{{"error":{{"field":null,"flag":null,"message":"could not encode JSON: {e}"}}}}"#
            )
        },
        |v| v.to_string(),
    )
}

/// Where g comes from, as `--g`, `--latitude` and `--height` give it.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gravity {
    pub g_m_s2: Option<f64>,
    pub latitude_deg: Option<f64>,
    pub height_m: Option<f64>,
}

impl Gravity {
    /// g, as the command line resolves its flags.
    pub fn resolve(&self) -> Result<pendulum_theory::gravity::Resolved, Failure> {
        Ok(pendulum_theory::gravity::resolve(
            self.g_m_s2,
            self.latitude_deg,
            self.height_m,
        )?)
    }
}
