//! Vendor syntax in `.st` text, handled before the parser: library-qualified names (`Standard.TON`;
//! a provided library's qualifier is dropped, any other is one E1032 per library; references and
//! pointers are read by [`super::refs`]).
//!
//! Input: the file's text and tokens. Output: the text with qualifiers blanked
//! (positions unchanged) and the diagnostics. Invariant: every span stays where the user wrote it.

use super::file::*;
use super::lexer::{Tok, Token};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics};

/// The library namespaces whose blocks and functions ladderc provides, upper case: CODESYS's and
/// TwinCAT's standard libraries (`Standard.TON`, `Tc2_Standard.CTU`), their utility libraries (a block
/// ladderc does not have is then an unknown type or function, named at its use), and their PLCopen
/// motion libraries (`SM3_Basic.MC_MoveAbsolute`, `Tc2_MC2.MC_Power`).
pub const PROVIDED_LIBRARIES: &[&str] = &[
    "STANDARD",
    "TC2_STANDARD",
    "IEC",
    "UTIL",
    "TC2_UTILITIES",
    "SM3_BASIC",
    "TC2_MC2",
];

/// Libraries of which ladderc provides some names only, upper case: their qualifier is dropped
/// before those names (`Tc2_System.MEMMOVE(...)`), and before any other it is E1032 naming the
/// library (`Tc2_System.ADSREAD`: its ADS and file blocks are not ladderc's).
pub const PARTLY_PROVIDED_LIBRARIES: &[(&str, &[&str])] = &[
    ("TC2_SYSTEM", &["MEMCPY", "MEMMOVE", "MEMSET", "MEMCMP"]),
    // the type of `__CATCH(exc)`'s variable (`__TRY`, W1427), read as a UDINT
    ("__SYSTEM", &["EXCEPTIONCODE"]),
];

thread_local! {
    /// The PROGRAM names of the project's files (upper case), set by [`set_project_programs`]:
    /// `PRG.M(x)` in a body calls a method or action of a program of another file (a TwinCAT
    /// project has one POU per file), not a function of a library `PRG`.
    static PROJECT_PROGRAMS: std::cell::RefCell<std::collections::HashSet<String>> =
        Default::default();

    /// The namespaces of the user libraries given as source projects (upper case, `--lib`), set
    /// by [`UserLibraries::set`]: their qualifier is dropped as a provided library's is.
    static USER_LIBRARIES: std::cell::RefCell<std::collections::HashSet<String>> =
        Default::default();

    /// The names other files of the project declare (upper case), set by
    /// [`with_other_files_names`]; empty otherwise.
    static OTHER_FILES_NAMES: std::cell::RefCell<std::collections::HashSet<String>> =
        Default::default();

    /// The base each function block or class of the project's files EXTENDS (upper case, derived
    /// to base), set by [`set_project_bases`]: `_abs.M()` in a block names a variable of any of
    /// its bases, which other files may declare (a chain `C EXTENDS B`, `B EXTENDS A` over three
    /// files: before round 28 only the direct base was looked up, E1032 for `A`'s variables).
    static PROJECT_BASES: std::cell::RefCell<std::collections::HashMap<String, String>> =
        Default::default();

    /// The `NAMESPACE Name ... END_NAMESPACE` names of every file of the project (upper case,
    /// dotted parts joined by `.`), set by [`set_project_namespaces`]: files given together are
    /// one project, and a namespace is not tied to a file (IEC 61131-3 ed. 3, 6.9), so
    /// `Plant.Util.Twice(21)` in one file names the function of another file's `NAMESPACE
    /// Plant.Util`.
    static PROJECT_NAMESPACES: std::cell::RefCell<std::collections::HashSet<String>> =
        Default::default();
}

/// Sets the namespaces that `library_qualifiers` takes as the project's (every file's, from
/// [`namespace_names`]); returns the ones set before, to put back when the project is read.
pub fn set_project_namespaces(
    names: std::collections::HashSet<String>,
) -> std::collections::HashSet<String> {
    PROJECT_NAMESPACES.with(|p| p.replace(names))
}

