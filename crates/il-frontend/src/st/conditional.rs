//! Conditional compilation pragmas (CODESYS, TwinCAT): `{IF defined (X)}` ... `{ELSIF ...}` ...
//! `{ELSE}` ... `{END_IF}`, with `{define X}` / `{define X 'value'}` and `{undefine X}`.
//!
//! Input: an ST text (a `.st` file, a TwinCAT object's declaration and implementation) and the
//! pragmas its lexer found. Output: `None` when the text holds no conditional pragma; otherwise the
//! text with every conditional pragma, and every section whose condition is false, blanked (spaces
//! for each byte but line ends, so positions do not move), and the diagnostics: E1037 for a condition
//! ladderc cannot evaluate, E1038 for an `{ELSIF}`/`{ELSE}`/`{END_IF}` without its `{IF}` or an
//! `{IF}` never closed, a W1419 note the first time a condition asks for a name that nothing in the
//! text defines.
//!
//! Invariants: sections nest; in a section that is not compiled, nothing is evaluated and no define
//! changes; a condition that cannot be evaluated (E1037) compiles none of its sections, so that no
//! branch is chosen by guess. Defines are the text's own (`{define}` before the condition, in text
//! order), and a TwinCAT project's `<CompilerDefines>` ([`ProjectDefines`]); they are
//! case-insensitive, as IEC 61131-3 names are.
//!
//! The standard leaves pragmas to the implementation (IEC 61131-3 ed. 3, 6.2). Beckhoff documents
//! that from TwinCAT 3.1 build 4024 these pragmas are evaluated in declarations as in implementations
//! ("Conditional pragmas", TC3 PLC intro), which is how ladderc reads them everywhere: a variable
//! declared once in each branch (a variant's value) is declared once. Defines set by a project
//! variant (`.tsproj`) are not read: `defined (X)` of a name that neither the text nor the
//! project's properties define is FALSE, with the W1419 note saying so.
//!
//! SIMATIC AX writes the same sections `{::ifdef X}` ... `{::elseif Y}` ... `{::else}` ...
//! `{::endif}` (Siemens' ae-demo-rack sample), each condition a symbol the build defines: read as
//! `defined (X)`, so with no define the `{::else}` branch, or none, is compiled (round 32; before,
//! every branch was compiled and each pragma was W0300). The symbols of the project's `apax.yml`
//! (its `DEFINED_PREPROCESSOR_SYMBOLS` list, read by `ladderc::apax`) are project defines too
//! (round 33).

use super::lexer::Problem;
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use std::collections::{HashMap, HashSet};
use std::ops::Range;

thread_local! {
    /// The compiler defines of the project being read (upper-case name to value), set by
    /// [`ProjectDefines::set`]; empty otherwise.
    static PROJECT_DEFINES: std::cell::RefCell<HashMap<String, String>> = Default::default();
}

/// Holds the project's compiler defines (a TwinCAT `.plcproj`'s `<CompilerDefines>`) known to
/// every text read while it lives; the defines before it are back when it is dropped.
pub struct ProjectDefines(HashMap<String, String>);

impl ProjectDefines {
    /// Makes `defines` (name, value) known until the returned guard is dropped.
    pub fn set(defines: Vec<(String, String)>) -> ProjectDefines {
        let map = defines
            .into_iter()
            .map(|(n, v)| (n.to_ascii_lowercase(), v))
            .collect();
        ProjectDefines(PROJECT_DEFINES.with(|d| d.replace(map)))
    }
}

impl Drop for ProjectDefines {
    fn drop(&mut self) {
        let before = std::mem::take(&mut self.0);
        PROJECT_DEFINES.with(|d| d.replace(before));
    }
}

