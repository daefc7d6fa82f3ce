//! Datapath widths, seen: every signal of an rtl block with the fixed-point format its source declares and the
//! range of values it takes in the rust-hdl simulation of the unit's vectors.
//!
//! The simulator keeps widths but not formats (`Sq1_10` and `Uq0_12` are both `Bits<12>` to it), so the formats
//! come from the rtl's own source text (`rtl::source::FILES`): each block's struct is parsed for its fields' types,
//! and a signal's hierarchical name (`uut.norm.s3_l.q`, as in the VCD) is followed through them, generic parameters
//! substituted, down to its type alias. The values come from a rust-hdl probe that visits every signal once a clock,
//! with the clock low and the slot settled (every register's d is then what the edge latches).

pub mod bounds;
pub mod wraps;

use rtl::stream::Runner;
use rtl::StreamUnit;
use rust_hdl::core::atom::Atom;
use rust_hdl::core::block::Block;
use rust_hdl::core::probe::Probe;
use std::collections::HashMap;
use vectors::UnitModel;

/// A type as the source writes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Ty {
    /// `Name` or `Name<args>` (the last path segment)
    Path(String, Vec<Ty>),
    /// `[T; len]`
    Array(Box<Ty>, String),
    /// a const argument: a number, `false`, `{ expr }`
    Expr(String),
}

impl Ty {
    fn parse(s: &str) -> Option<Ty> {
        let mut p = Parser { s: s.as_bytes(), i: 0 };
        let t = p.ty()?;
        p.ws();
        (p.i == p.s.len()).then_some(t)
    }

    /// The type with generic names replaced by the instance's arguments.
    fn subst(&self, env: &HashMap<String, Ty>) -> Ty {
        match self {
            Ty::Path(n, args) if args.is_empty() => env.get(n).cloned().unwrap_or_else(|| self.clone()),
            Ty::Path(n, args) => Ty::Path(n.clone(), args.iter().map(|a| a.subst(env)).collect()),
            Ty::Array(t, len) => Ty::Array(Box::new(t.subst(env)), len.clone()),
            Ty::Expr(_) => self.clone(),
        }
    }

    pub fn text(&self) -> String {
        match self {
            Ty::Path(n, a) if a.is_empty() => n.clone(),
            Ty::Path(n, a) => format!("{n}<{}>", a.iter().map(Ty::text).collect::<Vec<_>>().join(", ")),
            Ty::Array(t, len) => format!("[{}; {len}]", t.text()),
            Ty::Expr(e) => e.clone(),
        }
    }
}

struct Parser<'a> {
    s: &'a [u8],
    i: usize,
}

impl Parser<'_> {
    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }
    fn peek(&mut self) -> Option<u8> {
        self.ws();
        self.s.get(self.i).copied()
    }
    fn eat(&mut self, c: u8) -> Option<()> {
        (self.peek()? == c).then(|| self.i += 1)
    }
    /// Text up to the `close` that balances, nested `open`s counted.
    fn balanced(&mut self, open: u8, close: u8) -> Option<String> {
        let start = self.i;
        let mut depth = 0;
        while self.i < self.s.len() {
            let c = self.s[self.i];
            if c == open {
                depth += 1;
            } else if c == close {
                if depth == 0 {
                    return Some(String::from_utf8_lossy(&self.s[start..self.i]).trim().to_string());
                }
                depth -= 1;
            }
            self.i += 1;
        }
        None
    }
    fn ty(&mut self) -> Option<Ty> {
        match self.peek()? {
            b'[' => {
                self.i += 1;
                let t = self.ty()?;
                self.eat(b';')?;
                let len = self.balanced(b'[', b']')?;
                self.eat(b']')?;
                Some(Ty::Array(Box::new(t), len))
            }
            b'{' => {
                self.i += 1;
                let e = self.balanced(b'{', b'}')?;
                self.eat(b'}')?;
                Some(Ty::Expr(e))
            }
            c if c.is_ascii_digit() || c == b'-' => {
                let start = self.i;
                self.i += 1;
                while self.i < self.s.len() && (self.s[self.i].is_ascii_alphanumeric() || self.s[self.i] == b'_') {
                    self.i += 1;
                }
                Some(Ty::Expr(String::from_utf8_lossy(&self.s[start..self.i]).to_string()))
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                let mut name;
                loop {
                    let start = self.i;
                    while self.i < self.s.len() && (self.s[self.i].is_ascii_alphanumeric() || self.s[self.i] == b'_') {
                        self.i += 1;
                    }
                    name = String::from_utf8_lossy(&self.s[start..self.i]).to_string();
                    if self.s[self.i..].starts_with(b"::") {
                        self.i += 2;
                    } else {
                        break;
                    }
                }
                let mut args = vec![];
                if self.peek() == Some(b'<') {
                    self.i += 1;
                    loop {
                        args.push(self.ty()?);
                        match self.peek()? {
                            b',' => self.i += 1,
                            b'>' => {
                                self.i += 1;
                                break;
                            }
                            _ => return None,
                        }
                    }
                }
                match name.as_str() {
                    "true" | "false" => Some(Ty::Expr(name)),
                    _ => Some(Ty::Path(name, args)),
                }
            }
            _ => None,
        }
    }
}

