//! Blocks with generic constants (`VAR_GENERIC CONSTANT`, TwinCAT 3.1.4026 and CODESYS), one
//! block of its own for each set of values the project's instances give.
//!
//! Beckhoff Infosys, TC3 PLC "Generic constant variables - VAR_GENERIC CONSTANT", and the CODESYS
//! online help of the same name: a function block declares `VAR_GENERIC CONSTANT N : UDINT := 4;
//! END_VAR` (integer types, any number of constants, the initial value "only needed for compile
//! checks"); an instance gives the values in angle brackets after the block's name: a literal
//! (`FB_Buf<10>`), a parenthesised constant expression (`FB_Buf<(2 * C)>`), several values
//! separated by commas in the order of the declarations (`FB_Pou<100, 1000>`), or by name
//! (`FB_Pou<(N := 12)>`, CODESYS compiler error C0587 names an unknown one). Each instance is a
//! block of its own size, as the values bound its arrays, so C needs one block per set of values.
//!
//! Input: the texts of the files that declare such blocks ([`generic_blocks`]), and the parsed
//! units whose declarations name `FB_X<...>` (written there by `super::generic_constants`).
//! Output ([`specialise_instances`]): each such type renamed to the block of its values,
//! `FB_Buf__10` (`FB_Buf__10_1000` for two values, `m` for a minus: `FB_Buf__m1`), or to the block
//! itself when the values are its initial values (an instance without `<...>` has them too); the
//! list of the blocks to build: the caller parses the block's file again, as a file of its own,
//! within [`with_instance_values`], so that the block's generic constants take the instance's
//! values (in the bounds they give and as their initial values: `instance_value`, which the
//! declarations' parser asks), and renames the block.
//! Invariants: no panics on input; an instance's value that is not an integer constant expression,
//! a value too many, a name the block does not declare, or `<...>` on a block without generic
//! constants is one located E1090 at the instance's type, which then names the block itself (no
//! follow-on error); expressions are evaluated with checked arithmetic and a depth cap.

use super::lexer::{lex, Kw, Tok, Token};
use crate::ast::{CompilationUnit, LibraryElement, PouKind, TypeRef};
use crate::const_eval::{ConstNum, Constants};
use diagnostics::{code, Diagnostic, Diagnostics};
use std::ops::Range;

/// A function block with generic constants, as its file declares it.
#[derive(Debug, Clone)]
pub struct GenericBlock {
    /// The file that declares it.
    pub file: crate::FileId,
    /// The block's name as declared.
    pub name: String,
    /// Where the name is in the file's text.
    pub name_range: Range<usize>,
    /// Its generic constants, in the order of their declarations.
    pub constants: Vec<GenericConstant>,
}

/// One generic constant of a [`GenericBlock`].
#[derive(Debug, Clone)]
pub struct GenericConstant {
    /// The name as declared.
    pub name: String,
    /// The initial value (`None`: none given, or not a constant expression).
    pub initial: Option<i128>,
}

/// A block to build: `block` (an index into the blocks given to [`specialise_instances`]) with
/// these values, named `name`.
#[derive(Debug, Clone, PartialEq)]
pub struct Specialisation {
    /// The generic block's index.
    pub block: usize,
    /// One value per generic constant, in their order.
    pub values: Vec<i128>,
    /// The specialised block's name (`FB_Buf__10`).
    pub name: String,
}