/// What a pragma's text asks, when it is a conditional-compilation directive.
enum Directive<'a> {
    If(Cond<'a>),
    Elsif(Cond<'a>),
    Else,
    EndIf,
    Define(&'a str),
    Undefine(&'a str),
}

/// The condition of an `{IF}` or `{ELSIF}`.
enum Cond<'a> {
    /// A CODESYS/TwinCAT expression (`defined (X) AND NOT defined (Y)`).
    Expr(&'a str),
    /// SIMATIC AX's `{::ifdef X}` / `{::elseif X}`: whether the symbol X is defined.
    Defined(&'a str),
}

/// Reads the directive of a pragma's full text (`{IF defined (X)}`), `None` for other pragmas.
fn directive(text: &str) -> Option<Directive<'_>> {
    let inner = text.strip_prefix('{')?.strip_suffix('}')?;
    if inner.starts_with('{') {
        return None; // `{{ C code }}`
    }
    // SIMATIC AX (Siemens' ae-demo-rack sample): `{::ifdef SYMBOL}` ... `{::elseif SYMBOL}` ...
    // `{::else}` ... `{::endif}`, each condition a preprocessor symbol the build defines (its
    // `apax.yml` lists them, project defines): defined or not, as `defined (SYMBOL)`
    if let Some(ax) = inner.trim_start().strip_prefix("::") {
        let ax = ax.trim();
        let end = ax
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(ax.len());
        let (word, rest) = ax.split_at(end);
        let rest = rest.trim();
        let symbol =
            !rest.is_empty() && rest.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        return Some(match word.to_ascii_lowercase().as_str() {
            "ifdef" if symbol => Directive::If(Cond::Defined(rest)),
            "elseif" if symbol => Directive::Elsif(Cond::Defined(rest)),
            "else" if rest.is_empty() => Directive::Else,
            "endif" if rest.is_empty() => Directive::EndIf,
            _ => return None,
        });
    }
    let inner = inner.trim();
    let word_end = inner
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(inner.len());
    let (word, rest) = inner.split_at(word_end);
    let rest = rest.trim();
    let word = word.to_ascii_uppercase();
    Some(match word.as_str() {
        "IF" => Directive::If(Cond::Expr(rest)),
        "ELSIF" => Directive::Elsif(Cond::Expr(rest)),
        "ELSE" if rest.is_empty() => Directive::Else,
        "END_IF" if rest.is_empty() => Directive::EndIf,
        "DEFINE" => Directive::Define(rest),
        "UNDEFINE" => Directive::Undefine(rest),
        _ => return None,
    })
}

/// One open `{IF}`: where it is, whether its enclosing section is compiled, whether one of its
/// branches was chosen already, whether the current branch is compiled, whether `{ELSE}` was seen.
struct Frame {
    at: Range<usize>,
    outer: bool,
    taken: bool,
    active: bool,
    seen_else: bool,
}

/// The state of one text's reading: its defines and the names already noted (W1419).
struct Reader {
    file: FileId,
    defines: HashMap<String, String>,
    noted: HashSet<String>,
    diags: Vec<Diagnostic>,
    /// The pragma whose condition is being evaluated.
    current: Range<usize>,
}

/// Blanks the sections that conditional pragmas leave out (see the module header); `None` when
/// `src` holds no conditional pragma.
pub(super) fn conditional_sections(
    file: FileId,
    src: &str,
    problems: &[Problem],
    diags: &mut Diagnostics,
) -> Option<String> {
    let pragmas: Vec<Range<usize>> = problems
        .iter()
        .filter_map(|p| match p {
            Problem::Pragma(r) => Some(r.clone()),
            _ => None,
        })
        .filter(|r| src.get(r.clone()).and_then(directive).is_some())
        .collect();
    if pragmas.is_empty() {
        return None;
    }
    let mut reader = Reader {
        file,
        defines: PROJECT_DEFINES.with(|d| d.borrow().clone()),
        noted: HashSet::new(),
        diags: Vec::new(),
        current: 0..0,
    };
    let mut stack: Vec<Frame> = Vec::new();
    let mut text = src.to_string();
    // the start of the section being left out, while one is
    let mut left_out_from: Option<usize> = None;
    let compiled = |stack: &[Frame]| stack.last().is_none_or(|f| f.outer && f.active);
    for r in pragmas {
        let was = compiled(&stack);
        let Some(d) = src.get(r.clone()).and_then(directive) else {
            continue;
        };
        match d {
            Directive::If(cond) => {
                let value = if was {
                    reader.condition(cond, &r)
                } else {
                    None
                };
                stack.push(Frame {
                    at: r.clone(),
                    outer: was,
                    taken: value != Some(false),
                    active: value == Some(true),
                    seen_else: false,
                });
            }
            Directive::Elsif(cond) => match stack.last_mut() {
                Some(f) if !f.seen_else => {
                    if f.outer && !f.taken {
                        let value = reader.condition(cond, &r);
                        f.taken = value != Some(false);
                        f.active = value == Some(true);
                    } else {
                        f.active = false;
                    }
                }
                _ => reader.unmatched(&r, "{ELSIF}"),
            },
            Directive::Else => match stack.last_mut() {
                Some(f) if !f.seen_else => {
                    f.active = f.outer && !f.taken;
                    f.taken = true;
                    f.seen_else = true;
                }
                _ => reader.unmatched(&r, "{ELSE}"),
            },
            Directive::EndIf => {
                if stack.pop().is_none() {
                    reader.unmatched(&r, "{END_IF}");
                }
            }
            Directive::Define(rest) if was => {
                let (name, value) = match rest.find(char::is_whitespace) {
                    Some(i) => (&rest[..i], rest[i..].trim()),
                    None => (rest, ""),
                };
                if !name.is_empty() {
                    let value = value.trim_matches('\'');
                    reader
                        .defines
                        .insert(name.to_ascii_lowercase(), value.to_string());
                }
            }
            Directive::Undefine(name) if was => {
                reader.defines.remove(&name.trim().to_ascii_lowercase());
            }
            Directive::Define(_) | Directive::Undefine(_) => {}
        }
        let now = compiled(&stack);
        // the section left out ends where this pragma starts; the pragma itself is blanked
        if let Some(from) = left_out_from.take() {
            super::file::blank(&mut text, from..r.start);
        }
        super::file::blank(&mut text, r.clone());
        if !now {
            left_out_from = Some(r.end);
        }
    }
    for f in &stack {
        reader.diags.push(
            Diagnostic::error(code::E1038, "`{IF}` without its `{END_IF}`")
                .at(Span::new(file, f.at.start, f.at.end))
                .with_primary_label("opened here")
                .with_hint("close the conditional section with `{END_IF}`; everything after this `{IF}` is read as if the section ended at the end of the text"),
        );
    }
    // an unclosed section that is not compiled (`left_out_from` still set): the rest is read, as
    // the E1038 hint says
    for d in reader.diags {
        diags.push(d);
    }
    Some(text)
}

impl Reader {
    fn span(&self, r: &Range<usize>) -> Span {
        Span::new(self.file, r.start, r.end)
    }

    fn unmatched(&mut self, r: &Range<usize>, what: &str) {
        self.diags.push(
            Diagnostic::error(code::E1038, format!("`{what}` without an open `{{IF}}`"))
                .at(self.span(r))
                .with_primary_label("no `{IF ...}` before this is still open")
                .with_hint("a conditional section is `{IF cond}` ... [`{ELSIF cond}` ...] [`{ELSE}` ...] `{END_IF}`; remove this pragma or add its `{IF}`"),
        );
    }

    /// The value of the condition `cond` of the pragma at `at`; `None` (after E1037) when it
    /// cannot be evaluated.
    fn condition(&mut self, cond: Cond<'_>, at: &Range<usize>) -> Option<bool> {
        let cond = match cond {
            Cond::Expr(e) => e,
            Cond::Defined(name) => return Some(self.defined_symbol(name, at)),
        };
        let toks = cond_tokens(cond);
        self.current = at.clone();
        let mut p = CondParser {
            toks: &toks,
            pos: 0,
            reader: self,
            unknown: None,
        };
        let v = p.or();
        let unknown = p.unknown.take();
        let complete = p.pos == toks.len();
        match (v, unknown) {
            (Some(v), None) if complete => Some(v),
            (_, why) => {
                let why = why.unwrap_or_else(|| match cond.trim() {
                    "" => "it has no condition".to_string(),
                    c => format!("`{c}` is not a condition ladderc reads"),
                });
                self.diags.push(
                    Diagnostic::error(
                        code::E1037,
                        format!("ladderc cannot evaluate this conditional pragma: {why}"),
                    )
                    .at(self.span(at))
                    .with_primary_label("condition not evaluated")
                    .with_hint("ladderc evaluates `defined (name)`, `hasvalue (name, 'value')`, TRUE, FALSE, NOT, AND, OR and parentheses over the text's own `{define}`s; none of this `{IF}`'s sections is compiled"),
                );
                None
            }
        }
    }

    /// SIMATIC AX's `{::ifdef name}`: W1419 the first time a name nothing defined is asked for.
    fn defined_symbol(&mut self, name: &str, at: &Range<usize>) -> bool {
        self.defined_or_noted(
            name,
            at,
            format!("`{name}` is not defined: its `{{::ifdef}}` / `{{::elseif}}` section is not compiled"),
            "ladderc reads the symbols listed under `DEFINED_PREPROCESSOR_SYMBOLS` in the project's apax.yml (give the project folder or its .st files) and the text's own `{define}`s; the `{::else}` section, if any, is compiled",
        )
    }

    /// `defined (name)`: W1419 the first time a name nothing defined is asked for.
    fn defined(&mut self, name: &str, at: &Range<usize>) -> bool {
        self.defined_or_noted(
            name,
            at,
            format!("`{name}` is not defined at this point of the text: `defined ({name})` is FALSE"),
            "ladderc reads the text's own `{define ...}` pragmas and a TwinCAT project's `<CompilerDefines>`, not a variant's defines; add `{define NAME}` before the `{IF}`, or NAME to the project's compiler defines, to compile the other branch",
        )
    }

    /// Whether `name` is defined; the first time one is not, W1419 with `message` and `hint`.
    fn defined_or_noted(
        &mut self,
        name: &str,
        at: &Range<usize>,
        message: String,
        hint: &str,
    ) -> bool {
        let key = name.to_ascii_lowercase();
        if self.defines.contains_key(&key) {
            return true;
        }
        if self.noted.insert(key) {
            self.diags.push(
                Diagnostic::new(code::W1419, Severity::Note, message)
                    .at(self.span(at))
                    .with_hint(hint),
            );
        }
        false
    }
}

/// A token of a condition: a word, a quoted string or one punctuation character.
#[derive(Debug, Clone, PartialEq)]
enum CondTok {
    Word(String),
    Str(String),
    Punct(char),
}

fn cond_tokens(s: &str) -> Vec<CondTok> {
    let mut out = Vec::new();
    let mut chars = s.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        if c.is_whitespace() {
            continue;
        }
        if c.is_ascii_alphanumeric() || c == '_' {
            let mut end = i + c.len_utf8();
            while let Some(&(j, d)) = chars.peek() {
                if d.is_ascii_alphanumeric() || d == '_' {
                    end = j + d.len_utf8();
                    chars.next();
                } else {
                    break;
                }
            }
            out.push(CondTok::Word(s[i..end].to_string()));
        } else if c == '\'' || c == '"' {
            let mut value = String::new();
            for (_, d) in chars.by_ref() {
                if d == c {
                    break;
                }
                value.push(d);
            }
            out.push(CondTok::Str(value));
        } else {
            out.push(CondTok::Punct(c));
        }
    }
    out
}

/// Recursive descent over a condition: `or := and {OR and}`, `and := not {AND not}`,
/// `not := NOT not | primary`, `primary := ( or ) | defined ( name ) | hasvalue ( name , 'v' ) |
/// TRUE | FALSE`. `unknown` says why a condition cannot be evaluated.
struct CondParser<'t, 'r> {
    toks: &'t [CondTok],
    pos: usize,
    reader: &'r mut Reader,
    unknown: Option<String>,
}

impl CondParser<'_, '_> {
    fn peek_word(&self, w: &str) -> bool {
        matches!(self.toks.get(self.pos), Some(CondTok::Word(x)) if x.eq_ignore_ascii_case(w))
    }

    fn punct(&mut self, c: char) -> bool {
        if self.toks.get(self.pos) == Some(&CondTok::Punct(c)) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn or(&mut self) -> Option<bool> {
        let mut v = self.and()?;
        while self.peek_word("OR") {
            self.pos += 1;
            let w = self.and()?;
            v = v || w;
        }
        Some(v)
    }

    fn and(&mut self) -> Option<bool> {
        let mut v = self.not()?;
        while self.peek_word("AND") {
            self.pos += 1;
            let w = self.not()?;
            v = v && w;
        }
        Some(v)
    }

    fn not(&mut self) -> Option<bool> {
        if self.peek_word("NOT") {
            self.pos += 1;
            return self.not().map(|v| !v);
        }
        self.primary()
    }

    fn primary(&mut self) -> Option<bool> {
        if self.punct('(') {
            let v = self.or()?;
            return self.punct(')').then_some(v);
        }
        let Some(CondTok::Word(w)) = self.toks.get(self.pos).cloned() else {
            return None;
        };
        self.pos += 1;
        let lw = w.to_ascii_lowercase();
        match lw.as_str() {
            "true" => Some(true),
            "false" => Some(false),
            "defined" | "hasvalue" => {
                if !self.punct('(') {
                    return None;
                }
                let Some(CondTok::Word(name)) = self.toks.get(self.pos).cloned() else {
                    return None;
                };
                self.pos += 1;
                if self.toks.get(self.pos) == Some(&CondTok::Punct(':')) {
                    // `defined (variable: x)`, `defined (type: T)`, `defined (pou: P)`: about the
                    // whole project, which one text does not know
                    self.unknown = Some(format!("`{lw} ({name}: ...)` asks about the project"));
                    return None;
                }
                let v = if lw == "defined" {
                    let whole = self.reader.current.clone();
                    self.reader.defined(&name, &whole)
                } else {
                    if !self.punct(',') {
                        return None;
                    }
                    let Some(CondTok::Str(value)) = self.toks.get(self.pos).cloned() else {
                        return None;
                    };
                    self.pos += 1;
                    self.reader
                        .defines
                        .get(&name.to_ascii_lowercase())
                        .is_some_and(|v| *v == value)
                };
                self.punct(')').then_some(v)
            }
            _ => {
                self.unknown = Some(format!("the operator or operand `{w}`"));
                None
            }
        }
    }
}