/// A block's struct as its source declares it.
#[derive(Clone, Debug, Default)]
pub struct Decl {
    pub generics: Vec<String>,
    /// each generic's default (`const D: usize = 0`), for a type written without it
    pub defaults: Vec<Option<Ty>>,
    pub fields: Vec<(String, Ty)>,
}

/// The library blocks the rtl uses, declared as rust-hdl 0.46 declares them (their signals only).
const LIBRARY: &str = "
pub struct DFF<T> { pub d: Signal<In, T>, pub q: Signal<Out, T>, pub clock: Signal<In, Clock>, }
pub struct ROM<D, const N: usize> { pub address: Signal<In, Bits<N>>, pub data: Signal<Out, D>, }
pub struct RAM<D, const N: usize> {
    pub read_address: Signal<In, Bits<N>>, pub read_clock: Signal<In, Clock>, pub read_data: Signal<Out, D>,
    pub write_address: Signal<In, Bits<N>>, pub write_clock: Signal<In, Clock>, pub write_data: Signal<In, D>,
    pub write_enable: Signal<In, bool>,
}
";

/// Source text without comments (`//` to the end of the line) and attributes (`#[...]`).
fn strip(src: &str) -> String {
    let mut out = String::with_capacity(src.len());
    for line in src.lines() {
        let code = match line.find("//") {
            Some(k) => &line[..k],
            None => line,
        };
        let t = code.trim_start();
        if t.starts_with("#[") || t.starts_with("#![") {
            continue;
        }
        out.push_str(code);
        out.push('\n');
    }
    out
}

/// Split at the commas that stand outside every bracket.
fn top_level_commas(s: &str) -> Vec<String> {
    let (mut parts, mut cur, mut depth) = (vec![], String::new(), 0i32);
    for c in s.chars() {
        match c {
            '<' | '[' | '(' | '{' => depth += 1,
            '>' | ']' | ')' | '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(std::mem::take(&mut cur));
                continue;
            }
            _ => {}
        }
        cur.push(c);
    }
    parts.push(cur);
    parts.into_iter().map(|p| p.trim().to_string()).filter(|p| !p.is_empty()).collect()
}

/// `[pub] name: Type` items of a field list, each wrapped by `wrap` (the sections of `stream_block!`).
fn fields(list: &str, wrap: &dyn Fn(Ty) -> Ty) -> Vec<(String, Ty)> {
    let mut out = vec![];
    for item in top_level_commas(list) {
        let item = item.trim_start_matches("pub(crate)").trim_start_matches("pub").trim();
        let Some((name, ty)) = item.split_once(':') else { continue };
        if let Some(t) = Ty::parse(ty) {
            out.push((name.trim().to_string(), wrap(t)));
        }
    }
    out
}

fn signal(dir: &str, t: Ty) -> Ty {
    Ty::Path("Signal".into(), vec![Ty::Path(dir.into(), vec![]), t])
}

/// The invocations, in the same text, of each `macro_rules!` the text defines, expanded (`expand_macros`).
fn expand_local_macros(s: &str) -> Vec<String> {
    expand_macros(s, s)
}