/// The function blocks of `text` (a file's text as parsed) that declare generic constants; their
/// initial values evaluated with `known` (the project's global constants).
pub fn generic_blocks(file: crate::FileId, text: &str, known: &Constants) -> Vec<GenericBlock> {
    let (toks, _) = lex(text);
    let word = |t: &Token| text.get(t.range.clone()).unwrap_or("");
    let mut out: Vec<GenericBlock> = Vec::new();
    let mut current: Option<(String, Range<usize>)> = None;
    let mut k = 0;
    while k < toks.len() {
        let t = &toks[k];
        if t.tok == Tok::Ident && word(t).eq_ignore_ascii_case("FUNCTION_BLOCK") {
            // (`FUNCTION_BLOCK PUBLIC FB_X`, `FUNCTION_BLOCK ABSTRACT FB_X`)
            let name = toks[k + 1..].iter().take(3).find(|n| {
                n.tok == Tok::Ident
                    && ![
                        "PUBLIC",
                        "PRIVATE",
                        "INTERNAL",
                        "PROTECTED",
                        "ABSTRACT",
                        "FINAL",
                    ]
                    .iter()
                    .any(|q| word(n).eq_ignore_ascii_case(q))
            });
            current = name.map(|n| (word(n).to_string(), n.range.clone()));
        } else if t.tok == Tok::Ident && word(t).eq_ignore_ascii_case("VAR_GENERIC") {
            let Some((name, name_range)) = current.clone() else {
                k += 1;
                continue;
            };
            let (constants, next) = declarations(text, &toks, k + 1, known);
            k = next;
            match out.iter_mut().find(|b| b.name_range == name_range) {
                Some(b) => b.constants.extend(constants),
                None => out.push(GenericBlock {
                    file,
                    name,
                    name_range,
                    constants,
                }),
            }
            continue;
        }
        k += 1;
    }
    out
}

/// The declarations of a `VAR_GENERIC CONSTANT` block from token `k` (after `VAR_GENERIC`) to its
/// `END_VAR`, and the index after it.
fn declarations(
    text: &str,
    toks: &[Token],
    mut k: usize,
    known: &Constants,
) -> (Vec<GenericConstant>, usize) {
    let word = |t: &Token| text.get(t.range.clone()).unwrap_or("");
    let mut out = Vec::new();
    let mut names: Vec<String> = Vec::new();
    let mut assign: Option<usize> = None;
    let mut typed = false;
    while k < toks.len() {
        let t = &toks[k];
        match &t.tok {
            Tok::Eof => break,
            Tok::Ident if word(t).eq_ignore_ascii_case("END_VAR") => return (out, k + 1),
            Tok::Ident if word(t).eq_ignore_ascii_case("CONSTANT") && names.is_empty() => {}
            Tok::Ident if !typed => names.push(word(t).to_string()),
            Tok::Colon => typed = true,
            Tok::Assign if typed && assign.is_none() => assign = Some(k),
            Tok::Semi => {
                let initial = assign.and_then(|a| eval(text, &toks[a + 1..k], known));
                for name in names.drain(..) {
                    out.push(GenericConstant { name, initial });
                }
                assign = None;
                typed = false;
            }
            _ => {}
        }
        k += 1;
    }
    (out, k)
}

/// The value of an integer constant expression of tokens (`10`, `UDINT#10`, `16#FF`, `(2 * C)`,
/// `GVL.C + 1`), constants named from `known`; `None` when it is none.
fn eval(text: &str, toks: &[Token], known: &Constants) -> Option<i128> {
    let mut e = Eval {
        text,
        toks,
        at: 0,
        known,
        depth: 0,
    };
    let v = e.sum()?;
    (e.at == toks.len()).then_some(v)
}

struct Eval<'a> {
    text: &'a str,
    toks: &'a [Token],
    at: usize,
    known: &'a Constants,
    depth: usize,
}

