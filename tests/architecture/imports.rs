//! Which file of `src/` uses which: every path that names an item of the
//! crate (`crate::…`, `super::…`, `self::…`, a child module, or a name a
//! `use` brought in), in `use` trees, code, attributes and macros, resolved
//! to the file that defines the module it reaches. A `mod NAME;` line only
//! declares a module and is not a use.

use proc_macro2::{Delimiter, TokenStream, TokenTree};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// A module's path from the crate's root, e.g. `["api", "kind"]`.
type Module = Vec<String>;

/// The crate's files by module, and each file's module.
pub struct Crate {
    files: BTreeMap<Module, PathBuf>,
}

impl Crate {
    pub fn read(src: &Path) -> Self {
        let mut paths = Vec::new();
        super::rust_files(src, &mut paths);
        let mut files = BTreeMap::new();
        for path in paths {
            let rel = path.strip_prefix(src).unwrap().with_extension("");
            let mut module: Module = rel.iter().map(|c| c.to_string_lossy().into_owned()).collect();
            if module.last().is_some_and(|m| m == "mod") || module == ["lib"] {
                module.pop();
            }
            if module != ["main"] {
                files.insert(module, path);
            }
        }
        Self { files }
    }

    /// Every file's uses: file → the files it uses, leaving out its own
    /// module's ancestors (a submodule reads its parent's items through
    /// `super::`, the parent calls into it: that pair is one module's
    /// inside; any other way back is a cycle).
    pub fn edges(&self) -> BTreeMap<String, BTreeSet<String>> {
        let mut edges = BTreeMap::new();
        for (module, path) in &self.files {
            let text = std::fs::read_to_string(path).unwrap();
            let tokens: TokenStream = text.parse().unwrap_or_else(|e| panic!("{}: {e:?}", path.display()));
            let mut scan = Scan { krate: self, aliases: BTreeMap::new(), targets: BTreeSet::new() };
            scan.tokens(tokens, module);
            let ancestor = |m: &Module| module.starts_with(m);
            let targets = scan.targets.iter().filter(|m| !ancestor(m)).map(|m| self.name(m)).collect();
            edges.insert(self.name(module), targets);
        }
        edges
    }

    fn name(&self, module: &Module) -> String {
        self.files[module].to_string_lossy().rsplit_once("src/").map(|(_, f)| f.to_string()).unwrap()
    }

    fn is_module(&self, module: &[String]) -> bool {
        self.files.contains_key(module)
    }

    /// The deepest module with a file of its own along `path` (from the root).
    fn resolve(&self, path: &[String]) -> Module {
        let mut base = Module::new();
        for segment in path {
            base.push(segment.clone());
            if !self.is_module(&base) {
                base.pop();
                break;
            }
        }
        // An inline module (`mod tests { … }`) lives in its parent's file.
        while !base.is_empty() && !self.is_module(&base) {
            base.pop();
        }
        base
    }
}

struct Scan<'a> {
    krate: &'a Crate,
    /// Names a `use` brought in, with the module path they stand for.
    aliases: BTreeMap<String, Vec<String>>,
    targets: BTreeSet<Module>,
}