/// The invocations, in `s`, of each `macro_rules!` that `defs` defines, expanded by substituting their
/// arguments for the first rule's plain `$name:kind` parameters (repetitions such as `$(#[$doc:meta])*` are left
/// out on both sides), and for the parameters of its optional groups (`$(, marker: $a:ident, $b:ident)?`), which an
/// invocation binds by naming the marker (`marker: x, y`): a group of the body (`$( ... )?`) is kept when the
/// invocation bound every parameter it names and dropped when not. Enough for the rtl's own macros that declare
/// blocks.
fn expand_macros(defs: &str, s: &str) -> Vec<String> {
    let mut out = vec![];
    for (k, _) in defs.match_indices("macro_rules!") {
        let mut p = Parser { s: defs.as_bytes(), i: k + 12 };
        p.ws();
        let start = p.i;
        while p.i < p.s.len() && (p.s[p.i].is_ascii_alphanumeric() || p.s[p.i] == b'_') {
            p.i += 1;
        }
        let name = defs[start..p.i].to_string();
        // `{ (matcher) => { body } ... }`: the first rule
        if p.eat(b'{').is_none() || p.eat(b'(').is_none() {
            continue;
        }
        let Some(matcher) = p.balanced(b'(', b')') else { continue };
        p.i += 1;
        if p.eat(b'=').is_none() || p.eat(b'>').is_none() || p.eat(b'{').is_none() {
            continue;
        }
        let Some(body) = p.balanced(b'{', b'}') else { continue };
        // the matcher without its repetitions, then its parameters in order; the optional groups' markers and
        // parameters apart
        let names = |t: &str| -> Vec<String> {
            t.split('$').skip(1).filter_map(|t| t.split_once(':').map(|(n, _)| n.trim().to_string())).collect()
        };
        let mut plain = String::new();
        let mut groups: Vec<(String, Vec<String>)> = vec![];
        let mut m = Parser { s: matcher.as_bytes(), i: 0 };
        while m.i < m.s.len() {
            if m.s[m.i..].starts_with(b"$(") {
                m.i += 2;
                let inner = m.balanced(b'(', b')').unwrap_or_default();
                if m.s.get(m.i + 1) == Some(&b'?') {
                    let marker = inner
                        .split('$')
                        .next()
                        .unwrap_or("")
                        .trim_matches(|c: char| c == ',' || c.is_whitespace())
                        .trim_end_matches(':');
                    groups.push((marker.to_string(), names(&inner)));
                }
                m.i += 2; // `)` and the repetition's `*`, `+` or `?`
                continue;
            }
            plain.push(m.s[m.i] as char);
            m.i += 1;
        }
        let mut params: Vec<String> = names(&plain);
        // invocations `name!(args)` / `name! { args }`
        for (j, _) in s.match_indices(&format!("{name}!")) {
            if j > 0 && (s.as_bytes()[j - 1].is_ascii_alphanumeric() || s.as_bytes()[j - 1] == b'_') {
                continue;
            }
            let mut q = Parser { s: s.as_bytes(), i: j + name.len() + 1 };
            let (open, close) = match q.peek() {
                Some(b'(') => (b'(', b')'),
                Some(b'{') => (b'{', b'}'),
                _ => continue,
            };
            q.i += 1;
            let Some(args) = q.balanced(open, close) else { continue };
            let args = top_level_commas(&args);
            if args.len() < params.len() {
                continue;
            }
            let mut bound: Vec<(String, String)> = params.iter().cloned().zip(args.iter().cloned()).collect();
            let mut rest = &args[params.len()..];
            for (marker, group) in &groups {
                let Some(first) = rest
                    .first()
                    .and_then(|a| a.strip_prefix(marker.as_str()))
                    .and_then(|a| a.trim_start().strip_prefix(':'))
                else {
                    continue;
                };
                if marker.is_empty() || rest.len() < group.len() {
                    break;
                }
                let mut values = vec![first.trim().to_string()];
                values.extend(rest[1..group.len()].iter().cloned());
                bound.extend(group.iter().cloned().zip(values));
                rest = &rest[group.len()..];
            }
            if !rest.is_empty() {
                continue;
            }
            let mut text = optional_groups(&body, &bound);
            // the longest names first, so that `$dec_mod` is not read as `$dec` + `_mod`
            bound.sort_by_key(|(n, _)| std::cmp::Reverse(n.len()));
            for (n, a) in &bound {
                text = text.replace(&format!("${n}"), a.trim_matches('"'));
            }
            out.push(text);
        }
        params.clear();
    }
    out
}