impl Eval<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.at).map(|t| &t.tok)
    }
    fn sum(&mut self) -> Option<i128> {
        let mut v = self.product()?;
        loop {
            match self.peek() {
                Some(Tok::Plus) => {
                    self.at += 1;
                    v = v.checked_add(self.product()?)?;
                }
                Some(Tok::Minus) => {
                    self.at += 1;
                    v = v.checked_sub(self.product()?)?;
                }
                _ => return Some(v),
            }
        }
    }
    fn product(&mut self) -> Option<i128> {
        let mut v = self.unary()?;
        loop {
            match self.peek() {
                Some(Tok::Star) => {
                    self.at += 1;
                    v = v.checked_mul(self.unary()?)?;
                }
                Some(Tok::Slash) => {
                    self.at += 1;
                    v = v.checked_div(self.unary()?)?;
                }
                Some(Tok::Kw(Kw::Mod)) => {
                    self.at += 1;
                    v = v.checked_rem(self.unary()?)?;
                }
                _ => return Some(v),
            }
        }
    }
    fn unary(&mut self) -> Option<i128> {
        self.depth += 1;
        if self.depth > 64 {
            return None;
        }
        let v = match self.peek()? {
            Tok::Minus => {
                self.at += 1;
                self.unary()?.checked_neg()
            }
            Tok::Plus => {
                self.at += 1;
                self.unary()
            }
            Tok::LParen => {
                self.at += 1;
                let v = self.sum()?;
                (self.peek() == Some(&Tok::RParen)).then_some(())?;
                self.at += 1;
                Some(v)
            }
            // `UDINT#10`: the literal after the type
            Tok::TypePrefix => {
                self.at += 1;
                self.unary()
            }
            Tok::Int(n) => {
                let n = *n;
                self.at += 1;
                Some(n)
            }
            Tok::Ident => {
                // `C` or `GVL.C`: the last name is the constant's
                let mut name = self.word();
                self.at += 1;
                while self.peek() == Some(&Tok::Dot)
                    && self
                        .toks
                        .get(self.at + 1)
                        .is_some_and(|t| t.tok == Tok::Ident)
                {
                    self.at += 1;
                    name = self.word();
                    self.at += 1;
                }
                match self.known.get(&name.to_ascii_uppercase()) {
                    Some(ConstNum::Int(n)) => Some(*n),
                    _ => None,
                }
            }
            _ => None,
        };
        self.depth -= 1;
        v
    }
    fn word(&self) -> String {
        self.toks
            .get(self.at)
            .and_then(|t| self.text.get(t.range.clone()))
            .unwrap_or("")
            .to_string()
    }
}

/// Renames every type `FB_X<...>` of `units` (see the module documentation) and returns the
/// blocks to build, each set of values once; E1090 into `diags` for values that do not fit.
/// `blocks` are the project's generic blocks, `known` its global constants.
pub fn specialise_instances(
    units: &mut [CompilationUnit],
    pending: &mut [super::file::PendingBody],
    blocks: &[GenericBlock],
    known: &Constants,
    diags: &mut Diagnostics,
) -> Vec<Specialisation> {
    let blocks_declared: Vec<String> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Pou(p) if p.kind == PouKind::FunctionBlock => Some(p.name.key()),
            _ => None,
        })
        .collect();
    let mut built: Vec<Specialisation> = Vec::new();
    let mut each = |ty: &mut TypeRef| {
        rename(ty, &mut |id| {
            let Some((block_name, values)) = id.name.split_once('<') else {
                return;
            };
            let block_name = block_name.trim().to_string();
            let values = values.strip_suffix('>').unwrap_or(values).to_string();
            let Some(b) = blocks
                .iter()
                .position(|b| b.name.eq_ignore_ascii_case(&block_name))
            else {
                if blocks_declared.contains(&block_name.to_ascii_uppercase()) {
                    diags.push(misfit(
                        id.span,
                        &block_name,
                        format!(
                            "`{block_name}` declares no generic constants (`VAR_GENERIC CONSTANT`)"
                        ),
                    ));
                }
                id.name = block_name;
                return;
            };
            match instance_values(&blocks[b], &values, known) {
                Ok(values) => {
                    let defaults: Vec<Option<i128>> =
                        blocks[b].constants.iter().map(|c| c.initial).collect();
                    if values.iter().map(|v| Some(*v)).eq(defaults.iter().copied()) {
                        id.name = blocks[b].name.clone();
                        return;
                    }
                    let name = specialised_name(&blocks[b].name, &values);
                    if !built.iter().any(|s| s.name.eq_ignore_ascii_case(&name)) {
                        built.push(Specialisation {
                            block: b,
                            values,
                            name: name.clone(),
                        });
                    }
                    id.name = name;
                }
                Err(why) => {
                    diags.push(misfit(id.span, &block_name, why));
                    id.name = block_name;
                }
            }
        });
    };
    super::generic_constants::each_declared_type(units, pending, &mut each);
    built
}