impl Scan<'_> {
    fn tokens(&mut self, tokens: TokenStream, module: &Module) {
        let tokens: Vec<TokenTree> = tokens.into_iter().collect();
        let mut i = 0;
        while i < tokens.len() {
            match &tokens[i] {
                TokenTree::Ident(id) if id == "use" => {
                    let end = tokens[i..].iter().position(|t| is_punct(t, ';')).map_or(tokens.len(), |p| i + p);
                    self.use_tree(&tokens[i + 1..end], Vec::new(), module);
                    i = end;
                }
                TokenTree::Ident(id) if id == "mod" => {
                    if let (Some(TokenTree::Ident(name)), Some(TokenTree::Group(g))) =
                        (tokens.get(i + 1), tokens.get(i + 2))
                        && g.delimiter() == Delimiter::Brace
                    {
                        let inner = [module.clone(), vec![name.to_string()]].concat();
                        let outer = std::mem::take(&mut self.aliases);
                        self.tokens(g.stream(), &inner);
                        self.aliases = outer;
                        i += 2;
                    }
                }
                TokenTree::Ident(_) if !preceded_by_colons(&tokens, i) => {
                    let (path, next) = path_at(&tokens, i);
                    if path.len() > 1 {
                        self.path(&path, module);
                    }
                    i = next.max(i + 1) - 1;
                }
                TokenTree::Group(g) => self.tokens(g.stream(), module),
                _ => {}
            }
            i += 1;
        }
    }

    /// A `use` tree after `prefix`: `a::b`, `a::{b, c::d}`, `a as b`, `a::*`.
    fn use_tree(&mut self, tokens: &[TokenTree], prefix: Vec<String>, module: &Module) {
        for part in split_commas(tokens) {
            let mut path = prefix.clone();
            let mut alias = None;
            let mut j = 0;
            while j < part.len() {
                match &part[j] {
                    TokenTree::Ident(id) if id == "as" => {
                        alias = part.get(j + 1).map(|t| t.to_string());
                        j += 1;
                    }
                    TokenTree::Ident(id) => path.push(id.to_string()),
                    TokenTree::Group(g) if g.delimiter() == Delimiter::Brace => {
                        let inner: Vec<TokenTree> = g.stream().into_iter().collect();
                        self.use_tree(&inner, path.clone(), module);
                        path.clear();
                    }
                    _ => {}
                }
                j += 1;
            }
            if path.last().is_some_and(|s| s == "self") {
                path.pop();
            }
            let Some(last) = path.last().cloned() else { continue };
            if let Some(absolute) = self.absolute(&path, module) {
                self.record(&absolute);
                self.aliases.insert(alias.unwrap_or(last), absolute);
            }
        }
    }

    /// `path` from `module` as a path from the crate's root; None when it
    /// starts outside the crate.
    fn absolute(&self, path: &[String], module: &Module) -> Option<Vec<String>> {
        let mut base: Vec<String> = module.clone();
        let mut rest = path;
        match rest.first().map(String::as_str) {
            Some("crate") => {
                base.clear();
                rest = &rest[1..];
            }
            Some("self") => rest = &rest[1..],
            Some("super") => {
                while rest.first().is_some_and(|s| s == "super") {
                    base.pop();
                    rest = &rest[1..];
                }
            }
            Some(head) if self.krate.is_module(&[module.clone(), vec![head.to_string()]].concat()) => {}
            Some(head) if self.aliases.contains_key(head) => {
                base = self.aliases[head].clone();
                rest = &rest[1..];
            }
            _ => return None,
        }
        Some([base, rest.to_vec()].concat())
    }

    /// Records the file `path` (written in `module`) reaches.
    fn path(&mut self, path: &[String], module: &Module) {
        if let Some(absolute) = self.absolute(path, module) {
            self.record(&absolute);
        }
    }

    fn record(&mut self, absolute: &[String]) {
        self.targets.insert(self.krate.resolve(absolute));
    }
}

fn is_punct(t: &TokenTree, c: char) -> bool {
    matches!(t, TokenTree::Punct(p) if p.as_char() == c)
}

fn preceded_by_colons(tokens: &[TokenTree], i: usize) -> bool {
    i >= 2 && is_punct(&tokens[i - 1], ':') && is_punct(&tokens[i - 2], ':')
}

/// The path `a::b::c` starting at `i`, and the index after it.
fn path_at(tokens: &[TokenTree], mut i: usize) -> (Vec<String>, usize) {
    let mut path = Vec::new();
    while let Some(TokenTree::Ident(id)) = tokens.get(i) {
        path.push(id.to_string());
        let colons =
            tokens.get(i + 1).is_some_and(|t| is_punct(t, ':')) && tokens.get(i + 2).is_some_and(|t| is_punct(t, ':'));
        if !colons {
            return (path, i + 1);
        }
        i += 3;
    }
    (path, i)
}

fn split_commas(tokens: &[TokenTree]) -> Vec<&[TokenTree]> {
    tokens.split(|t| is_punct(t, ',')).filter(|p| !p.is_empty()).collect()
}

/// The cycles of `edges`: each strongly connected component of more than one file.
pub fn cycles(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    // Tarjan's algorithm, recursive (the graph is a few hundred files).
    struct State<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        s.on_stack.insert(v);
        for w in s.edges.get(v).into_iter().flatten() {
            if !s.index.contains_key(w.as_str()) {
                visit(s, w);
                let low = s.low[w.as_str()].min(s.low[v]);
                s.low.insert(v, low);
            } else if s.on_stack.contains(w.as_str()) {
                let low = s.index[w.as_str()].min(s.low[v]);
                s.low.insert(v, low);
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack.remove(w);
                component.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                s.out.push(component);
            }
        }
    }
    let mut s = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in edges.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out
}