/// A macro body with each optional group `$( ... )?` kept (its content alone) when every `$name` in it is bound,
/// and dropped when not; other repetitions are left as they are.
fn optional_groups(body: &str, bound: &[(String, String)]) -> String {
    let mut out: Vec<u8> = vec![];
    let mut p = Parser { s: body.as_bytes(), i: 0 };
    while p.i < p.s.len() {
        if p.s[p.i..].starts_with(b"$(") {
            let start = p.i;
            p.i += 2;
            let inner = p.balanced(b'(', b')').unwrap_or_default();
            if p.s.get(p.i + 1) == Some(&b'?') {
                let used = inner
                    .split('$')
                    .skip(1)
                    .map(|t| t.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect::<String>());
                let all_bound = used.filter(|n| !n.is_empty()).all(|n| bound.iter().any(|(b, _)| *b == n));
                if all_bound {
                    out.extend_from_slice(inner.as_bytes());
                    out.push(b' ');
                }
                p.i += 2;
            } else {
                p.i = start + 2;
                out.extend_from_slice(b"$(");
            }
            continue;
        }
        out.push(p.s[p.i]);
        p.i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Every struct of the rtl's source (and of the library blocks it uses), by name; every type alias; and every
/// integer constant (`const NAME: usize = 10;`) whose name is not declared twice with two values.
pub fn declarations() -> (HashMap<String, Decl>, HashMap<String, Ty>) {
    let (mut decls, mut aliases) = (HashMap::new(), HashMap::new());
    let mut consts: HashMap<String, Option<String>> = HashMap::new();
    let mut sources: Vec<String> = vec![strip(LIBRARY)];
    let files: Vec<String> = rtl::source::FILES.iter().map(|f| strip(f.1)).collect();
    // a file whose macros are re-exported by path (`pub(crate) use name;`) lends them to every other file
    let lenders: Vec<&String> =
        files.iter().filter(|s| s.contains("macro_rules!") && s.contains("pub(crate) use ")).collect();
    for s in &files {
        sources.extend(expand_local_macros(s));
        for d in lenders.iter().filter(|d| !std::ptr::eq(**d, s)) {
            sources.extend(expand_macros(d, s));
        }
        sources.push(s.clone());
    }
    for s in &sources {
        let b = s.as_bytes();
        // integer constants
        for (k, _) in s.match_indices("const ") {
            let rest = &s[k + 6..];
            let Some(semi) = rest.find(';') else { continue };
            let decl = &rest[..semi];
            let (Some((name, _)), Some((_, value))) = (decl.split_once(':'), decl.split_once('=')) else { continue };
            let (name, value) = (name.trim(), value.trim());
            if value.parse::<u64>().is_ok() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                let e = consts.entry(name.to_string()).or_insert(Some(value.to_string()));
                if e.as_deref() != Some(value) {
                    *e = None;
                }
            }
        }
        // type aliases: `type Name = Type;`
        for (k, _) in s.match_indices("type ") {
            if k > 0 && (b[k - 1].is_ascii_alphanumeric() || b[k - 1] == b'_') {
                continue;
            }
            let rest = &s[k + 5..];
            let (Some(eq), Some(semi)) = (rest.find('='), rest.find(';')) else { continue };
            if eq > semi {
                continue;
            }
            let name = rest[..eq].trim();
            if name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                if let Some(t) = Ty::parse(&rest[eq + 1..semi]) {
                    aliases.insert(name.to_string(), t);
                }
            }
        }
        // structs: `struct Name<generics> {` or `struct Name<generics>: unit(..) { in { } out { } fields }`
        for (k, _) in s.match_indices("struct ") {
            if k > 0 && (b[k - 1].is_ascii_alphanumeric() || b[k - 1] == b'_') {
                continue;
            }
            let mut p = Parser { s: b, i: k + 7 };
            p.ws();
            let start = p.i;
            while p.i < b.len() && (b[p.i].is_ascii_alphanumeric() || b[p.i] == b'_') {
                p.i += 1;
            }
            let name = s[start..p.i].to_string();
            let (mut generics, mut defaults) = (vec![], vec![]);
            if p.peek() == Some(b'<') {
                p.i += 1;
                let Some(g) = p.balanced(b'<', b'>') else { continue };
                p.i += 1;
                for item in top_level_commas(&g) {
                    let item = item.trim_start_matches("const ").trim();
                    let n = item.split([':', '=']).next().unwrap_or("").trim();
                    generics.push(n.to_string());
                    defaults.push(item.split_once('=').and_then(|(_, d)| Ty::parse(d.trim())));
                }
            }
            // to the body's brace, past `: unit(...)` in a stream block; a `;` or `(` first is no block of ours
            let stream = p.peek() == Some(b':');
            if stream {
                while p.i < b.len() && b[p.i] != b'(' {
                    p.i += 1;
                }
                p.i += 1;
                if p.balanced(b'(', b')').is_none() {
                    continue;
                }
                p.i += 1;
            }
            while p.i < b.len() && !matches!(b[p.i], b'{' | b';' | b'(') {
                p.i += 1;
            }
            if p.i >= b.len() || b[p.i] != b'{' {
                continue;
            }
            p.i += 1;
            let Some(body) = p.balanced(b'{', b'}') else { continue };
            let mut d = Decl { generics, defaults, fields: vec![] };
            let mut rest = body.as_str();
            if stream {
                d.fields.push(("clock".into(), signal("In", Ty::Path("Clock".into(), vec![]))));
                d.fields.push(("valid_in".into(), signal("In", Ty::Path("Bit".into(), vec![]))));
                d.fields.push(("valid_out".into(), signal("Out", Ty::Path("Bit".into(), vec![]))));
                for (section, dir) in [("in", "In"), ("out", "Out")] {
                    let t = rest.trim_start();
                    let Some(after) = t.strip_prefix(section) else { break };
                    let mut q = Parser { s: after.as_bytes(), i: 0 };
                    if q.eat(b'{').is_none() {
                        break;
                    }
                    let Some(list) = q.balanced(b'{', b'}') else { break };
                    d.fields.extend(fields(&list, &|t| signal(dir, t)));
                    rest = &after[q.i + 1..];
                }
            }
            d.fields.extend(fields(rest, &|t| t));
            if !name.is_empty() {
                decls.insert(name, d);
            }
        }
    }
    // the constants stand beside the aliases: a width written `Bits<ANGLE_BITS>` reads its value there
    for (name, v) in consts {
        if let Some(v) = v {
            aliases.entry(name).or_insert(Ty::Expr(v));
        }
    }
    (decls, aliases)
}

