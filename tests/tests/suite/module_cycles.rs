//! The core reads top-down (ARCHITECTURE.md, "bcsdf-core modules"): no import cycle between
//! bcsdf-core's modules. Reads every `bcsdf-core/src/**/*.rs` file, takes each `crate::x`
//! path in code (`use crate::…` lines, grouped `use crate::{a::…, b}` and inline paths;
//! comments and doc links skipped, `#[cfg(test)]` modules and items skipped) as an edge from
//! the file's top-level module to `x`, and fails on any cycle, naming it. `lib.rs`, the
//! façade that re-exports the modules, is above all of them and not a node.
//!
//! `FUR_BCSDF_CORE_SRC=<dir>` checks another copy of the sources (e.g. an older commit's,
//! from `git archive`).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Module → the modules it names, from a source tree's files (relative path → text).
type Graph = BTreeMap<String, BTreeSet<String>>;

fn identifier(s: &str) -> &str {
    let end = s
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    &s[..end]
}

/// The text with `//` comments removed (doc comments and their links included).
fn strip_comments(text: &str) -> String {
    text.lines()
        .map(|line| match line.find("//") {
            Some(i) => &line[..i],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The text with every `#[cfg(test)]` item removed: an inline `mod x { … }` (by brace
/// matching), a `mod x;` declaration or a single `use …;` line. Returns the text and the
/// names of the `#[cfg(test)] mod x;` declarations (whose files are test code).
fn strip_test_items(text: &str) -> (String, Vec<String>) {
    let mut out = String::new();
    let mut test_mods = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("#[cfg(test)]") {
        out.push_str(&rest[..at]);
        let after = &rest[at + "#[cfg(test)]".len()..];
        let item = after.trim_start();
        // The item ends at the first `;` or at the brace matching its first `{`.
        let semi = item.find(';');
        let brace = item.find('{');
        let end = match (semi, brace) {
            (Some(s), Some(b)) if s < b => s + 1,
            (Some(s), None) => s + 1,
            (_, Some(b)) => {
                let mut depth = 0usize;
                let mut end = item.len();
                for (i, c) in item[b..].char_indices() {
                    match c {
                        '{' => depth += 1,
                        '}' => {
                            depth -= 1;
                            if depth == 0 {
                                end = b + i + 1;
                                break;
                            }
                        }
                        _ => {}
                    }
                }
                end
            }
            (None, None) => item.len(),
        };
        let decl = &item[..end];
        if let Some(name) = decl
            .strip_prefix("mod ")
            .or_else(|| decl.strip_prefix("pub mod "))
        {
            if decl.ends_with(';') {
                test_mods.push(identifier(name.trim_start()).to_string());
            }
        }
        rest = &item[end..];
    }
    out.push_str(rest);
    (out, test_mods)
}

/// The top-level module names a piece of code refers to through `crate::`.
fn crate_references(code: &str) -> BTreeSet<String> {
    let mut refs = BTreeSet::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        let prefix_ok = at == 0 || {
            let c = rest[..at].chars().next_back().unwrap();
            !(c.is_ascii_alphanumeric() || c == '_')
        };
        rest = &rest[at + "crate::".len()..];
        if !prefix_ok {
            continue;
        }
        if let Some(group) = rest.strip_prefix('{') {
            // `crate::{a::b, c, d::{e, f}}`: the first identifier of each top-level element.
            let mut depth = 0usize;
            let mut start = true;
            for (i, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => start = true,
                    c if start && (c.is_ascii_alphabetic() || c == '_') => {
                        refs.insert(identifier(&group[i..]).to_string());
                        start = false;
                    }
                    _ => {}
                }
            }
        } else {
            refs.insert(identifier(rest).to_string());
        }
    }
    refs
}

/// Every `.rs` file under `dir`, as paths relative to `root`.
fn rust_files(root: &Path, dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(root, &path, out);
        } else if path.extension().is_some_and(|x| x == "rs") {
            out.push(path.strip_prefix(root).unwrap().to_path_buf());
        }
    }
}

/// The module graph of the crate whose `src` is `root`.
fn module_graph(root: &Path) -> Graph {
    let mut files = Vec::new();
    rust_files(root, root, &mut files);
    // Pass 1: which files are `#[cfg(test)]` modules (declared so by their parent).
    let mut test_files = BTreeSet::new();
    let mut texts = BTreeMap::new();
    for rel in &files {
        let text = fs::read_to_string(root.join(rel)).unwrap();
        let (code, test_mods) = strip_test_items(&strip_comments(&text));
        // A file `a/b.rs` or `a/b/mod.rs` declares children in `a/b/`; `lib.rs` in `./`.
        let dir = match rel.file_name().and_then(|n| n.to_str()) {
            Some("mod.rs" | "lib.rs") => rel.parent().unwrap().to_path_buf(),
            _ => rel.with_extension(""),
        };
        for m in test_mods {
            test_files.insert(dir.join(format!("{m}.rs")));
            test_files.insert(dir.join(&m));
        }
        texts.insert(rel.clone(), code);
    }
    let modules: BTreeSet<String> = files
        .iter()
        .filter_map(|rel| rel.components().next())
        .map(|c| {
            Path::new(c.as_os_str())
                .with_extension("")
                .to_string_lossy()
                .into_owned()
        })
        .filter(|m| m != "lib")
        .collect();
    let mut graph = Graph::new();
    for (rel, code) in &texts {
        let is_test = test_files
            .iter()
            .any(|t| rel == t || rel.starts_with(t.with_extension("")) && t.extension().is_none());
        let top = Path::new(rel.components().next().unwrap().as_os_str())
            .with_extension("")
            .to_string_lossy()
            .into_owned();
        if is_test || top == "lib" {
            continue;
        }
        let edges = graph.entry(top.clone()).or_default();
        for r in crate_references(code) {
            if r != top && modules.contains(&r) {
                edges.insert(r);
            }
        }
    }
    graph
}