/// Whether `name` (upper case, dotted) is a namespace some file of the project declares.
pub(super) fn is_project_namespace(name: &str) -> bool {
    PROJECT_NAMESPACES.with(|p| p.borrow().contains(name))
}

/// The names of the `NAMESPACE Name ... END_NAMESPACE` blocks of `text` (an `.st` file), upper
/// case, dotted parts joined by `.`: a scan before any file is parsed.
pub fn namespace_names(text: &str) -> Vec<String> {
    if !text
        .as_bytes()
        .windows(13)
        .any(|w| w.eq_ignore_ascii_case(b"END_NAMESPACE"))
    {
        return Vec::new();
    }
    let toks = super::lexer::lex(text).0;
    namespace_blocks(text, &toks, &mut None)
}

/// The namespaces of the user libraries read with the project (`Struckig` of `Struckig.Otg`),
/// known to `library_qualifiers` while the guard lives: `UserLibraries::set(names)`.
pub struct UserLibraries {
    before: std::collections::HashSet<String>,
}

impl UserLibraries {
    /// Makes `namespaces` (upper case) known until the guard is dropped (then the ones known
    /// before are again).
    pub fn set(namespaces: impl IntoIterator<Item = String>) -> UserLibraries {
        let names = namespaces.into_iter().collect();
        UserLibraries {
            before: USER_LIBRARIES.with(|u| u.replace(names)),
        }
    }
}

impl Drop for UserLibraries {
    fn drop(&mut self) {
        let before = std::mem::take(&mut self.before);
        USER_LIBRARIES.with(|u| u.replace(before));
    }
}

/// Sets the PROGRAM names that `library_qualifiers` takes as declared (every file of the
/// project's); returns the names set before, to put back when the project is read.
pub fn set_project_programs(
    names: std::collections::HashSet<String>,
) -> std::collections::HashSet<String> {
    PROJECT_PROGRAMS.with(|p| p.replace(names))
}

/// Sets the bases (derived to base, upper case, [`extends_pairs`] of every file of the project)
/// that `library_qualifiers` follows; returns those set before, to put back when the project is
/// read.
pub fn set_project_bases(
    bases: std::collections::HashMap<String, String>,
) -> std::collections::HashMap<String, String> {
    PROJECT_BASES.with(|p| p.replace(bases))
}

/// Each `FUNCTION_BLOCK Name EXTENDS Base` and `CLASS Name EXTENDS Base` of `text` (an `.st` file or
/// a TwinCAT object's XML; `FINAL`, `ABSTRACT` and an access word may stand before the name, a
/// qualified base counts by its last part), upper case: a scan of the raw text, before any file
/// is parsed.
pub fn extends_pairs(text: &str) -> Vec<(String, String)> {
    let b = text.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    // the words of the text (a dotted name as one: `Lib.Base`)
    let mut words: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if !is_word(b[i]) {
            i += 1;
            continue;
        }
        let start = i;
        while i < b.len()
            && (is_word(b[i]) || (b[i] == b'.' && b.get(i + 1).is_some_and(|&c| is_word(c))))
        {
            i += 1;
        }
        words.push(&text[start..i]);
    }
    let mut out = Vec::new();
    for k in 1..words.len().saturating_sub(1) {
        if !words[k].eq_ignore_ascii_case("EXTENDS") {
            continue;
        }
        let opens = words[..k - 1].iter().rev().take(4).find(|w| {
            !["FINAL", "ABSTRACT", "PUBLIC", "INTERNAL"]
                .iter()
                .any(|m| w.eq_ignore_ascii_case(m))
        });
        if !opens.is_some_and(|w| {
            w.eq_ignore_ascii_case("FUNCTION_BLOCK") || w.eq_ignore_ascii_case("CLASS")
        }) {
            continue;
        }
        let base = words[k + 1].rsplit('.').next().unwrap_or(words[k + 1]);
        let name = words[k - 1].rsplit('.').next().unwrap_or(words[k - 1]);
        out.push((name.to_ascii_uppercase(), base.to_ascii_uppercase()));
    }
    out
}

