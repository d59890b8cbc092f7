//! The files an invocation names, typed by what the command does with
//! them: [`InputPath`] read, [`OutputPath`] written. The table of a
//! command's files that [`crate::commands::run`] checks before any work
//! (no output twice, none over an input, at most one `-`) is derived from
//! these types in the parsed arguments ([`declared`]), not kept by hand:
//! a new flag of either type is checked without another line.

use clap::builder::{MapValueParser, PathBufValueParser, TypedValueParser, ValueParserFactory};
use clap::parser::ArgMatches;
use std::path::{Path, PathBuf};

/// A file the command reads.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputPath(pub PathBuf);

/// A file the command writes (`-` for standard output where the flag
/// allows it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutputPath(pub PathBuf);

macro_rules! path_type {
    ($name:ident) => {
        impl std::ops::Deref for $name {
            type Target = Path;
            fn deref(&self) -> &Path {
                &self.0
            }
        }

        impl ValueParserFactory for $name {
            type Parser = MapValueParser<PathBufValueParser, fn(PathBuf) -> $name>;
            fn value_parser() -> Self::Parser {
                PathBufValueParser::new().map($name)
            }
        }
    };
}

/// The start of several files' names the command writes (`log --plot
/// PREFIX`: PREFIX-rate.svg, …): the command checks the files it names
/// with the other outputs before any work.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutputPrefix(pub PathBuf);

path_type!(InputPath);
path_type!(OutputPath);
path_type!(OutputPrefix);

/// The files of the subcommand `matches` ran (the innermost: `fit decay`'s
/// own): each as (the flag, or the positional argument's value name, and
/// the path), outputs and inputs in the order the command declares them;
/// and whether it prints JSON or CSV for programs (`--json`, `--csv`).
pub struct Declared {
    /// The files written.
    pub outputs: Vec<(String, PathBuf)>,
    /// The files read.
    pub inputs: Vec<(String, PathBuf)>,
    /// Whether standard output carries JSON or CSV.
    pub machine: bool,
}

/// The files and the machine format of the invocation `matches` of
/// `command` (the whole command line's definition).
pub fn declared(command: &clap::Command, matches: &ArgMatches) -> Declared {
    let (mut command, mut matches) = (command, matches);
    while let Some((name, sub)) = matches.subcommand() {
        match command.find_subcommand(name) {
            Some(c) => (command, matches) = (c, sub),
            None => break,
        }
    }
    let mut declared = Declared {
        outputs: Vec::new(),
        inputs: Vec::new(),
        machine: false,
    };
    for arg in command.get_arguments() {
        let id = arg.get_id().as_str();
        let label = || match arg.get_long() {
            Some(long) => format!("--{long}"),
            None => arg
                .get_value_names()
                .and_then(|n| n.first())
                .map_or_else(|| id.to_uppercase(), |n| n.to_string()),
        };
        if let Ok(Some(p)) = matches.try_get_one::<OutputPath>(id) {
            declared.outputs.push((label(), p.0.clone()));
        } else if let Ok(Some(p)) = matches.try_get_one::<InputPath>(id) {
            declared.inputs.push((label(), p.0.clone()));
        } else if (id == "json" || id == "csv")
            && matches!(matches.try_get_one::<bool>(id), Ok(Some(&true)))
        {
            declared.machine = true;
        }
    }
    declared
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::args::Cli;
    use clap::CommandFactory;

    fn of(line: &[&str]) -> Declared {
        let command = Cli::command();
        let matches = command.clone().try_get_matches_from(line).unwrap();
        declared(&command, &matches)
    }

    #[test]
    fn every_written_and_read_file_is_found_with_its_flag() {
        let d = of(&[
            "pendulum",
            "simulate",
            "--amplitude",
            "3deg",
            "--duration",
            "10s",
            "--swings",
            "s.csv",
            "--trajectory",
            "t.csv",
            "--plot",
            "p.svg",
            "--phase-plot",
            "q.svg",
            "--design",
            "d.toml",
            "--json",
        ]);
        let flags: Vec<&str> = d.outputs.iter().map(|(f, _)| f.as_str()).collect();
        assert_eq!(
            flags,
            ["--swings", "--trajectory", "--plot", "--phase-plot"]
        );
        assert_eq!(
            d.inputs,
            [("--design".to_string(), PathBuf::from("d.toml"))]
        );
        assert!(d.machine);
        // Nested subcommands and positional files: their value names.
        let d = of(&["pendulum", "fit", "decay", "run.csv", "--plot", "-"]);
        assert_eq!(d.inputs, [("FILE".to_string(), PathBuf::from("run.csv"))]);
        assert_eq!(d.outputs, [("--plot".to_string(), PathBuf::from("-"))]);
        assert!(!d.machine);
        let d = of(&["pendulum", "synth", "ticks", "out.wav", "--truth", "t.csv"]);
        let flags: Vec<&str> = d.outputs.iter().map(|(f, _)| f.as_str()).collect();
        assert_eq!(flags, ["OUT.wav", "--truth"]);
    }

    #[test]
    fn every_path_argument_is_typed_as_read_or_written() {
        // A PathBuf flag would escape the table: only the report's folder
        // (checked as a folder of its own) is one.
        fn walk(c: &clap::Command, found: &mut Vec<String>) {
            for a in c.get_arguments() {
                let parser = a.get_value_parser();
                let untyped = parser.type_id() == clap::builder::ValueParser::path_buf().type_id();
                if untyped {
                    found.push(format!("{} {}", c.get_name(), a.get_id()));
                }
            }
            for s in c.get_subcommands() {
                walk(s, found);
            }
        }
        let mut found = Vec::new();
        walk(&Cli::command(), &mut found);
        assert_eq!(found, ["report output"]);
    }
}
