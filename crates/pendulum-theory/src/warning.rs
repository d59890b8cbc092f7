//! One warning type for every analysis.
//!
//! An analysis that finds something wrong with its own answer says so in a
//! warning: a stable code for programs, one sentence for people, and the
//! figure it concerns (the result's key, such as `g_m_s2`), when it
//! concerns one. Each analysis keeps its warnings typed (an enum of what it
//! can find, with the numbers), and every one of those types implements
//! [`Warn`]; the results write each warning the same way, as a
//! [`Warning`]: `{"code": …, "message": …, "figure": …}` in the command
//! line's JSON, Python's dictionaries and the page, whose text front ends
//! print the sentence.

use serde::Serialize;
use std::fmt;

/// A warning as every result writes it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Warning {
    /// A stable code for programs (`snake_case`).
    pub code: &'static str,
    /// The sentence for people.
    pub message: String,
    /// The key of the figure it concerns in the result (`g_m_s2`), if it
    /// concerns one.
    pub figure: Option<&'static str>,
}

impl Warning {
    /// A warning of `code` saying `message` about `figure`.
    pub fn new(
        code: &'static str,
        message: impl Into<String>,
        figure: Option<&'static str>,
    ) -> Self {
        Self {
            code,
            message: message.into(),
            figure,
        }
    }

    /// The warning `w` says.
    pub fn of(w: &impl Warn) -> Self {
        Self {
            code: w.code(),
            message: w.to_string(),
            figure: w.figure(),
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl Warn for Warning {
    fn code(&self) -> &'static str {
        self.code
    }

    fn figure(&self) -> Option<&'static str> {
        self.figure
    }
}

/// A typed warning of one analysis: its code, its sentence (its
/// `Display`) and the figure it concerns. Its serialisation is its
/// [`Warning`]'s ([`serialize`]).
pub trait Warn: fmt::Display {
    /// A stable code for programs.
    fn code(&self) -> &'static str;

    /// The key of the figure it concerns in the result, if one.
    fn figure(&self) -> Option<&'static str>;
}

/// Writes `w` as its [`Warning`] (each warning type's `Serialize`).
pub fn serialize<W: Warn, S: serde::Serializer>(w: &W, s: S) -> Result<S::Ok, S::Error> {
    Warning::of(w).serialize(s)
}

/// Writes `w` as its [`Warning`] with its numbers beside (`fields`, a
/// JSON object of its own keys: a warning type that derives its fields'
/// serialisation with `#[serde(remote = "Self")]` gives them), so that a
/// program reads `{"code", "message", "figure", …numbers}`.
pub fn serialize_with_fields<W: Warn, S: serde::Serializer>(
    w: &W,
    fields: Result<serde_json::Value, serde_json::Error>,
    s: S,
) -> Result<S::Ok, S::Error> {
    use serde::ser::Error;
    let mut map = serde_json::Map::new();
    map.insert("code".into(), w.code().into());
    map.insert("message".into(), w.to_string().into());
    map.insert("figure".into(), w.figure().into());
    match fields.map_err(S::Error::custom)? {
        serde_json::Value::Object(fields) => {
            for (k, v) in fields {
                map.entry(k).or_insert(v);
            }
        }
        serde_json::Value::String(_) | serde_json::Value::Null => {}
        other => return Err(S::Error::custom(format!("a warning's fields are {other}"))),
    }
    map.serialize(s)
}

/// Implements `Serialize` for warning types through [`serialize`].
macro_rules! serialize_as_warning {
    ($($t:ty),+ $(,)?) => {
        $(impl serde::Serialize for $t {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                $crate::warning::serialize(self, s)
            }
        })+
    };
}
pub(crate) use serialize_as_warning;

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug)]
    struct Odd(f64);

    impl fmt::Display for Odd {
        fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            write!(f, "g is {} m/s²", self.0)
        }
    }

    impl Warn for Odd {
        fn code(&self) -> &'static str {
            "odd"
        }
        fn figure(&self) -> Option<&'static str> {
            Some("g_m_s2")
        }
    }

    serialize_as_warning!(Odd);

    #[test]
    fn a_typed_warning_is_written_as_code_message_and_figure() {
        let json = serde_json::to_value(Odd(9.0)).unwrap();
        assert_eq!(
            json,
            serde_json::json!({"code": "odd", "message": "g is 9 m/s²", "figure": "g_m_s2"})
        );
        let w = Warning::new("plain", "words", None);
        assert_eq!(
            serde_json::to_value(&w).unwrap(),
            serde_json::json!({"code": "plain", "message": "words", "figure": null})
        );
        assert_eq!(Warning::of(&Odd(9.0)).to_string(), "g is 9 m/s²");
    }
}