/// A signal's declared fixed-point format.
#[derive(Clone, Debug, PartialEq)]
pub struct Format {
    /// as the source names it after aliases and generics: `Sq1_10`, `U8`, `Bits<23>`, `Bit`
    pub name: String,
    pub signed: bool,
    pub bits: usize,
    /// fraction bits (0 for integers and raw bits)
    pub frac: u32,
}

impl Format {
    /// Qm.n, the sign not counted in m (the convention of `rtl::q`), with `s`/`u`: "sQ1.10", "uQ0.10", "u8".
    pub fn q(&self) -> String {
        let int = self.bits as i64 - self.frac as i64 - self.signed as i64;
        match (self.signed, self.frac) {
            (s, 0) => format!("{}{}", if s { "s" } else { "u" }, self.bits),
            (true, f) => format!("sQ{int}.{f}"),
            (false, f) => format!("uQ{int}.{f}"),
        }
    }

    fn of(name: &str, aliases: &HashMap<String, Ty>, depth: usize) -> Option<Format> {
        let num = |s: &str| s.parse::<usize>().ok();
        let f = |signed: bool, bits: usize, frac: u32| Some(Format { name: name.to_string(), signed, bits, frac });
        if let Some((m, n)) = name.strip_prefix("Sq").and_then(|r| r.split_once('_')) {
            return f(true, 1 + num(m)? + num(n)?, num(n)? as u32);
        }
        if let Some((m, n)) = name.strip_prefix("Uq").and_then(|r| r.split_once('_')) {
            return f(false, num(m)? + num(n)?, num(n)? as u32);
        }
        if let Some(b) = name.strip_prefix('U').and_then(num) {
            return f(false, b, 0);
        }
        if let Some(b) = name.strip_prefix('S').and_then(num) {
            return f(true, b, 0);
        }
        if name == "Bit" || name == "bool" {
            return f(false, 1, 0);
        }
        let t = aliases.get(name)?;
        match t {
            Ty::Path(n, a) if n == "Bits" && a.len() == 1 => {
                let Ty::Expr(w) = &a[0] else { return None };
                f(false, num(w)?, 0)
            }
            Ty::Path(n, a) if a.is_empty() && depth < 4 => {
                Format::of(n, aliases, depth + 1).map(|x| Format { name: name.to_string(), ..x })
            }
            _ => None,
        }
    }
}

/// The format of the leaf type a signal's path ends at, or None (a clock, an unresolved name).
fn leaf_format(t: &Ty, aliases: &HashMap<String, Ty>) -> Option<Format> {
    match t {
        Ty::Path(n, a) if n == "Bits" && a.len() == 1 => match &a[0] {
            Ty::Expr(w) => Some(Format { name: format!("Bits<{w}>"), signed: false, bits: w.parse().ok()?, frac: 0 }),
            // a named constant
            Ty::Path(c, ca) if ca.is_empty() => match aliases.get(c) {
                Some(Ty::Expr(w)) => {
                    Some(Format { name: format!("Bits<{c}>"), signed: false, bits: w.parse().ok()?, frac: 0 })
                }
                _ => None,
            },
            _ => None,
        },
        // a two's complement integer of a parameter's width
        Ty::Path(n, a) if n == "SBits" && a.len() == 1 => match &a[0] {
            Ty::Expr(w) => Some(Format { name: format!("SBits<{w}>"), signed: true, bits: w.parse().ok()?, frac: 0 }),
            _ => None,
        },
        Ty::Path(n, a) if a.is_empty() => Format::of(n, aliases, 0),
        _ => None,
    }
}

/// The formats of a unit's signals, by the type name of its rtl block (`std::any::type_name`).
pub struct Formats {
    decls: HashMap<String, Decl>,
    aliases: HashMap<String, Ty>,
    top: Ty,
}

impl Formats {
    pub fn of<U>() -> Formats {
        let (decls, aliases) = declarations();
        let top = Ty::parse(std::any::type_name::<U>()).unwrap_or(Ty::Path(String::new(), vec![]));
        Formats { decls, aliases, top }
    }

    /// The types along a signal's path: the top block's, then each field's (its generics bound to the enclosing
    /// block's arguments, array elements for `name$k`), the last the signal's own (`Signal<In, Sq1_10>`).
    fn types_along(&self, path: &str) -> Option<Vec<Ty>> {
        let mut types = vec![self.top.clone()];
        for seg in path.split('.').skip(1) {
            let Ty::Path(name, args) = types.last()? else { return None };
            let d = self.decls.get(name)?;
            let mut env: HashMap<String, Ty> = d.generics.iter().cloned().zip(args.iter().cloned()).collect();
            for (g, def) in d.generics.iter().zip(&d.defaults).skip(args.len()) {
                if let Some(def) = def {
                    env.insert(g.clone(), def.clone());
                }
            }
            let mut parts = seg.split('$');
            let field = parts.next()?;
            let (_, ft) = d.fields.iter().find(|(n, _)| n == field)?;
            let mut t = ft.subst(&env);
            for _ in parts {
                let Ty::Array(inner, _) = t else { return None };
                t = *inner;
            }
            types.push(t);
        }
        Some(types)
    }