fn rename(ty: &mut TypeRef, f: &mut impl FnMut(&mut crate::ast::Ident)) {
    match ty {
        TypeRef::Named(id) if id.name.contains('<') => f(id),
        TypeRef::Array { element, .. } => rename(element, f),
        TypeRef::Ref { target, .. } => rename(target, f),
        _ => {}
    }
}

/// E1090 at an instance's `FB_X<...>`.
fn misfit(span: crate::Span, block: &str, why: String) -> Diagnostic {
    Diagnostic::error(code::E1090, format!("`{block}<...>`: {why}"))
        .at(span)
        .with_primary_label("the instance's generic values")
        .with_hint(format!(
            "give one integer constant expression per generic constant of `{block}`, in their order (`{block}<10>`, `{block}<(2 * N)>`) or by name (`{block}<(N := 10)>`); this instance is read as a plain `{block}`"
        ))
}

/// The values an instance gives (`values`: the text between the angle brackets), one per
/// constant of `block`, its initial value where the instance gives none; or why they do not fit.
fn instance_values(
    block: &GenericBlock,
    values: &str,
    known: &Constants,
) -> Result<Vec<i128>, String> {
    let (toks, _) = lex(values);
    let toks: Vec<Token> = toks.into_iter().filter(|t| t.tok != Tok::Eof).collect();
    // `(N := 10, M := 2)`: the parentheses hold named values
    let named_in_parens = toks.first().is_some_and(|t| t.tok == Tok::LParen)
        && toks.last().is_some_and(|t| t.tok == Tok::RParen)
        && top_level(&toks[1..toks.len() - 1]).any(|(_, t)| t.tok == Tok::Assign);
    let toks = if named_in_parens {
        &toks[1..toks.len() - 1]
    } else {
        &toks[..]
    };
    let mut out: Vec<Option<i128>> = block.constants.iter().map(|c| c.initial).collect();
    let mut parts: Vec<&[Token]> = Vec::new();
    let mut from = 0;
    for (k, t) in top_level(toks) {
        if t.tok == Tok::Comma {
            parts.push(&toks[from..k]);
            from = k + 1;
        }
    }
    parts.push(&toks[from..]);
    if parts.len() == 1 && parts[0].is_empty() {
        return Err("no value is given".into());
    }
    for (i, part) in parts.iter().enumerate() {
        let text_of = |p: &[Token]| match (p.first(), p.last()) {
            (Some(a), Some(b)) => values
                .get(a.range.start..b.range.end)
                .unwrap_or("")
                .to_string(),
            _ => String::new(),
        };
        let (slot, expr) = match part {
            [name, assign, rest @ ..] if name.tok == Tok::Ident && assign.tok == Tok::Assign => {
                let name = values.get(name.range.clone()).unwrap_or("");
                let Some(slot) = block
                    .constants
                    .iter()
                    .position(|c| c.name.eq_ignore_ascii_case(name))
                else {
                    return Err(format!(
                        "`{name}` is no generic constant of `{}`",
                        block.name
                    ));
                };
                (slot, rest)
            }
            _ if i >= block.constants.len() => {
                return Err(format!(
                    "{} values given, `{}` declares {} generic constant(s)",
                    parts.len(),
                    block.name,
                    block.constants.len()
                ))
            }
            _ => (i, *part),
        };
        let Some(v) = eval(values, expr, known) else {
            return Err(format!(
                "`{}` is not an integer constant expression (a literal, or constants declared in a global constant list)",
                text_of(expr)
            ));
        };
        out[slot] = Some(v);
    }
    out.iter()
        .zip(&block.constants)
        .map(|(v, c)| {
            v.ok_or_else(|| format!("no value for `{}`, which has no initial value", c.name))
        })
        .collect()
}

