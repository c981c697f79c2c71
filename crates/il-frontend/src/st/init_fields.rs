//! The fields of a structured initial value computed at run time, at any depth (CODESYS, TwinCAT):
//! `fb : FB_X := (a := F(1), b := 2)`, and nested in a structure or an array of structures
//! (`w : FB_Wrap := (View := (iParent := THIS^));`, `aRcp : ARRAY[0..1] OF ST_Rcp := [(id := 2,
//! days := F_Days(TRUE, FALSE)), (id := 3)];` in Beckhoff's TF8040 samples), which a
//! declaration's constant initial value cannot hold.
//!
//! Input: the tokens of one declaration's value (after its `:=`, a `( .. )` or `[ .. ]`
//! initialiser), the variables and globals a computed value may read ([`super::pou_inits`]).
//! Output ([`computed_fields`]): the fields `name := expr` whose value is computed (it calls a
//! function, reads a variable declared before or a global, holds `^` or `THIS`), each with the
//! path from the variable to the structure holding it ([`InitStep`]), grouped by the structure
//! initialiser they are written in (to cut them out of it, [`Fields::cuts`]), and the elements
//! whose computed fields have no place: in a repeated element (`[2((p := THIS^))]`) or after a
//! repetition whose count is a name (`[N(0), (p := THIS^)]`: the element's index is not known
//! before the constants are), reported by the caller (E1069). [`prefix_fields`] turns the
//! assignment `a := F(1);` parsed where the field is written into `fb.a := F(1);`, an element
//! `aRcp[LOWER_BOUND(aRcp, 1) + 0].days := ..` (the array's first index, whatever its bounds).
//! Invariants: positions do not move; nothing here recurses deeper than [`MAX_DEPTH`]
//! initialisers (deeper: nothing is taken, the declaration's parse reports what it finds); a
//! bare element of an array (`[F(1), 2]`) is no field and stays the declaration's (E0022 names
//! the call); an array initialiser is read as one dimension (a `[..]` element as the next level:
//! an array of arrays).

use super::lexer::{Tok, Token};
use std::ops::Range;

/// How many initialisers deep the fields are looked for.
const MAX_DEPTH: usize = 16;

/// One step from a variable to the structure initialiser holding a computed field.
#[derive(Debug, Clone, PartialEq)]
pub enum InitStep {
    /// `.name`: a field of a structure (an input of an instance).
    Field(String),
    /// The element at this position (from 0) of an array initial value.
    Element(usize),
}

/// Where a computed field's assignment goes: the variable (its name, where it is declared: the
/// assignment's target is that name, as a plain variable's initial assignment is) and the steps
/// to the structure holding the field.
pub type InitTarget = (String, Range<usize>, Vec<InitStep>);

/// One element `name := expr` of a structure initialiser, as indexes into the value's tokens.
#[derive(Debug, Clone)]
pub(super) struct Field {
    /// The separator before it (`(` or `,`).
    pub sep: usize,
    /// Its first token (the field's name).
    pub first: usize,
    /// Its last token.
    pub last: usize,
    /// Its value is computed at run time (then it is assigned, not declared).
    pub computed: bool,
    /// Its value is a nested initialiser (it stays, maybe emptied: `View := ()`).
    pub nested: bool,
    /// The steps from the variable to the structure holding it.
    pub path: Vec<InitStep>,
}

/// What [`computed_fields`] finds in one value.
#[derive(Debug, Default)]
pub(super) struct Fields {
    /// The structure initialisers, each its elements in order.
    pub groups: Vec<Vec<Field>>,
    /// The token ranges (first, last) of the elements whose computed fields have no place.
    pub unplaceable: Vec<(usize, usize)>,
}

impl Fields {
    /// The computed fields, in the order of the text.
    pub fn computed(&self) -> impl Iterator<Item = &Field> {
        let mut all: Vec<&Field> = self
            .groups
            .iter()
            .flatten()
            .filter(|f| f.computed)
            .collect();
        all.sort_by_key(|f| f.first);
        all.into_iter()
    }

    /// Every field that is no nested initialiser is computed: the whole value is assigned.
    pub fn all_computed(&self) -> bool {
        self.groups.iter().flatten().all(|f| f.nested || f.computed)
    }