/// One cycle of `graph` (as a path a → … → a), if it has any.
fn find_cycle(graph: &Graph) -> Option<Vec<String>> {
    #[derive(Clone, Copy, PartialEq)]
    enum Mark {
        Open,
        Done,
    }
    fn visit(
        node: &str,
        graph: &Graph,
        marks: &mut BTreeMap<String, Mark>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        marks.insert(node.to_string(), Mark::Open);
        stack.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            match marks.get(next.as_str()) {
                Some(Mark::Open) => {
                    let from = stack.iter().position(|m| m == next).unwrap();
                    let mut cycle = stack[from..].to_vec();
                    cycle.push(next.clone());
                    return Some(cycle);
                }
                Some(Mark::Done) => {}
                None => {
                    if let Some(c) = visit(next, graph, marks, stack) {
                        return Some(c);
                    }
                }
            }
        }
        stack.pop();
        marks.insert(node.to_string(), Mark::Done);
        None
    }
    let mut marks = BTreeMap::new();
    for node in graph.keys() {
        if !marks.contains_key(node) {
            if let Some(c) = visit(node, graph, &mut marks, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

fn core_src() -> PathBuf {
    std::env::var_os("FUR_BCSDF_CORE_SRC").map_or_else(
        || Path::new(env!("CARGO_MANIFEST_DIR")).join("../bcsdf-core/src"),
        PathBuf::from,
    )
}

#[test]
fn the_core_has_no_import_cycle() {
    let graph = module_graph(&core_src());
    assert!(graph.len() > 20, "only {} modules found", graph.len());
    if let Some(cycle) = find_cycle(&graph) {
        panic!(
            "import cycle between bcsdf-core's modules: {}\n{graph:#?}",
            cycle.join(" → ")
        );
    }
    // The layers the architecture describes: the model above its lobes, its lobes above
    // the math.
    let reaches = |from: &str, to: &str| {
        let mut seen = BTreeSet::new();
        let mut todo = vec![from.to_string()];
        while let Some(m) = todo.pop() {
            if m == to {
                return true;
            }
            if seen.insert(m.clone()) {
                todo.extend(graph.get(&m).into_iter().flatten().cloned());
            }
        }
        false
    };
    assert!(reaches("model", "residual") && reaches("residual_gen", "model"));
    assert!(reaches("model", "longitudinal") && reaches("longitudinal", "math"));
}

#[test]
fn the_checker_finds_cycles_and_skips_comments_and_test_modules() {
    let dir = tempfile::tempdir().unwrap();
    let write = |rel: &str, text: &str| {
        let path = dir.path().join(rel);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, text).unwrap();
    };
    write(
        "lib.rs",
        "pub mod a;\npub mod b;\npub mod c;\npub use a::X;\n",
    );
    write(
        "a.rs",
        "//! See [`crate::c::Z`].\nuse crate::{b::Y, math};\n#[cfg(test)]\nmod tests;\n",
    );
    write("a/tests.rs", "use crate::c::Z;\n");
    write(
        "b.rs",
        "/// [`crate::a::X`]\npub struct Y;\n#[cfg(test)]\nmod tests {\n    use crate::a::X;\n}\n",
    );
    write("c.rs", "pub struct Z; // crate::a::X\n");
    write("math.rs", "");
    let graph = module_graph(dir.path());
    assert_eq!(find_cycle(&graph), None, "{graph:?}");
    assert_eq!(graph["a"], BTreeSet::from(["b".into(), "math".into()]));
    // A real edge back closes the cycle, inline or in a group.
    write("b.rs", "pub fn f() -> u32 { crate::a::g() }\n");
    let cycle = find_cycle(&module_graph(dir.path())).unwrap();
    assert_eq!(cycle.first(), cycle.last());
    assert_eq!(cycle.len(), 3, "{cycle:?}");
    write("b.rs", "use crate::{math::PI, c::{Z, W}};\n");
    write("c.rs", "use crate::a::X;\n");
    let cycle = find_cycle(&module_graph(dir.path())).unwrap();
    assert_eq!(cycle.len(), 4, "{cycle:?}");
}
