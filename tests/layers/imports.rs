//! How the library's modules import one another, read from the source text: the crate paths
//! each file names (in `use` trees and in code; comments, strings and test modules left out),
//! resolved through `super`, `self` and the re-exports of a module's own file, as graphs of
//! the children of each module; and the files that name an item through a root re-export.

use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
pub fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("a source folder") {
        let path = entry.expect("a folder entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

use std::collections::{BTreeMap, BTreeSet};

/// The crate's `src/` folder.
pub fn src_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

// ---- reading code ----------------------------------------------------------------------------

/// Whether `ch` can continue an identifier.
fn is_ident(ch: char) -> bool {
    ch.is_alphanumeric() || ch == '_'
}

/// Where the string body starting at `j` (just past its opening `"`) ends, past the closing `"`.
fn string_end(c: &[char], mut j: usize) -> usize {
    while j < c.len() {
        match c[j] {
            '\\' => j += 2,
            '"' => return j + 1,
            _ => j += 1,
        }
    }
    c.len()
}

/// Where a raw string body starting at `j` ends: past `"` and `hashes` `#`s.
fn raw_string_end(c: &[char], mut j: usize, hashes: usize) -> usize {
    while j < c.len() {
        if c[j] == '"' && (1..=hashes).all(|k| c.get(j + k) == Some(&'#')) {
            return j + 1 + hashes;
        }
        j += 1;
    }
    c.len()
}

/// Where a char literal starting at the quote `i` ends; `None` for a lifetime (`'a`).
fn char_end(c: &[char], i: usize) -> Option<usize> {
    if c.get(i + 1) == Some(&'\\') {
        let close = (i + 3..c.len()).find(|&k| c[k] == '\'')?;
        Some(close + 1)
    } else if c.get(i + 2) == Some(&'\'') {
        Some(i + 3)
    } else {
        None
    }
}

/// Where a nested block comment starting at `i` (`/*`) ends.
fn block_comment_end(c: &[char], mut i: usize) -> usize {
    let mut depth = 0;
    while i + 1 < c.len() {
        if c[i] == '/' && c[i + 1] == '*' {
            depth += 1;
            i += 2;
        } else if c[i] == '*' && c[i + 1] == '/' {
            depth -= 1;
            i += 2;
            if depth == 0 {
                return i;
            }
        } else {
            i += 1;
        }
    }
    c.len()
}

/// Where a `b"…"`, `b'…'`, `r"…"`, `r#"…"#`, `br"…"`, `c"…"` literal starting at `i` ends.
fn prefixed_literal_end(c: &[char], i: usize) -> Option<usize> {
    let j = if c[i] == 'r' { i } else { i + 1 };
    match c.get(j) {
        Some('"') => Some(string_end(c, j + 1)),
        Some('\'') if c[i] == 'b' => char_end(c, j),
        Some('r') => {
            let hashes = c[j + 1..].iter().take_while(|&&h| h == '#').count();
            (c.get(j + 1 + hashes) == Some(&'"')).then(|| raw_string_end(c, j + 2 + hashes, hashes))
        }
        _ => None,
    }
}

/// Where the comment or literal starting at `i` ends, if one starts there.
fn skip_at(c: &[char], i: usize) -> Option<usize> {
    let ident_before = i > 0 && is_ident(c[i - 1]);
    match (c[i], c.get(i + 1)) {
        ('/', Some('/')) => Some((i..c.len()).find(|&k| c[k] == '\n').unwrap_or(c.len())),
        ('/', Some('*')) => Some(block_comment_end(c, i)),
        ('"', _) => Some(string_end(c, i + 1)),
        ('\'', _) => char_end(c, i),
        ('b' | 'r' | 'c', _) if !ident_before => prefixed_literal_end(c, i),
        _ => None,
    }
}

/// The lines of `text` with comments (`//`, `/* */`, doc comments) and the insides of string
/// and char literals blanked to spaces: only code is left, on the same lines and columns.
pub fn code_lines(text: &str) -> Vec<String> {
    let c: Vec<char> = text.chars().collect();
    let mut out = c.clone();
    let mut i = 0;
    while i < c.len() {
        match skip_at(&c, i) {
            Some(end) => {
                for ch in &mut out[i..end] {
                    if *ch != '\n' {
                        *ch = ' ';
                    }
                }
                i = end;
            }
            None => i += 1,
        }
    }
    out.into_iter()
        .collect::<String>()
        .split('\n')
        .map(String::from)
        .collect()
}

/// `s` without a leading visibility (`pub`, `pub(crate)`, `pub(in …)`).
fn strip_visibility(s: &str) -> &str {
    let Some(rest) = s.strip_prefix("pub") else {
        return s;
    };
    if let Some(inner) = rest.strip_prefix('(') {
        return inner.find(')').map_or(s, |k| inner[k + 1..].trim_start());
    }
    if rest.starts_with(char::is_whitespace) {
        rest.trim_start()
    } else {
        s
    }
}

/// The last line of the `#[cfg(test)]` module whose attribute is on line `at` (its `mod … {`
/// on that line or the next); `None` if no inline module follows the attribute.
fn test_module_end(code: &[String], at: usize) -> Option<usize> {
    let is_mod = |s: &str| strip_visibility(s.trim()).starts_with("mod ");
    let rest = code[at].trim_start().trim_start_matches("#[cfg(test)]");
    let first = if is_mod(rest) {
        at
    } else if code.get(at + 1).is_some_and(|l| is_mod(l)) {
        at + 1
    } else {
        return None;
    };
    let (mut depth, mut opened) = (0i32, false);
    for (k, line) in code.iter().enumerate().skip(first) {
        if !opened && line.contains(';') && !line.contains('{') {
            return None; // `mod tests;`: a file of its own
        }
        for ch in line.chars() {
            match ch {
                '{' => (depth, opened) = (depth + 1, true),
                '}' => depth -= 1,
                _ => {}
            }
        }
        if opened && depth <= 0 {
            return Some(k);
        }
    }
    Some(code.len() - 1)
}

/// `code` with its `#[cfg(test)] mod … { … }` blocks blanked.
fn without_test_modules(mut code: Vec<String>) -> Vec<String> {
    let mut i = 0;
    while i < code.len() {
        if code[i].trim_start().starts_with("#[cfg(test)]") {
            if let Some(end) = test_module_end(&code, i) {
                code[i..=end].iter_mut().for_each(String::clear);
                i = end;
            }
        }
        i += 1;
    }
    code
}

// ---- the paths a file names ------------------------------------------------------------------

/// A path named in a file: its line (0-based), the inline modules (`mod x { … }`) it is
/// written in, whether it comes from a `use` declaration (and a `pub` one), its segments as
/// written (`crate`, `super`, `self`, `$crate` or a name first) and the name it is imported as
/// (`as x`, else its last segment).
struct Mention {
    line: usize,
    scope: Vec<String>,
    in_use: bool,
    public: bool,
    segs: Vec<String>,
    name: String,
}

/// A token of a use tree (a name, `$crate` included, or `::`, `{`, `}`, `,`, `*`) and its line.
type Token = (String, usize);

/// The tokens of a use tree written on `line`.
fn use_tokens(text: &str, line: usize, out: &mut Vec<Token>) {
    let c: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < c.len() {
        if is_ident(c[i]) || c[i] == '$' {
            let end = (i + 1..c.len())
                .find(|&k| !is_ident(c[k]))
                .unwrap_or(c.len());
            out.push((c[i..end].iter().collect(), line));
            i = end;
        } else if c[i] == ':' && c.get(i + 1) == Some(&':') {
            out.push(("::".to_string(), line));
            i += 2;
        } else {
            if "{},*".contains(c[i]) {
                out.push((c[i].to_string(), line));
            }
            i += 1;
        }
    }
}

/// A path a `use` declaration brings in: its segments, the name it is imported as, and the
/// line of its last segment.
type UsePath = (Vec<String>, String, usize);

/// Expands the use tree at `t[*pos]` under `prefix` into full paths and their imported names
/// (`a::{b::{self, c}, d as e}` → `a::b` as `b`, `a::b::c` as `c`, `a::d` as `e`).
fn expand_use(t: &[Token], pos: &mut usize, prefix: &[String], out: &mut Vec<UsePath>) {
    let is = |k: usize, s: &str| t.get(k).is_some_and(|x| x.0 == s);
    let mut path = prefix.to_vec();
    while let Some((tok, line)) = t.get(*pos).cloned() {
        *pos += 1;
        match tok.as_str() {
            "{" => {
                while t.get(*pos).is_some() && !is(*pos, "}") {
                    expand_use(t, pos, &path, out);
                    if is(*pos, ",") {
                        *pos += 1;
                    }
                }
                *pos += 1;
                return;
            }
            "*" => return out.push(([path, vec![tok.clone()]].concat(), tok, line)),
            "self" if path.len() == prefix.len() && !prefix.is_empty() => {}
            "::" => continue,
            _ => path.push(tok),
        }
        if is(*pos, "::") {
            continue;
        }
        let name = if is(*pos, "as") {
            *pos += 2;
            t.get(*pos - 1).map(|x| x.0.clone()).unwrap_or_default()
        } else {
            path.last().cloned().unwrap_or_default()
        };
        return out.push((path, name, line));
    }
}

/// The `use` declarations of `code`, expanded; their lines are blanked in `code`.
fn use_mentions(code: &mut [String]) -> Vec<Mention> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < code.len() {
        let trimmed = code[i].trim_start();
        let rest = strip_visibility(trimmed);
        if let Some(tree) = rest.strip_prefix("use ") {
            let public = rest.len() < trimmed.len();
            let (mut tokens, mut last, mut text) = (Vec::new(), i, tree.to_string());
            loop {
                use_tokens(text.split(';').next().unwrap_or(""), last, &mut tokens);
                if text.contains(';') || last + 1 >= code.len() {
                    break;
                }
                last += 1;
                text = code[last].clone();
            }
            let mut paths = Vec::new();
            expand_use(&tokens, &mut 0, &[], &mut paths);
            for (segs, name, line) in paths {
                out.push(Mention {
                    line,
                    scope: Vec::new(),
                    in_use: true,
                    public,
                    segs,
                    name,
                });
            }
            code[i..=last].iter_mut().for_each(String::clear);
            i = last;
        }
        i += 1;
    }
    out
}

/// Every path of two or more segments written in `line` (`a::b::c`, `$crate::x`), by its
/// segments; `::<`, `::{` and `::*` end a path, and a path continuing another (`>::x`) is skipped.
fn inline_paths(line: &str) -> Vec<Vec<String>> {
    let c: Vec<char> = line.chars().collect();
    let (mut out, mut i) = (Vec::new(), 0);
    let starts_ident = |k: usize| {
        c.get(k)
            .is_some_and(|&ch| ch.is_alphabetic() || ch == '_' || ch == '$')
    };
    while i < c.len() {
        let boundary = i == 0 || !(is_ident(c[i - 1]) || c[i - 1] == '$');
        if !(starts_ident(i) && boundary) {
            i += 1;
            continue;
        }
        let continues = i >= 2 && c[i - 1] == ':' && c[i - 2] == ':';
        let mut segs = Vec::new();
        loop {
            let end = (i + 1..c.len())
                .find(|&k| !is_ident(c[k]))
                .unwrap_or(c.len());
            segs.push(c[i..end].iter().collect::<String>());
            i = end;
            if !(c.get(i) == Some(&':') && c.get(i + 1) == Some(&':') && starts_ident(i + 2)) {
                break;
            }
            i += 2;
        }
        if segs.len() >= 2 && !continues {
            out.push(segs);
        }
    }
    out
}

/// For each line of `code`, the inline modules (`mod x { … }`) it lies in, outermost first.
fn inline_modules(code: &[String]) -> Vec<Vec<String>> {
    let (mut open, mut depth, mut out) = (Vec::<(String, i32)>::new(), 0i32, Vec::new());
    for line in code {
        let head = strip_visibility(line.trim())
            .strip_prefix("mod ")
            .and_then(|r| r.split_once('{'));
        if let Some((name, _)) = head {
            open.push((name.trim().to_string(), depth));
        }
        out.push(open.iter().map(|(name, _)| name.clone()).collect());
        depth += line.matches('{').count() as i32 - line.matches('}').count() as i32;
        while open.last().is_some_and(|&(_, d)| depth <= d) {
            open.pop();
        }
    }
    out
}

/// Every path that `code` names: its `use` declarations, expanded, then the paths in the rest,
/// each with the inline modules it is written in.
fn mentions(code: &[String]) -> Vec<Mention> {
    let scopes = inline_modules(code);
    let mut rest = code.to_vec();
    let mut out = use_mentions(&mut rest);
    for (line, text) in rest.iter().enumerate() {
        for segs in inline_paths(text) {
            let name = segs.last().cloned().unwrap_or_default();
            out.push(Mention {
                line,
                scope: Vec::new(),
                in_use: false,
                public: false,
                segs,
                name,
            });
        }
    }
    for m in &mut out {
        m.scope = scopes[m.line].clone();
    }
    out
}

// ---- the library's files and modules ---------------------------------------------------------

/// A file of the library crate: its path under `src/`, its module path, its lines as written
/// and as code (comments, literals and `#[cfg(test)]` modules blanked), and what it names.
struct Unit {
    rel: String,
    module: Vec<String>,
    raw: Vec<String>,
    mentions: Vec<Mention>,
    test_free: Vec<Mention>,
}

/// The module path of a file under `src/` (`a/b.rs`, `a/b/mod.rs` → `[a, b]`; `lib.rs` → `[]`);
/// `None` for the program's files (`main.rs`, `cli/`).
fn module_path(rel: &str) -> Option<Vec<String>> {
    if rel == "main.rs" || rel.starts_with("cli/") {
        return None;
    }
    let stem = rel.trim_end_matches(".rs").trim_end_matches("/mod");
    let stem = if stem == "lib" { "" } else { stem };
    Some(
        stem.split('/')
            .filter(|s| !s.is_empty())
            .map(String::from)
            .collect(),
    )
}

/// The library crate's files under `src`, in path order.
fn library_units(src: &Path) -> Vec<Unit> {
    let mut files = Vec::new();
    sources(src, &mut files);
    files.sort();
    files
        .iter()
        .filter_map(|f| {
            let rel = f
                .strip_prefix(src)
                .expect("under src")
                .to_string_lossy()
                .replace('\\', "/");
            let module = module_path(&rel)?;
            let text = std::fs::read_to_string(f).expect("a source file");
            let code = code_lines(&text);
            Some(Unit {
                raw: text.split('\n').map(|l| l.trim().to_string()).collect(),
                mentions: mentions(&code),
                test_free: mentions(&without_test_modules(code)),
                rel,
                module,
            })
        })
        .collect()
}

/// The module paths of the file tree (every file's and every folder's), the root included.
fn module_set(units: &[Unit]) -> BTreeSet<Vec<String>> {
    let mut out = BTreeSet::new();
    for u in units {
        for k in 0..=u.module.len() {
            out.insert(u.module[..k].to_vec());
        }
    }
    out
}

/// `base` followed by `rest`.
fn joined(base: &[String], rest: &[String]) -> Vec<String> {
    [base, rest].concat()
}

/// The absolute module path a mention names, from a file of module `module`: `crate::`,
/// `$crate::`, `self::`, `super::…` resolved, a bare first segment only if it is a child
/// module of `module` (else the path is outside the crate or a local item: `None`).
fn absolute(
    segs: &[String],
    module: &[String],
    modules: &BTreeSet<Vec<String>>,
) -> Option<Vec<String>> {
    match segs[0].as_str() {
        "crate" | "$crate" => Some(segs[1..].to_vec()),
        "self" => Some(joined(module, &segs[1..])),
        "super" => {
            let ups = segs.iter().take_while(|s| *s == "super").count();
            let base = module.get(..module.len().checked_sub(ups)?)?;
            Some(joined(base, &segs[ups..]))
        }
        first => modules
            .contains(&joined(module, &[first.to_string()]))
            .then(|| joined(module, segs)),
    }
}

/// `file:line: text` for a mention of `unit`.
fn witness(unit: &Unit, m: &Mention) -> String {
    format!("{}:{}: {}", unit.rel, m.line + 1, unit.raw[m.line])
}

// ---- rule A: only the root names a root re-export --------------------------------------------

/// The names `lib.rs` re-exports (`pub use a::{X, Y}`, `pub use nalgebra`, `pub use a as b`)
/// that are not modules of the root.
fn root_reexports(units: &[Unit], modules: &BTreeSet<Vec<String>>) -> BTreeSet<String> {
    let lib = units
        .iter()
        .find(|u| u.rel == "lib.rs")
        .expect("src/lib.rs");
    lib.mentions
        .iter()
        .filter(|m| m.in_use && m.public && m.name != "*" && m.name != "_")
        .filter(|m| !modules.contains(&vec![m.name.clone()]))
        .map(|m| m.name.clone())
        .collect()
}

/// Every line of a file under `src` other than `lib.rs`, `prelude.rs` and the program's
/// (`main.rs`, `cli/`, where `crate` is the program) that names a root re-export as
/// `crate::X` (in a path or a `use crate::{X, …}`), as `file:line: text`.
pub fn root_reexport_offenders(src: &Path) -> Vec<String> {
    let units = library_units(src);
    let modules = module_set(&units);
    let names = root_reexports(&units, &modules);
    let mut out = Vec::new();
    for u in units
        .iter()
        .filter(|u| u.rel != "lib.rs" && u.rel != "prelude.rs")
    {
        for m in &u.mentions {
            let hit = m.segs[0] == "crate" && m.segs.get(1).is_some_and(|x| names.contains(x));
            if hit && !out.contains(&witness(u, m)) {
                out.push(witness(u, m));
            }
        }
    }
    out
}

// ---- rule B: no cycles between the modules, at every level -----------------------------------

/// A graph per module (its path): edges `from → to` between its children's nodes (a child
/// module's name, or `mod` for its own `mod.rs` / `lib.rs`), each with its witnesses.
type Graphs = BTreeMap<Vec<String>, BTreeMap<(String, String), Vec<String>>>;

/// Whether `unit` is a module's own file with child modules (`lib.rs`, `mod.rs`, `a.rs` beside `a/`).
fn owns_children(unit: &Unit, modules: &BTreeSet<Vec<String>>) -> bool {
    modules
        .iter()
        .any(|m| m.len() == unit.module.len() + 1 && m.starts_with(&unit.module))
}

/// For each module with children, the names its own file imports from a child (`pub use
/// c::X`, `use self::c::Y as Z`, `use crate::…::c::W`) and that child `c`.
fn reexports(
    units: &[Unit],
    modules: &BTreeSet<Vec<String>>,
) -> BTreeMap<Vec<String>, BTreeMap<String, String>> {
    let mut out: BTreeMap<_, BTreeMap<_, _>> = BTreeMap::new();
    for u in units.iter().filter(|u| owns_children(u, modules)) {
        for m in u.test_free.iter().filter(|m| m.in_use && m.name != "*") {
            let Some(path) = absolute(&m.segs, &joined(&u.module, &m.scope), modules) else {
                continue;
            };
            if let Some(child) = child_of(&u.module, &path, modules) {
                out.entry(u.module.clone())
                    .or_default()
                    .insert(m.name.clone(), child);
            }
        }
    }
    out
}

/// The child module of `module` that `path` lies in, if any.
fn child_of(module: &[String], path: &[String], modules: &BTreeSet<Vec<String>>) -> Option<String> {
    let child = path.get(..module.len() + 1)?;
    (child.starts_with(module) && modules.contains(child)).then(|| child[module.len()].clone())
}

/// The edge that a file of node path `node` (its module path, plus `mod` for a module's own
/// file) naming `target` makes: at the deepest module both lie in (and `node` is below), from
/// the node holding the file to the child holding the target — through that module's
/// re-exports for an item it re-exports, `mod` for an item of its own. `None` for a self-edge.
fn edge(
    node: &[String],
    target: &[String],
    modules: &BTreeSet<Vec<String>>,
    reexp: &BTreeMap<Vec<String>, BTreeMap<String, String>>,
) -> Option<(Vec<String>, String, String)> {
    let common = node.iter().zip(target).take_while(|(a, b)| a == b).count();
    let level = node[..common.min(node.len() - 1)].to_vec();
    let from = node[level.len()].clone();
    let to = match target.get(level.len()) {
        None => "mod".to_string(),
        Some(t) if modules.contains(&joined(&level, std::slice::from_ref(t))) => t.clone(),
        Some(t) => reexp
            .get(&level)
            .and_then(|r| r.get(t))
            .cloned()
            .unwrap_or_else(|| "mod".into()),
    };
    (from != to).then_some((level, from, to))
}

/// The import graphs of the library under `src` (test modules, `lib.rs`, `prelude.rs` and the
/// program left out; a module's own `use` of its children is a declaration, not an edge).
fn import_graphs(src: &Path) -> Graphs {
    let units = library_units(src);
    let modules = module_set(&units);
    let reexp = reexports(&units, &modules);
    let mut graphs = Graphs::new();
    for u in units
        .iter()
        .filter(|u| u.rel != "lib.rs" && u.rel != "prelude.rs")
    {
        let owner = owns_children(u, &modules);
        let node = if owner {
            joined(&u.module, &["mod".to_string()])
        } else {
            u.module.clone()
        };
        for m in &u.test_free {
            let Some(target) = absolute(&m.segs, &joined(&u.module, &m.scope), &modules) else {
                continue;
            };
            if owner && m.in_use && child_of(&u.module, &target, &modules).is_some() {
                continue;
            }
            if let Some((level, from, to)) = edge(&node, &target, &modules, &reexp) {
                let w = graphs
                    .entry(level)
                    .or_default()
                    .entry((from, to))
                    .or_default();
                if !w.contains(&witness(u, m)) {
                    w.push(witness(u, m));
                }
            }
        }
    }
    graphs
}

/// The nodes reachable from `start` by one or more edges.
fn reachable<'a>(
    edges: &'a BTreeMap<(String, String), Vec<String>>,
    start: &'a str,
) -> BTreeSet<&'a str> {
    let (mut seen, mut todo) = (BTreeSet::new(), vec![start]);
    while let Some(n) = todo.pop() {
        for (from, to) in edges.keys() {
            if from == n && seen.insert(to.as_str()) {
                todo.push(to);
            }
        }
    }
    seen
}