    /// The type of the block at `path` ("uut.unit$0"), by the name its struct has in the source.
    pub fn block_at(&self, path: &str) -> Option<String> {
        match self.types_along(path)?.pop()? {
            Ty::Path(n, _) => Some(n),
            _ => None,
        }
    }

    /// The block that declares the signal `path` and its name there, array indices dropped: for
    /// "uut.unit$0.s2_d0.d", ("Bilinear", "s2_d0.d"). The library's registers and memories are not owners; the
    /// block holding one is.
    pub fn owner(&self, path: &str) -> Option<(String, String)> {
        let types = self.types_along(path)?;
        let segs: Vec<&str> = path.split('.').skip(1).collect();
        // the last block on the path (not the signal itself) that is not a library register or memory
        let (k, name) = types[..types.len() - 1].iter().enumerate().rev().find_map(|(k, t)| match t {
            Ty::Path(n, _) if !matches!(n.as_str(), "DFF" | "RAM" | "ROM") => Some((k, n.clone())),
            _ => None,
        })?;
        let local: Vec<&str> = segs[k..].iter().map(|s| s.split('$').next().unwrap_or(s)).collect();
        Some((name, local.join(".")))
    }

    /// The declared format of the signal `path` ("uut.norm.s3_l.q"), or None where the source does not say.
    pub fn format(&self, path: &str) -> Option<Format> {
        match self.types_along(path)?.pop()? {
            Ty::Path(n, a) if n == "Signal" && a.len() == 2 => leaf_format(&a[1], &self.aliases),
            Ty::Path(n, a) if n == "Constant" && a.len() == 1 => leaf_format(&a[0], &self.aliases),
            _ => None,
        }
    }
}

/// Bits a range needs: for a signed one, the two's complement width holding min and max; for an unsigned one, the
/// width holding max (at least 1).
pub fn bits_needed(signed: bool, min: i64, max: i64) -> usize {
    let mag = |v: i64| 64 - v.leading_zeros() as usize; // bits of a non-negative value
    if signed {
        1 + mag(max.max(0)).max(mag((-min - 1).max(0)))
    } else {
        mag(max.max(0)).max(1)
    }
}

/// The range a signal took: its raw bit patterns, and read as two's complement.
#[derive(Clone, Debug)]
pub struct Seen {
    pub name: String,
    pub bits: usize,
    pub umin: u64,
    pub umax: u64,
    pub smin: i64,
    pub smax: i64,
}

/// Every signal's range over a run (the signals in the probe's order, which is the block's field order).
#[derive(Default)]
pub struct Ranges {
    pub signals: Vec<Seen>,
    /// clocks probed
    pub clocks: u64,
    /// what left the unit, in order (bit patterns)
    pub outputs: Vec<Vec<u64>>,
    path: Vec<String>,
    next: usize,
}

impl Ranges {
    fn value(a: &dyn Atom) -> Option<u64> {
        use rust_hdl::core::synth::VCDValue;
        match a.vcd() {
            VCDValue::Single(v) => Some((v == hdl_vcd::Value::V1) as u64),
            VCDValue::Vector(v) if v.len() <= 64 => {
                Some(v.iter().fold(0u64, |acc, b| acc << 1 | (*b == hdl_vcd::Value::V1) as u64))
            }
            _ => None,
        }
    }
}

impl Probe for Ranges {
    fn visit_start_scope(&mut self, name: &str, _node: &dyn Block) {
        self.path.push(name.to_string());
    }
    fn visit_end_scope(&mut self, _name: &str, _node: &dyn Block) {
        self.path.pop();
    }
    fn visit_start_namespace(&mut self, name: &str, _node: &dyn Block) {
        self.path.push(name.to_string());
    }
    fn visit_end_namespace(&mut self, _name: &str, _node: &dyn Block) {
        self.path.pop();
    }
    fn visit_atom(&mut self, name: &str, a: &dyn Atom) {
        let Some(v) = Ranges::value(a) else { return };
        let bits = a.bits();
        let s = if bits < 64 && bits > 0 && v >> (bits - 1) & 1 == 1 { v as i64 - (1i64 << bits) } else { v as i64 };
        if self.next == self.signals.len() {
            // the first clock: the signals in visiting order, named as the VCD names them
            let full = format!("{}.{name}", self.path.join("."));
            self.signals.push(Seen { name: full, bits, umin: v, umax: v, smin: s, smax: s });
        } else {
            let r = &mut self.signals[self.next];
            (r.umin, r.umax, r.smin, r.smax) = (r.umin.min(v), r.umax.max(v), r.smin.min(s), r.smax.max(s));
        }
        self.next += 1;
    }
}