    /// The byte ranges of `value`'s text to blank so that the declaration keeps the fields that
    /// are not computed: each computed field with one comma (the one before it after a field that
    /// stays, else its own after it, so that two computed fields side by side never take the same
    /// comma); all the elements of an initialiser whose fields are all computed (`View := ()`).
    pub fn cuts(&self, value: &[Token]) -> Vec<Range<usize>> {
        let mut out = Vec::new();
        for group in &self.groups {
            let (Some(head), Some(tail)) = (group.first(), group.last()) else {
                continue;
            };
            if group.iter().all(|f| f.computed) {
                out.push(value[head.first].range.start..value[tail.last].range.end);
                continue;
            }
            let mut kept_before = false;
            for f in group {
                if !f.computed {
                    kept_before = true;
                    continue;
                }
                let (from, to) = if kept_before {
                    (value[f.sep].range.start, value[f.last].range.end)
                } else {
                    (value[f.first].range.start, value[f.last + 1].range.end)
                };
                out.push(from..to);
            }
        }
        out
    }
}

/// See the module documentation: `None` when no field of `value` is computed (and no element is
/// unplaceable), or when it is no initialiser of fields (`(5)`, a bare array `[1, 2]`);
/// `computed(tokens)`: whether an expression's tokens are computed at run time.
pub(super) fn computed_fields(
    decls: &str,
    value: &[Token],
    computed: &dyn Fn(&[Token]) -> bool,
) -> Option<Fields> {
    let close = value.len().checked_sub(1)?;
    if close < 2
        || !matches!(value[0].tok, Tok::LParen | Tok::LBracket)
        || closing(value, 0) != Some(close)
        || !value.iter().any(|t| t.tok == Tok::Assign)
    {
        return None;
    }
    let mut found = Fields::default();
    let walker = Walker { decls, computed };
    walker.walk(value, 0, close, &mut Vec::new(), &mut found, 0)?;
    let any = found.groups.iter().flatten().any(|f| f.computed);
    (any || !found.unplaceable.is_empty()).then_some(found)
}

struct Walker<'a> {
    decls: &'a str,
    computed: &'a dyn Fn(&[Token]) -> bool,
}

impl Walker<'_> {
    /// Whether the tokens hold a computed value: a call or a read ([`Self::computed`]), a `^`,
    /// `THIS`.
    fn run_time(&self, toks: &[Token]) -> bool {
        toks.iter().any(|t| {
            t.tok == Tok::Caret
                || (t.tok == Tok::Ident
                    && self
                        .decls
                        .get(t.range.clone())
                        .is_some_and(|w| w.eq_ignore_ascii_case("THIS")))
        }) || (self.computed)(toks)
    }

    /// Walks the initialiser `value[open..=close]` (a `(..)` of fields or a `[..]` of elements)
    /// reached by `path`; `None` when it is no initialiser of fields.
    fn walk(
        &self,
        value: &[Token],
        open: usize,
        close: usize,
        path: &mut Vec<InitStep>,
        found: &mut Fields,
        depth: usize,
    ) -> Option<()> {
        if depth > MAX_DEPTH {
            return None;
        }
        let items = elements(value, open, close)?;
        if value[open].tok == Tok::LParen {
            let mut group = Vec::new();
            for (sep, first, last) in items {
                let toks = value.get(first..=last)?;
                if toks.len() < 3 || toks[0].tok != Tok::Ident || toks[1].tok != Tok::Assign {
                    return None;
                }
                let name = self.decls.get(toks[0].range.clone())?.to_string();
                let nested = initialiser(value, first + 2, last);
                if nested {
                    path.push(InitStep::Field(name));
                    let inner = self.walk(value, first + 2, last, path, found, depth + 1);
                    path.pop();
                    inner?;
                }
                let computed = !nested && self.run_time(&toks[2..]);
                group.push(Field {
                    sep,
                    first,
                    last,
                    computed,
                    nested,
                    path: path.clone(),
                });
            }
            found.groups.push(group);
            return Some(());
        }
        // an array: each element's position, while it is known
        let mut at = Some(0usize);
        for (_, first, last) in items {
            if initialiser(value, first, last) {
                let mut inner = Fields::default();
                path.push(InitStep::Element(at.unwrap_or(0)));
                let walked = self.walk(value, first, last, path, &mut inner, depth + 1);
                path.pop();
                walked?;
                let any = inner.groups.iter().flatten().any(|f| f.computed);
                if at.is_none() && any {
                    found.unplaceable.push((first, last));
                } else {
                    found.groups.append(&mut inner.groups);
                    found.unplaceable.append(&mut inner.unplaceable);
                }
                at = at.map(|k| k + 1);
                continue;
            }
            // `3(x)`, `N(x)`: a repetition (or a call, which the declaration's parse reports)
            let repeated = last > first + 2
                && matches!(value[first].tok, Tok::Ident | Tok::Int(_))
                && value[first + 1].tok == Tok::LParen
                && closing(value, first + 1) == Some(last);
            if repeated {
                let inner = &value[first + 2..last];
                if inner.iter().any(|t| t.tok == Tok::Assign) && self.run_time(inner) {
                    found.unplaceable.push((first, last));
                }
                let count = match value[first].tok {
                    Tok::Int(n) => usize::try_from(n).ok(),
                    _ => None,
                };
                at = at.zip(count).map(|(k, n)| k.saturating_add(n));
                continue;
            }
            at = at.map(|k| k + 1);
        }
        Some(())
    }
}

