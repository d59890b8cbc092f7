//! The library's top-level modules import one another without a cycle:
//! each physical idea builds on simpler ones only (issue 22: the
//! simulation <-> clock and pendulum <-> period cycles are gone). Read
//! from the source: every `crate::name` outside comments, and the crate
//! root's re-exports (`crate::Pendulum` is `pendulum`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let root_exports = [
        ("Pendulum", "pendulum"),
        ("Amplitude", "pendulum"),
        ("STANDARD_GRAVITY", "pendulum"),
        ("InputError", "error"),
        ("Problem", "error"),
        ("Quantity", "error"),
    ];
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut stack = vec![src.clone()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let relative = path.strip_prefix(&src).unwrap();
            let first = relative.components().next().unwrap();
            let top = first
                .as_os_str()
                .to_string_lossy()
                .trim_end_matches(".rs")
                .to_string();
            if top == "lib" {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            let uses = graph.entry(top.clone()).or_default();
            for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
                for (i, _) in line.match_indices("crate::") {
                    let name: String = line[i + 7..]
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    let module = root_exports
                        .iter()
                        .find(|(e, _)| *e == name)
                        .map_or(name.clone(), |(_, m)| m.to_string());
                    if module != top && !module.is_empty() {
                        uses.insert(module);
                    }
                }
            }
        }
    }
    graph
}

/// Whether `to` is reachable from `from`.
fn reaches(graph: &BTreeMap<String, BTreeSet<String>>, from: &str, to: &str) -> bool {
    let mut seen = BTreeSet::new();
    let mut stack = vec![from.to_string()];
    while let Some(m) = stack.pop() {
        for next in graph.get(&m).into_iter().flatten() {
            if next == to {
                return true;
            }
            if seen.insert(next.clone()) {
                stack.push(next.clone());
            }
        }
    }
    false
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let graph = graph();
    // The reader sees the modules it must (a broken reader finds none).
    for m in ["pendulum", "period", "simulation", "clock", "damped"] {
        assert!(graph.contains_key(m), "{m} not read");
    }
    assert!(graph["clock"].contains("pendulum"));
    let cycles: Vec<(String, String)> = graph
        .iter()
        .flat_map(|(a, uses)| uses.iter().map(move |b| (a.clone(), b.clone())))
        .filter(|(a, b)| reaches(&graph, b, a))
        .collect();
    assert!(cycles.is_empty(), "import cycles: {cycles:?}");
}