/// The unit's vectors through its rust-hdl block, every signal probed every clock (the flush included: the last
/// vectors are still in the pipeline then, bubbles with zero inputs behind them).
pub fn seen<U: StreamUnit>(m: &UnitModel, inputs: &[Vec<i64>]) -> Ranges {
    seen_ticking::<U>(m, inputs, &|_| {})
}

/// `seen`, calling `tick` with the vectors done every 4,096.
pub fn seen_ticking<U: StreamUnit>(m: &UnitModel, inputs: &[Vec<i64>], tick: &dyn Fn(usize)) -> Ranges {
    let mut r = Runner::<U>::new();
    let mut ranges = Ranges::default();
    let zeros = vec![0u64; U::INPUTS.len()];
    let slots =
        inputs.iter().map(|v| Some(vectors::unit::to_patterns(v, m.inputs))).chain((0..U::LATENCY + 1).map(|_| None));
    for (k, s) in slots.enumerate() {
        if k % 4096 == 0 {
            tick(k.min(inputs.len()));
        }
        ranges.next = 0;
        let out = match &s {
            Some(v) => r.step_probed(true, v, Some(&mut ranges)),
            None => r.step_probed(false, &zeros, Some(&mut ranges)),
        };
        ranges.outputs.extend(out);
        ranges.clocks += 1;
    }
    ranges
}

/// How many vectors' outputs differ from the model's (a stream unit's model runs over the whole stream), and how
/// many outputs are missing: the evidence behind the steps `wraps` argues for, since the model does not wrap.
pub fn mismatches(m: &UnitModel, inputs: &[Vec<i64>], outputs: &[Vec<u64>]) -> usize {
    let want = m.run(inputs);
    let differ = want.iter().zip(outputs).filter(|(w, o)| vectors::unit::from_patterns(o, m.outputs) != **w).count();
    differ + want.len().abs_diff(outputs.len())
}

/// A step the proof finds may leave its target's declared range: the signal it writes (VCD name), the block that
/// owns the step and the signal's name there, what the step computes, and its entry in `wraps` if it is listed.
pub struct Site {
    pub name: String,
    pub owner: String,
    pub local: String,
    pub exact: (i128, i128),
    pub listed: Option<&'static wraps::Waived>,
}

/// Every such step of a block, from its proof.
pub fn sites(f: &Formats, proof: &bounds::Proof) -> Vec<Site> {
    let mut out: Vec<Site> = proof
        .wraps
        .iter()
        .map(|((module, name), &exact)| {
            // the step belongs to the block whose statement it is: a parent writing a child's port owns that write
            let owner = f.block_at(module).unwrap_or_else(|| String::from("?"));
            let rest = name.strip_prefix(&format!("{module}.")).unwrap_or(name);
            let local: Vec<&str> = rest.split('.').map(|s| s.split('$').next().unwrap_or(s)).collect();
            let local = local.join(".");
            let listed = wraps::find(&owner, &local);
            Site { name: name.clone(), owner, local, exact, listed }
        })
        .collect();
    out.sort_by(|a, b| a.name.cmp(&b.name));
    out
}

#[cfg(test)]
mod tests {

    #[test]
    fn a_macro_s_optional_groups_are_kept_where_the_invocation_names_them() {
        let src = "macro_rules! m { ($t:ident, $n:literal $(, gloss: $g:ident, $c:ident)? $(, filter: $f:ident)?) => { \
                   struct $t { a: U8, $($c: U8,)? $(pub $g: Gloss,)? $(pub $f: [Bilinear; 2],)? } }; }\n\
                   m!(A, 1);\nm!(B, 2, gloss: gl, conc);\nm!(C, 3, filter: filt);\nm!(D, 4, gloss: gl, conc, filter: filt);";
        let x = expand_local_macros(src);
        let squash = |t: &str| t.split_whitespace().collect::<Vec<_>>().join(" ");
        assert_eq!(x.len(), 4, "{x:?}");
        assert_eq!(squash(&x[0]), "struct A { a: U8, }");
        assert_eq!(squash(&x[1]), "struct B { a: U8, conc: U8, pub gl: Gloss, }");
        assert_eq!(squash(&x[2]), "struct C { a: U8, pub filt: [Bilinear; 2], }");
        assert_eq!(squash(&x[3]), "struct D { a: U8, conc: U8, pub gl: Gloss, pub filt: [Bilinear; 2], }");
    }

    use super::*;