/// The tokens of `toks` outside parentheses and brackets, with their indexes.
fn top_level(toks: &[Token]) -> impl Iterator<Item = (usize, &Token)> {
    let mut depth = 0usize;
    toks.iter().enumerate().filter(move |(_, t)| match t.tok {
        Tok::LParen | Tok::LBracket => {
            depth += 1;
            false
        }
        Tok::RParen | Tok::RBracket => {
            depth = depth.saturating_sub(1);
            false
        }
        _ => depth == 0,
    })
}

/// `FB_Buf__10`, `FB_Pou__100_1000`, `FB_Buf__m1`.
fn specialised_name(block: &str, values: &[i128]) -> String {
    let values: Vec<String> = values
        .iter()
        .map(|v| match v {
            v if *v < 0 => format!("m{}", v.unsigned_abs()),
            v => v.to_string(),
        })
        .collect();
    format!("{block}__{}", values.join("_"))
}

thread_local! {
    /// The generic constants' values of the block being built (upper-case name to value): set for
    /// the time of one call of [`with_instance_values`], empty otherwise.
    static INSTANCE_VALUES: std::cell::RefCell<std::collections::HashMap<String, i128>> =
        Default::default();
}

/// Runs `parse` (of `block`'s file) with the generic constants of `block` taking `values` in
/// place of their initial values: in the bounds and lengths they give, and as the constants'
/// initial values (see `instance_value`).
pub fn with_instance_values<R>(
    block: &GenericBlock,
    values: &[i128],
    parse: impl FnOnce() -> R,
) -> R {
    let map = block
        .constants
        .iter()
        .zip(values)
        .map(|(c, v)| (c.name.to_ascii_uppercase(), *v))
        .collect();
    let before = INSTANCE_VALUES.with(|m| m.replace(map));
    let result = parse();
    INSTANCE_VALUES.with(|m| m.replace(before));
    result
}

/// The value of the generic constant `names` (one declaration's names, in a `CONSTANT` block:
/// `constant`) while a block is built by [`with_instance_values`]; `None` otherwise.
pub(crate) fn instance_value(names: &[crate::ast::Ident], constant: bool) -> Option<i128> {
    if !constant {
        return None;
    }
    let first = names.first()?;
    INSTANCE_VALUES.with(|m| m.borrow().get(&first.key()).copied())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(text: &str) -> GenericBlock {
        generic_blocks(crate::FileId(0), text, &Constants::new())
            .pop()
            .expect("a generic block")
    }

    #[test]
    fn reads_the_constants_and_the_values_of_instances() {
        let text = "FUNCTION_BLOCK FB_Pou\nVAR_GENERIC CONSTANT\n  A : UDINT := 4;\n  B : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n";
        let b = block(text);
        assert_eq!(b.name, "FB_Pou");
        assert_eq!(b.constants.len(), 2);
        assert_eq!(b.constants[0].initial, Some(4));
        assert_eq!(b.constants[1].initial, None);
        let known: Constants = [("C".to_string(), ConstNum::Int(5))].into_iter().collect();
        assert_eq!(instance_values(&b, "10, 2", &known), Ok(vec![10, 2]));
        assert_eq!(
            instance_values(&b, "(B := 2 * GVL.C)", &known),
            Ok(vec![4, 10])
        );
        assert!(instance_values(&b, "10", &known).is_err());
        assert!(instance_values(&b, "1, 2, 3", &known).is_err());
        assert!(instance_values(&b, "(X := 1)", &known).is_err());
        assert!(instance_values(&b, "n, 2", &known).is_err());
        assert_eq!(specialised_name("FB", &[-1, 3]), "FB__m1_3");
    }
}