/// Whether `value[first..=last]` is one initialiser: `[..]`, or `(..)` holding a `:=`.
fn initialiser(value: &[Token], first: usize, last: usize) -> bool {
    let Some(t) = value.get(first) else {
        return false;
    };
    match t.tok {
        Tok::LBracket => closing(value, first) == Some(last),
        Tok::LParen => {
            closing(value, first) == Some(last)
                && value[first..=last].iter().any(|t| t.tok == Tok::Assign)
        }
        _ => false,
    }
}

/// The index of the token closing the `(` or `[` at `open`.
fn closing(value: &[Token], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (j, t) in value.iter().enumerate().skip(open) {
        match t.tok {
            Tok::LParen | Tok::LBracket => depth += 1,
            Tok::RParen | Tok::RBracket => {
                depth = depth.checked_sub(1)?;
                if depth == 0 {
                    return Some(j);
                }
            }
            _ => {}
        }
    }
    None
}

/// The elements between `value[open]` and `value[close]`, split at the commas of that level:
/// (separator before, first token, last token); `None` when one is empty.
fn elements(value: &[Token], open: usize, close: usize) -> Option<Vec<(usize, usize, usize)>> {
    let mut out = Vec::new();
    let mut depth = 0i32;
    let mut first = open + 1;
    for (j, t) in value.iter().enumerate().take(close).skip(open + 1) {
        match t.tok {
            Tok::LParen | Tok::LBracket => depth += 1,
            Tok::RParen | Tok::RBracket => depth -= 1,
            Tok::Comma if depth == 0 => {
                if j == first {
                    return None;
                }
                out.push((first - 1, first, j - 1));
                first = j + 1;
            }
            _ => {}
        }
        if depth < 0 {
            return None;
        }
    }
    if first >= close {
        return None;
    }
    out.push((first - 1, first, close - 1));
    Some(out)
}

/// Puts the variable and the steps before the targets of the field assignments a structured
/// initial value's computed fields became (the range of each, its [`InitTarget`]): `a := F(1);`
/// at one of them is `fb.a := F(1);`, `aRcp[LOWER_BOUND(aRcp, 1) + 0].days := ..` in an array.
pub(super) fn prefix_fields(
    stmts: &mut [super::ast::Stmt],
    prefixed: &[(Range<usize>, InitTarget)],
) {
    use super::ast::{Accessor, Arg, ArgDir, BinaryOp, Expr, ExprKind, Place, PlaceBase, StmtKind};
    use crate::ast::{Ident, LiteralKind};
    for s in stmts {
        let at = s.span.start as usize;
        let Some((_, (var, declared, steps))) = prefixed.iter().find(|(r, _)| r.contains(&at))
        else {
            continue;
        };
        let StmtKind::Assign { target, .. } = &mut s.kind else {
            continue;
        };
        let PlaceBase::Name(field) = &target.base else {
            continue;
        };
        let field = field.clone();
        let span = field.span;
        let name = Ident::new(
            var,
            crate::Span::new(span.file, declared.start, declared.end),
        );
        let mut accessors: Vec<Accessor> = Vec::new();
        for step in steps {
            accessors.push(match step {
                InitStep::Field(n) => Accessor::Field(Ident::new(n, span)),
                InitStep::Element(k) => {
                    // the array's first index, whatever its bounds, plus the position
                    let array = Expr {
                        kind: ExprKind::Place(Place {
                            base: PlaceBase::Name(name.clone()),
                            accessors: accessors.clone(),
                            span,
                        }),
                        span,
                    };
                    let arg = |value: Expr| Arg {
                        name: None,
                        dir: ArgDir::Input,
                        value,
                        span,
                    };
                    let lower = Expr {
                        kind: ExprKind::Call {
                            name: Ident::new("LOWER_BOUND", span),
                            args: vec![arg(array), arg(Expr::literal(LiteralKind::Int(1), span))],
                        },
                        span,
                    };
                    let k = i128::try_from(*k).unwrap_or(i128::MAX);
                    Accessor::Index(vec![Expr {
                        kind: ExprKind::Binary {
                            op: BinaryOp::Add,
                            left: Box::new(lower),
                            right: Box::new(Expr::literal(LiteralKind::Int(k), span)),
                        },
                        span,
                    }])
                }
            });
        }
        accessors.push(Accessor::Field(field));
        accessors.append(&mut target.accessors);
        target.base = PlaceBase::Name(name);
        target.accessors = accessors;
    }
}