    /// A macro defined in one file and invoked in another (re-exported by path) is expanded in the invoking file.
    #[test]
    fn a_macro_lent_by_another_file_is_expanded_where_it_is_invoked() {
        let defs = "macro_rules! w { ($t:ident $(, gloss: $g:ident)?) => { struct $t { a: U8, $(pub $g: Gloss,)? } }; }\npub(crate) use w;";
        let uses = "use crate::cartesian::wiring::w;\nw!(A);\nw!(B, gloss: gl);";
        let squash = |t: &str| t.split_whitespace().collect::<Vec<_>>().join(" ");
        let x: Vec<String> = expand_macros(defs, uses).iter().map(|t| squash(t)).collect();
        assert_eq!(x, ["struct A { a: U8, }", "struct B { a: U8, pub gl: Gloss, }"]);
        assert!(expand_local_macros(uses).is_empty());
    }

    #[test]
    fn types_parse_with_their_arguments() {
        assert_eq!(
            Ty::parse("[Delay<Sq1_10, { table_builder::LATENCY }>; 3]"),
            Some(Ty::Array(
                Box::new(Ty::Path(
                    "Delay".into(),
                    vec![Ty::Path("Sq1_10".into(), vec![]), Ty::Expr("table_builder::LATENCY".into())]
                )),
                "3".into()
            ))
        );
        assert_eq!(
            Ty::parse("rtl::palette::palette_pipeline::PalettePipeline<8, 9>").map(|t| t.text()),
            Some("PalettePipeline<8, 9>".into())
        );
        assert_eq!(Ty::parse("Signal<Local, Bits<16>>").map(|t| t.text()), Some("Signal<Local, Bits<16>>".into()));
    }

    #[test]
    fn bits_needed_counts_the_sign_once() {
        assert_eq!(bits_needed(true, -1024, 1023), 11);
        assert_eq!(bits_needed(true, -1024, 1024), 12);
        assert_eq!(bits_needed(true, -1025, 0), 12);
        assert_eq!(bits_needed(true, 0, 0), 1);
        assert_eq!(bits_needed(false, 0, 255), 8);
        assert_eq!(bits_needed(false, 0, 256), 9);
        assert_eq!(bits_needed(false, 0, 0), 1);
    }

    #[test]
    fn formats_follow_the_q_convention() {
        let a = HashMap::new();
        let q = |n: &str| Format::of(n, &a, 0).map(|f| (f.q(), f.bits));
        assert_eq!(q("Sq1_10"), Some(("sQ1.10".into(), 12)));
        assert_eq!(q("Uq0_10"), Some(("uQ0.10".into(), 10)));
        assert_eq!(q("U8"), Some(("u8".into(), 8)));
        assert_eq!(q("S11"), Some(("s11".into(), 11)));
    }

    #[test]
    fn the_stream_blocks_and_the_library_blocks_are_declared() {
        let (d, aliases) = declarations();
        let dot3 = &d["Dot3"];
        let names: Vec<&str> = dot3.fields.iter().map(|f| f.0.as_str()).collect();
        assert!(names.starts_with(&["clock", "valid_in", "valid_out", "n_x"]), "{names:?}");
        assert!(names.contains(&"s3_t") && names.contains(&"w_partial"));
        assert_eq!(d["PaletteLookup"].generics, ["A", "R"]);
        assert_eq!(d["Delay"].generics, ["T", "N"]);
        assert!(d.contains_key("DFF") && d.contains_key("RAM"));
        assert_eq!(aliases.get("Sq1_10").map(Ty::text), Some("Bits<12>".into()));
    }

    #[test]
    fn a_signal_path_resolves_through_blocks_arrays_and_generics() {
        let f = Formats::of::<rtl::palette_pipeline::PalettePipeline<12, 13>>();
        let q = |p: &str| f.format(p).map(|x| (x.name, x.bits, x.signed));
        assert_eq!(q("uut.idx"), Some(("Bits<12>".into(), 12, false)));
        assert_eq!(q("uut.lookup.ram.read_address"), Some(("Bits<13>".into(), 13, false)));
        assert_eq!(q("uut.builder.diffuse.s3_t$2.q"), Some(("Sq4_20".into(), 25, true)));
        assert_eq!(q("uut.builder.l_dly$1.line$3.d"), Some(("Sq1_10".into(), 12, true)));
        assert_eq!(q("uut.builder.conc"), Some(("U8".into(), 8, false)));
        assert_eq!(q("uut.clock"), None);
        assert_eq!(f.owner("uut.builder.diffuse.s3_t$2.q"), Some(("Dot3".into(), "s3_t.q".into())));
        assert_eq!(f.owner("uut.builder.l_dly$1.line$3.d"), Some(("Delay".into(), "line.d".into())));
        assert_eq!(f.owner("uut.lookup.ram.read_data"), Some(("PaletteLookup".into(), "ram.read_data".into())));
        assert_eq!(f.owner("uut.idx"), Some(("PalettePipeline".into(), "idx".into())));
        assert_eq!(f.block_at("uut.builder.diffuse").as_deref(), Some("Dot3"));
        assert_eq!(f.block_at("uut").as_deref(), Some("PalettePipeline"));
    }
}