/// The names after the word `PROGRAM` in `text` (an `.st` file or a TwinCAT object's XML), upper
/// case: a scan of the raw text, before any file is parsed.
pub fn program_names(text: &str) -> Vec<String> {
    let b = text.as_bytes();
    let word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut out = Vec::new();
    let mut i = 0;
    while i + 7 <= b.len() {
        let keyword = b[i..i + 7].eq_ignore_ascii_case(b"PROGRAM")
            && (i == 0 || !word(b[i - 1]))
            && b.get(i + 7).is_some_and(|c| c.is_ascii_whitespace());
        if !keyword {
            i += 1;
            continue;
        }
        let mut j = i + 7;
        while b.get(j).is_some_and(|c| c.is_ascii_whitespace()) {
            j += 1;
        }
        let start = j;
        while b.get(j).is_some_and(|&c| word(c)) {
            j += 1;
        }
        if j > start {
            out.push(text[start..j].to_ascii_uppercase());
        }
        i = j;
    }
    out
}

/// Runs `parse` with `names` (upper case) known as names the project's other files declare: a
/// qualifier `X.` among them is not a library (`GVL.fbTimer(...)` with the list `GVL` in another
/// file, a CODESYS object exported as `GVL (GVL).st`).
pub fn with_other_files_names<R>(
    names: std::collections::HashSet<String>,
    parse: impl FnOnce() -> R,
) -> R {
    let before = OTHER_FILES_NAMES.with(|c| c.replace(names));
    let result = parse();
    OTHER_FILES_NAMES.with(|c| c.replace(before));
    result
}

/// The names `unit` declares for the project's other files (upper case): its POUs, types, global
/// variables, named global lists and configurations; and each POU's variables as `POU.VAR` (a
/// B&R block declared in a `.fun` file and implemented in a `.st` file: `ax.Delay(...)` in the
/// body calls the member of the block's variable `ax`, no library).
pub fn offered_names(unit: &crate::ast::CompilationUnit) -> impl Iterator<Item = String> + '_ {
    use crate::ast::LibraryElement;
    unit.items.iter().flat_map(|item| -> Vec<String> {
        match item {
            LibraryElement::Pou(p) => std::iter::once(p.name.key())
                .chain(p.var_blocks.iter().flat_map(|b| {
                    b.vars
                        .iter()
                        .map(|v| format!("{}.{}", p.name.key(), v.name.key()))
                }))
                .collect(),
            LibraryElement::DataTypes(types) => types.iter().map(|t| t.name.key()).collect(),
            LibraryElement::GlobalVars(b) => b
                .name
                .iter()
                .map(|n| n.key())
                .chain(b.vars.iter().map(|v| v.name.key()))
                .collect(),
            LibraryElement::Configuration(c) => std::iter::once(c.name.key())
                .chain(
                    c.globals
                        .iter()
                        .flat_map(|b| b.vars.iter().map(|v| v.name.key())),
                )
                .collect(),
            LibraryElement::Action(_) => Vec::new(),
        }
    })
}