/// The strongly connected components of more than one node.
fn components(edges: &BTreeMap<(String, String), Vec<String>>) -> Vec<BTreeSet<String>> {
    let nodes: BTreeSet<&str> = edges
        .keys()
        .flat_map(|(a, b)| [a.as_str(), b.as_str()])
        .collect();
    let reach: BTreeMap<&str, BTreeSet<&str>> =
        nodes.iter().map(|&n| (n, reachable(edges, n))).collect();
    let mut out: Vec<BTreeSet<String>> = Vec::new();
    for &n in &nodes {
        let comp: BTreeSet<String> = nodes
            .iter()
            .filter(|&&m| m == n || reach[n].contains(m) && reach[m].contains(n))
            .map(|m| m.to_string())
            .collect();
        if comp.len() > 1 && !out.contains(&comp) {
            out.push(comp);
        }
    }
    out
}

/// A cycle's description: its module, its nodes, and its edges, each with its first witness;
/// with `mod_edges`, only the edges to and from `mod` get witnesses, the others are listed.
fn describe(
    level: &[String],
    comp: &BTreeSet<String>,
    edges: &BTreeMap<(String, String), Vec<String>>,
    mod_edges: bool,
) -> String {
    let name = if level.is_empty() {
        "crate".to_string()
    } else {
        level.join("::")
    };
    let nodes: Vec<&str> = comp.iter().map(String::as_str).collect();
    let mut text = format!("cycle in `{name}`: {}", nodes.join(" ⇄ "));
    let mut others = Vec::new();
    for ((from, to), w) in edges
        .iter()
        .filter(|((a, b), _)| comp.contains(a) && comp.contains(b))
    {
        if mod_edges && from != "mod" && to != "mod" {
            others.push(format!("{from} → {to}"));
            continue;
        }
        let more = if w.len() > 1 {
            format!(" (+{} more)", w.len() - 1)
        } else {
            String::new()
        };
        text += &format!("\n    {from} → {to}: {}{more}", w[0]);
    }
    if !others.is_empty() {
        text += &format!("\n    and {}", others.join(", "));
    }
    text
}

/// The import cycles of the library under `src`, one description per cycle: with
/// `through_mod` false, cycles among child modules (the `mod` nodes left out); with it true,
/// the cycles that pass through a module's own file (`mod.rs`), showing their edges to and from it.
pub fn module_cycles(src: &Path, through_mod: bool) -> Vec<String> {
    let mut out = Vec::new();
    for (level, mut edges) in import_graphs(src) {
        if !through_mod {
            edges.retain(|(a, b), _| a != "mod" && b != "mod");
        }
        for comp in components(&edges) {
            if !through_mod || comp.contains("mod") {
                out.push(describe(&level, &comp, &edges, through_mod));
            }
        }
    }
    out
}

/// The imports between the top-level rooms of the library (files and folders of `src/`):
/// each edge `(from, to)` with one witness `file:line: text`.
pub fn room_edges(src: &Path) -> Vec<(String, String, String)> {
    import_graphs(src)
        .remove(&Vec::new())
        .unwrap_or_default()
        .into_iter()
        .filter(|((a, b), _)| a != "mod" && b != "mod")
        .map(|((a, b), w)| (a, b, w.first().cloned().unwrap_or_default()))
        .collect()
}