/// The names (upper case, dotted parts joined by `.`) of the file's `NAMESPACE Name ...
/// END_NAMESPACE` blocks, whose words
/// (`NAMESPACE Name`, `NAMESPACE INTERNAL Name`, `END_NAMESPACE` and a `;` after it) are blanked in
/// `text`. A `NAMESPACE` with no `END_NAMESPACE` after it is left alone (a name of the program).
fn namespace_blocks(src: &str, toks: &[Token], text: &mut Option<String>) -> Vec<String> {
    let mut names = Vec::new();
    let mut open = 0usize;
    for (k, t) in toks.iter().enumerate() {
        if is_word(src, t, "NAMESPACE")
            && toks[k + 1..]
                .iter()
                .any(|e| is_word(src, e, "END_NAMESPACE"))
        {
            let mut j = k + 1;
            if toks.get(j).is_some_and(|n| is_word(src, n, "INTERNAL")) {
                j += 1;
            }
            if !toks.get(j).is_some_and(|n| n.tok == Tok::Ident) {
                continue;
            }
            // `NAMESPACE A.B`: `A.B.Name` names what it declares
            let mut last = j;
            while toks.get(last + 1).is_some_and(|d| d.tok == Tok::Dot)
                && toks.get(last + 2).is_some_and(|n| n.tok == Tok::Ident)
            {
                last += 2;
            }
            names.push(
                (j..=last)
                    .step_by(2)
                    .map(|p| word(src, &toks[p]).to_ascii_uppercase())
                    .collect::<Vec<_>>()
                    .join("."),
            );
            blank(
                text.get_or_insert_with(|| src.to_string()),
                t.range.start..toks[last].range.end,
            );
            open += 1;
        } else if is_word(src, t, "END_NAMESPACE") && open > 0 {
            open -= 1;
            let end = match toks.get(k + 1) {
                Some(semi) if semi.tok == Tok::Semi => semi.range.end,
                _ => t.range.end,
            };
            blank(
                text.get_or_insert_with(|| src.to_string()),
                t.range.start..end,
            );
        }
    }
    names
}

/// Whether `base` (upper case; empty: none) or one of the bases it extends in turn
/// ([`PROJECT_BASES`]) declares variable `var` in one of the project's files (`BASE.VAR` among
/// `names`), or, with `missing_base_members` (a body, not a declaration's type), is a base no file
/// declares (any variable may be its).
fn in_bases(
    base: &str,
    var: &str,
    names: &std::collections::HashSet<String>,
    declared: &std::collections::HashSet<String>,
    missing_base_members: bool,
) -> bool {
    PROJECT_BASES.with(|p| {
        let p = p.borrow();
        let mut b = base.to_string();
        // (a chain is finite: a cycle, E0331, is cut after as many steps as there are blocks)
        for _ in 0..=p.len() {
            if b.is_empty() {
                return false;
            }
            if names.contains(&format!("{b}.{var}")) {
                return true;
            }
            // a base that no file of the project declares (a library's block, E0330 at the
            // EXTENDS): `_logger.M()` may name any of its variables, and E0330 is the one cause
            // (known once the other files' names are, `names` not empty: the file's parse again)
            if missing_base_members
                && !names.is_empty()
                && !names.contains(&b)
                && !declared.contains(&b)
            {
                return true;
            }
            match p.get(&b) {
                Some(next) => b = next.clone(),
                None => return false,
            }
        }
        false
    })
}

/// CODESYS and TwinCAT qualify a library's names with the library's namespace (`t : Standard.TON;`,
/// `x := Util.F(1);`). A qualifier naming a library ladderc provides ([`PROVIDED_LIBRARIES`]) is
/// dropped (blanked: positions stay). Any other qualifier where it can only name a library (a type
/// after `:` or `OF` in a VAR block or a TYPE declaration, a call `Lib.F(...)` or an enumeration's
/// value `Lib.E.V` in a body) whose name is no variable, POU or
/// type of the file is E1032, once per library (an error of the parse stage: the checks that would
/// report each use as an unknown type or function do not run), and its uses are renamed `__...`.
/// `None`: nothing to change.
pub(super) fn library_qualifiers(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let ident = |t: &Token| matches!(t.tok, Tok::Ident);
    // names declared in the file (`x :`, `a, b :`, `TYPE T :`, POU names): not libraries
    let mut declared = std::collections::HashSet::new();
    for (k, t) in toks.iter().enumerate() {
        if !ident(t) {
            continue;
        }
        let next = toks.get(k + 1).map(|n| &n.tok);
        let prev = k
            .checked_sub(1)
            .map(|p| word(src, &toks[p]).to_ascii_uppercase());
        if matches!(next, Some(Tok::Colon | Tok::Comma))
            || matches!(
                prev.as_deref(),
                Some("PROGRAM" | "FUNCTION" | "FUNCTION_BLOCK" | "CONFIGURATION" | "RESOURCE")
            )
        {
            declared.insert(word(src, t).to_ascii_uppercase());
        }
    }
    let mut text: Option<String> = None;
    // edition 3's `NAMESPACE Lib ... END_NAMESPACE` (6.9): the words blanked, so the POUs and
    // types inside are the file's, and `Lib.Name` names them as a provided library's name does
    let mut namespaces = namespace_blocks(src, toks, &mut text);
    // and those of the project's other files (one project: a namespace spans its files)
    PROJECT_NAMESPACES.with(|p| {
        for n in p.borrow().iter() {
            if !namespaces.contains(n) {
                namespaces.push(n.clone());
            }
        }
    });
    // the dotted ones by their parts (`Factory.Motion.Speed`)
    let dotted: Vec<Vec<&str>> = namespaces
        .iter()
        .filter(|n| n.contains('.'))
        .map(|n| n.split('.').collect())
        .collect();
    let mut reported = std::collections::HashSet::new();
    let mut in_decl = false;
    // the POU the token is in (`POU.VAR` among the other files' names: a variable its
    // declaration in another file gives it)
    let mut pou = String::new();
    // the base it EXTENDS (`CLASS EncA EXTENDS BaseEnc`): `_abs.M()` in its methods names a
    // variable the base declares, maybe in another file (`BASE.VAR` among the other files' names)
    let mut base = String::new();
    // the namespaces open at the token (upper case, dotted)
    let mut open_ns: Vec<String> = Vec::new();
    for (k, t) in toks.iter().enumerate() {
        let w = word(src, t).to_ascii_uppercase();
        if w == "NAMESPACE" && matches!(t.tok, Tok::Ident | Tok::Kw(_)) {
            let mut parts = Vec::new();
            let mut j = k + 1;
            if toks.get(j).is_some_and(|x| is_word(src, x, "INTERNAL")) {
                j += 1;
            }
            while let Some(x) = toks.get(j).filter(|x| ident(x)) {
                parts.push(word(src, x).to_ascii_uppercase());
                if toks.get(j + 1).is_some_and(|d| d.tok == Tok::Dot) {
                    j += 2;
                } else {
                    break;
                }
            }
            if !parts.is_empty() {
                open_ns.push(parts.join("."));
            }
        } else if w == "END_NAMESPACE" {
            open_ns.pop();
        }
        if matches!(
            w.as_str(),
            "PROGRAM" | "FUNCTION" | "FUNCTION_BLOCK" | "CLASS"
        ) && toks.get(k + 1).is_some_and(ident)
        {
            pou = word(src, &toks[k + 1]).to_ascii_uppercase();
            base.clear();
            // `CLASS [FINAL|ABSTRACT] Name`: the name is the last word before EXTENDS
            if let Some(e) = toks[k + 1..]
                .iter()
                .take(4)
                .position(|x| is_word(src, x, "EXTENDS"))
            {
                let at = k + 1 + e;
                if let Some(b) = toks.get(at + 1).filter(|b| ident(b)) {
                    base = word(src, b).to_ascii_uppercase();
                }
                if let Some(n) = toks.get(at - 1).filter(|n| ident(n)) {
                    pou = word(src, n).to_ascii_uppercase();
                }
            }
        }
        if matches!(t.tok, Tok::Kw(_) | Tok::Ident) {
            // a type is named after `:` in VAR blocks and in TYPE declarations (a STRUCT's
            // fields, `TYPE T : Lib.U; END_TYPE`)
            if is_var_keyword(&w) || w == "TYPE" {
                in_decl = true;
            } else if w == "END_VAR" || w == "END_TYPE" {
                in_decl = false;
            }
        }
        let (Some(dot), Some(member)) = (toks.get(k + 1), toks.get(k + 2)) else {
            continue;
        };
        // `Kinds.Mode#Fill` (SIMATIC AX): an enumeration's typed literal qualified by its
        // namespace (IEC 61131-3 ed. 3, 6.9): the namespace is blanked below as before a name
        let prefixed = member.tok == Tok::TypePrefix;
        if !ident(t)
            || dot.tok != Tok::Dot
            || !(ident(member) || prefixed)
            // `THIS.M(...)`: edition 3's call of the block's own method (`parser::statements_in`), `SUPER.M(...)` its base's (`inherit`)
            || w == "THIS"
            || w == "SUPER"
            || declared.contains(&w)
            || PROJECT_PROGRAMS.with(|p| p.borrow().contains(&w))
            || OTHER_FILES_NAMES.with(|o| {
                let o = o.borrow();
                o.contains(&w)
                    || (!pou.is_empty() && o.contains(&format!("{pou}.{w}")))
                    // (a missing base's members are no names of a declaration's type:
                    // `p : Resi.ParameterSet` with `EXTENDS Resi.Base` missing is the library)
                    || in_bases(&base, &w, &o, &declared, !in_decl)
            })
        {
            continue;
        }
        let prev = k.checked_sub(1).map(|p| &toks[p]);
        if prev.is_some_and(|p| p.tok == Tok::Dot) {
            continue;
        }
        // `Factory.Motion.Speed` of `NAMESPACE Factory.Motion`: the whole chain blanked; also
        // named from inside an enclosing namespace (`Types.BeltData` in `NAMESPACE Plant.Line`
        // for `NAMESPACE Plant.Line.Types`: IEC 61131-3 ed. 3, 6.9, names are looked up in the
        // enclosing namespaces outward), the chain's tail after that namespace
        let mut tails = dotted.iter().flat_map(|parts| {
            (0..parts.len()).filter_map(|i| {
                let head = parts[..i].join(".");
                (i == 0
                    || open_ns
                        .iter()
                        .any(|o| o == &head || o.starts_with(&format!("{head}."))))
                .then(|| &parts[i..])
            })
        });
        if let Some(end) = tails.find_map(|parts| {
            let matches = parts.iter().enumerate().all(|(n, part)| {
                toks.get(k + 2 * n)
                    .is_some_and(|t| ident(t) && word(src, t).eq_ignore_ascii_case(part))
                    && toks.get(k + 2 * n + 1).is_some_and(|d| d.tok == Tok::Dot)
            });
            let member = toks
                .get(k + 2 * parts.len())
                .is_some_and(|m| ident(m) || m.tok == Tok::TypePrefix);
            (matches && member).then(|| toks[k + 2 * parts.len() - 1].range.end)
        }) {
            blank(
                text.get_or_insert_with(|| src.to_string()),
                t.range.start..end,
            );
            continue;
        }
        if prefixed && !namespaces.contains(&w) {
            continue;
        }
        let text = text.get_or_insert_with(|| src.to_string());
        let member_name = word(src, member).to_ascii_uppercase();
        let provided = namespaces.contains(&w)
            || PROVIDED_LIBRARIES.contains(&w.as_str())
            || USER_LIBRARIES.with(|u| u.borrow().contains(&w))
            || PARTLY_PROVIDED_LIBRARIES
                .iter()
                .any(|(lib, names)| *lib == w && names.contains(&member_name.as_str()));
        if provided {
            blank(text, t.range.start..dot.range.end);
            continue;
        }
        // `Lib.Sub.Name` (`SysFile.SysTypes.RTS_IEC_HANDLE`): the last token of the chain
        let mut last = k + 2;
        while toks.get(last + 1).is_some_and(|d| d.tok == Tok::Dot)
            && toks.get(last + 2).is_some_and(ident)
        {
            last += 2;
        }
        // a result type: `METHOD PUBLIC Close : Lib.T;`, `FUNCTION F : Lib.T`
        let header_result = prev.is_some_and(|p| p.tok == Tok::Colon)
            && toks[..k]
                .iter()
                .rev()
                .skip(1)
                .take(6)
                .take_while(|b| b.tok != Tok::Semi)
                .any(|b| {
                    let w = word(src, b);
                    ["METHOD", "FUNCTION", "PROPERTY"]
                        .iter()
                        .any(|h| w.eq_ignore_ascii_case(h))
                });
        let type_position = header_result
            || in_decl
                && prev.is_some_and(|p| {
                    p.tok == Tok::Colon || word(src, p).eq_ignore_ascii_case("OF")
                });
        let call_position = !in_decl && toks.get(last + 1).is_some_and(|n| n.tok == Tok::LParen);
        // `Tc2_System.E_HRESULTAdsErr.INVALIDPARM` in a body: a library's enumeration value,
        // `<namespace>.<enumeration>.<value>` (Beckhoff Infosys, TC3 PLC, "Library namespace"),
        // its qualifier no variable of the file nor of the project's other files (those are
        // known when the file is parsed again): the library is the cause, as for its types
        // (not a kind after `:`, SIMATIC AX's `TASK Cyclic : Siemens.Simatic.S71500.Tasks.
        // ProgramCycle`, E1048's; nor a `USING`/`NAMESPACE` name)
        let value_position = !in_decl
            && last >= k + 4
            // (CODESYS's `__SYSTEM.TYPE_CLASS.TYPE_INT`: read where ANY inputs are)
            && w != "__SYSTEM"
            && !prev.is_some_and(|p| {
                p.tok == Tok::Colon
                    || ["USING", "NAMESPACE"]
                        .iter()
                        .any(|h| word(src, p).eq_ignore_ascii_case(h))
            });
        if !(type_position || call_position || value_position) {
            continue;
        }
        let name = word(src, t);
        if reported.insert(w.clone()) {
            diags.push(
                Diagnostic::error(
                    code::E1032,
                    format!("`{name}` is neither a variable nor a library ladderc provides"),
                )
                .at(Span::new(file, t.range.start, t.range.end))
                .with_primary_label("library qualifier")
                .with_hint(format!(
                    "ladderc provides the standard and PLCopen blocks of Standard, Util, Tc2_Standard, SM3_Basic and Tc2_MC2 (and Tc2_System's MEMCPY, MEMMOVE, MEMSET, MEMCMP); `{}` comes from another library: give its source project with --lib, or add its POUs and types to the project",
                    // (a value, `Lib.E_Enum.VALUE`: its enumeration with it)
                    if value_position && !type_position && !call_position {
                        toks[k + 2..=last].iter().map(|x| word(src, x)).collect::<String>()
                    } else {
                        word(src, &toks[last]).to_string()
                    }
                )),
            );
        }
        // `Lib.Name` -> `__b_Name` (same length; sema reports nothing more about it)
        let mut bytes = std::mem::take(text).into_bytes();
        bytes[t.range.start] = b'_';
        if t.range.len() > 1 {
            bytes[t.range.start + 1] = b'_';
        }
        bytes[dot.range.start] = b'_';
        for d in (k + 3..last).step_by(2) {
            bytes[toks[d].range.start] = b'_';
        }
        *text = String::from_utf8(bytes).unwrap_or_default();
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bases of a project's blocks and classes, read from raw text (ST, a `.TcPOU`'s XML):
    /// modifiers before the name and a qualified base are read; an INTERFACE's and a STRUCT's
    /// EXTENDS are not a block's.
    #[test]
    fn extends_pairs_are_read_from_raw_text() {
        let text = "CLASS FINAL Enc EXTENDS Lib.BaseEnc\nEND_CLASS\n\
                    <Declaration><![CDATA[FUNCTION_BLOCK FB_C EXTENDS FB_B IMPLEMENTS I_X\n]]>\n\
                    INTERFACE I_B EXTENDS I_A END_INTERFACE\n\
                    TYPE ST_B EXTENDS ST_A : STRUCT x : INT; END_STRUCT END_TYPE\n";
        assert_eq!(
            extends_pairs(text),
            [
                ("ENC".to_string(), "BASEENC".to_string()),
                ("FB_C".to_string(), "FB_B".to_string()),
            ]
        );
    }
}
