//! `SIZEOF(T)` and `SIZEOF(v)` in constant expressions (`aBuffer : ARRAY[0..SIZEOF(ST_Data) - 1]
//! OF BYTE;`, `VAR CONSTANT n : UDINT := SIZEOF(ST_Data); END_VAR`, as TcUnit and TwinCAT projects
//! write them): the bytes a type takes in the C that ladderc generates, computed while the
//! declarations are parsed, before any C exists.
//!
//! Input: a declared type ([`TypeRef`]) and the sizes known so far (in the [`Constants`] of the
//! parser, under [`size_key`] and [`align_key`]); for a whole project, its parsed units
//! ([`project_sizes`]). Output: a [`Layout`] (size and alignment in bytes), or why there is none.
//! Invariants: the layout is the one of the C types of `crates/c-backend` (README "Memory model"):
//! BOOL 1 byte, the integer and real types their widths, TIME/LTIME/DATE/TOD/DT 8, an enumeration
//! an `IEC_DINT` (4), a reference an `IEC_REF` (an address, a 4-byte size and a 4-byte offset),
//! STRING an `IEC_STRING` (258) and WSTRING an `IEC_WSTRING` (512) whatever their lengths, arrays
//! their elements times their lengths, structures C structs with the C compiler's padding (each
//! field at a multiple of its alignment, the whole a multiple of the largest), unions the largest
//! member rounded likewise, a structure that EXTENDS another its base's fields first (flattened, as
//! `crate::st::struct_extends` does); `tests/tests/lang_left_r18.rs` runs each kind against the
//! run-time `SIZEOF` (C's `sizeof`). A function block instance has no size here
//! (its C struct holds members of ladderc's own): `SIZEOF(FB_X)` in a constant expression says so.
//! Nothing panics: sizes are checked against overflow, bases and nesting are followed to a depth cap.

use crate::ast::{CompilationUnit, LibraryElement, PouKind, TypeDecl, TypeDef, TypeRef, VarDecl};
use crate::const_eval::{ConstNum, Constants};
use crate::sema::Elementary;
use std::collections::HashMap;

/// The size and alignment of a type in the generated C, in bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// C's `sizeof`.
    pub size: u64,
    /// The alignment the C compiler gives it (a struct field's offset is a multiple of it).
    pub align: u64,
}

/// The key of a type's size among the [`Constants`] (`SIZEOF ST_DATA`: a space, so no constant's
/// name).
pub fn size_key(name: &str) -> String {
    format!("SIZEOF {}", name.to_ascii_uppercase())
}

/// The key of a type's alignment among the [`Constants`].
pub fn align_key(name: &str) -> String {
    format!("ALIGNOF {}", name.to_ascii_uppercase())
}

/// The key marking a function block's name among the [`Constants`] (its size is not known here).
pub fn block_key(name: &str) -> String {
    format!("BLOCK {}", name.to_ascii_uppercase())
}

/// The hidden first field of a structure that EXTENDS another (`crate::st::struct_extends`).
const BASE_FIELD: &str = "__B";

/// How deep structures, arrays and bases may nest before the size is given up.
const MAX_DEPTH: u32 = 64;

/// The C layout of `IEC_REF` on this host: `{ unsigned char *base; uint32_t size; int32_t off; }`
/// (the C is compiled for the host ladderc runs on).
fn reference() -> Layout {
    let ptr = std::mem::size_of::<usize>() as u64;
    Layout {
        size: round_up(ptr + 8, ptr),
        align: ptr,
    }
}

fn round_up(n: u64, align: u64) -> u64 {
    n.div_ceil(align.max(1)) * align.max(1)
}

/// The layout of an elementary type (an `IEC_<T>` of its width).
fn elementary(e: Elementary) -> Layout {
    let size = u64::from(e.bit_width().div_ceil(8));
    Layout { size, align: size }
}

/// What a type name measures: the layouts known in `known`, and the structures whose fields
/// flatten into a structure that EXTENDS them.
struct Known<'a> {
    consts: &'a Constants,
    structs: &'a HashMap<String, &'a [VarDecl]>,
}

/// The layout of `ty`, with the user types of `consts` known (see [`size_key`]); the error says why
/// there is none.
pub fn of_type(ty: &TypeRef, consts: &Constants) -> Result<Layout, String> {
    of(
        ty,
        &Known {
            consts,
            structs: &HashMap::new(),
        },
        0,
    )
}

fn of(ty: &TypeRef, known: &Known, depth: u32) -> Result<Layout, String> {
    if depth > MAX_DEPTH {
        return Err("the type is nested too deeply".into());
    }
    match ty {
        TypeRef::Named(n) => named(&n.name, known.consts),
        // `{ uint16_t len; char data[255]; }`: 257 bytes, padded to 258
        TypeRef::String { wide: false, .. } => Ok(Layout {
            size: round_up(2 + 255, 2),
            align: 2,
        }),
        TypeRef::String { wide: true, .. } => Ok(Layout {
            size: 2 + 2 * 255,
            align: 2,
        }),
        TypeRef::Array { dims, element, .. } => {
            let e = of(element, known, depth + 1)?;
            let mut size = e.size;
            for d in dims {
                let len = d.upper.checked_sub(d.lower).and_then(|n| n.checked_add(1));
                let len = len.and_then(|n| u64::try_from(n.max(1)).ok());
                size = len
                    .and_then(|n| size.checked_mul(n))
                    .ok_or("the array's size overflows")?;
            }
            Ok(Layout {
                size,
                align: e.align,
            })
        }
        TypeRef::Subrange { base, .. } => named(&base.name, known.consts),
        TypeRef::Enum { .. } => Ok(elementary(Elementary::Dint)),
        TypeRef::Ref { .. } => Ok(reference()),
    }
}

/// The layout of a type named `name`: elementary, or a user type whose layout is known.
fn named(name: &str, consts: &Constants) -> Result<Layout, String> {
    if let Some(e) = Elementary::from_name(name) {
        return Ok(elementary(e));
    }
    if name.eq_ignore_ascii_case("STRING") {
        return of_type(
            &TypeRef::String {
                wide: false,
                length: None,
                span: Default::default(),
            },
            consts,
        );
    }
    if name.eq_ignore_ascii_case("WSTRING") {
        return of_type(
            &TypeRef::String {
                wide: true,
                length: None,
                span: Default::default(),
            },
            consts,
        );
    }
    let int = |key: String| match consts.get(&key) {
        Some(ConstNum::Int(v)) => u64::try_from(*v).ok(),
        _ => None,
    };
    match (int(size_key(name)), int(align_key(name))) {
        (Some(size), Some(align)) => Ok(Layout { size, align }),
        _ if consts.contains_key(&block_key(name)) => Err(format!(
            "`{name}` is a function block: the size of its instance is known in code (`SIZEOF(x)` in a body), not while declarations are read"
        )),
        _ => {
            // (read by key, never by a scan of every constant: a text of 100,000 types declared
            // in terms of each other stays linear)
            let held = held_of(consts, name);
            match held {
                // a type declared with a field of a type declared nowhere: that type is the cause
                // (sema's E1003 names it, and then this one is left out: [`held_unknown`])
                Some(held) => Err(format!(
                    "the size of `{name}` is not known: it holds `{held}`{DECLARED_NOWHERE}"
                )),
                None => Err(format!(
                    "the size of `{name}` is not known (no data type or variable of that name declared before, in this file or another given file)"
                )),
            }
        }
    }
}

/// The key prefix marking a declared type whose size is not known because it holds a type declared
/// nowhere (`HOLDS ST_LOG`: the length of the unknown type's name as written, and `HOLDS ST_LOG #0`,
/// `#1` ...: its bytes, [`mark_unknown`]).
const HOLDS: &str = "HOLDS ";

/// The end of the reason [`named`] gives for a type that holds a type whose size is not known.
const DECLARED_NOWHERE: &str = ", whose size is not known";

/// The type declared nowhere that `why` (a reason of [`of_type`]) names as the cause: the type
/// itself when it is not declared, or the unknown type a declared one holds.
pub fn held_unknown(why: &str) -> Option<&str> {
    if let Some(rest) = why.strip_prefix("the size of `") {
        let (name, tail) = rest.split_once('`')?;
        if tail.starts_with(" is not known (no data type") {
            return Some(name);
        }
        let held = tail.strip_prefix(" is not known: it holds `")?;
        let (held, tail) = held.split_once('`')?;
        return (tail == DECLARED_NOWHERE).then_some(held);
    }
    None
}

/// Marks `name` as holding the unknown type that `why` names (see [`HOLDS`]); of two, the first
/// in name order (as the messages are the same whatever the order of the text).
fn mark_unknown(consts: &mut Constants, name: &str, why: &str) {
    let Some(held) = held_unknown(why) else {
        return;
    };
    if held_of(consts, name).is_some_and(|h| h.as_str() <= held) {
        return;
    }
    let key = format!("{HOLDS}{}", name.to_ascii_uppercase());
    // the name's bytes, 15 to a number (so that each stays positive), after its length
    let bytes = held.as_bytes();
    consts.insert(key.clone(), ConstNum::Int(bytes.len() as i128));
    for (k, chunk) in bytes.chunks(15).enumerate() {
        let v = chunk
            .iter()
            .rev()
            .fold(0i128, |acc, &b| (acc << 8) | i128::from(b));
        consts.insert(format!("{key} #{k}"), ConstNum::Int(v));
    }
}

/// The unknown type `name` is marked as holding ([`mark_unknown`]).
fn held_of(consts: &Constants, name: &str) -> Option<String> {
    let key = format!("{HOLDS}{}", name.to_ascii_uppercase());
    let Some(ConstNum::Int(len)) = consts.get(&key) else {
        return None;
    };
    let len = usize::try_from(*len).ok()?;
    let mut bytes = Vec::with_capacity(len);
    for k in 0..len.div_ceil(15) {
        let Some(ConstNum::Int(mut v)) = consts.get(&format!("{key} #{k}")).cloned() else {
            return None;
        };
        for _ in 0..15.min(len - bytes.len()) {
            bytes.push((v & 0xff) as u8);
            v >>= 8;
        }
    }
    String::from_utf8(bytes).ok()
}

/// Whether the E0022 message `message` (`constant expression ...: <reason>`) is about a type that
/// holds `unknown`, a type declared nowhere (sema's E1003 for `unknown` is then the one error).
pub fn is_about_unknown(message: &str, unknown: &str) -> bool {
    message
        .split_once("`: ")
        .and_then(|(_, why)| held_unknown(why))
        .is_some_and(|held| held.eq_ignore_ascii_case(unknown))
}

/// The layout of a structure (or a union) of `fields`: a base's fields first, flattened.
fn structure(fields: &[VarDecl], union: bool, known: &Known, depth: u32) -> Result<Layout, String> {
    let mut members = Vec::new();
    flatten(fields, known, depth, &mut members)?;
    let (mut size, mut align) = (0u64, 1u64);
    for ty in members {
        let f = of(ty, known, depth + 1)?;
        align = align.max(f.align);
        size = if union {
            size.max(f.size)
        } else {
            round_up(size, f.align)
                .checked_add(f.size)
                .ok_or("the structure's size overflows")?
        };
    }
    // a structure without members is one `char unused_;` in the C
    Ok(Layout {
        size: round_up(size.max(1), align),
        align,
    })
}

/// The types of the members of a structure of `fields` as the C declares them: a base's (the hidden
/// [`BASE_FIELD`]) flattened in its place, located fields left out (they have no storage).
fn flatten<'a>(
    fields: &'a [VarDecl],
    known: &Known<'a>,
    depth: u32,
    out: &mut Vec<&'a TypeRef>,
) -> Result<(), String> {
    if depth > MAX_DEPTH {
        return Err("the structure's bases are nested too deeply".into());
    }
    for (k, f) in fields.iter().enumerate() {
        if f.location.is_some() {
            continue;
        }
        if k == 0 && f.name.name == BASE_FIELD {
            if let TypeRef::Named(base) = &f.ty {
                if let Some(base_fields) = known.structs.get(&base.name.to_ascii_uppercase()) {
                    flatten(base_fields, known, depth + 1, out)?;
                    continue;
                }
            }
        }
        out.push(&f.ty);
    }
    Ok(())
}

/// The layout of the type declared by `decl`.
fn declared(decl: &TypeDecl, known: &Known) -> Result<Layout, String> {
    match &decl.def {
        TypeDef::Alias { ty, .. } => of(ty, known, 0),
        TypeDef::Struct { fields } => structure(fields, decl.union, known, 0),
        TypeDef::Enum { .. } => Ok(elementary(Elementary::Dint)),
    }
}

/// Adds the layout of the type `decl` declares to `consts` when it can be computed from what they
/// hold (a type declared before in the same text: no base of another structure is followed).
pub fn add_declared(consts: &mut Constants, decl: &TypeDecl) {
    // a structure that EXTENDS another is measured with its base's fields ([`project_sizes`])
    if let TypeDef::Struct { fields } = &decl.def {
        if fields.first().is_some_and(|f| f.name.name == BASE_FIELD) {
            return;
        }
    }
    let structs = HashMap::new();
    let layout = declared(
        decl,
        &Known {
            consts,
            structs: &structs,
        },
    );
    match layout {
        Ok(l) => insert(consts, &decl.name.name, l),
        Err(why) => mark_unknown(consts, &decl.name.name, &why),
    }
}

fn insert(consts: &mut Constants, name: &str, l: Layout) {
    consts.insert(size_key(name), ConstNum::Int(i128::from(l.size)));
    consts.insert(align_key(name), ConstNum::Int(i128::from(l.align)));
}

/// The layouts of every data type `units` declare that can be computed (a type of another unit
/// too, in any order), and the names of their function blocks ([`block_key`]): the keys
/// [`size_key`], [`align_key`] and [`block_key`] offered to the constant expressions of every file.
pub fn project_sizes<'a>(
    units: impl IntoIterator<Item = &'a CompilationUnit> + Clone,
) -> Constants {
    let decls: Vec<&TypeDecl> = units
        .clone()
        .into_iter()
        .flat_map(|u| &u.items)
        .flat_map(|item| match item {
            LibraryElement::DataTypes(types) => types.as_slice(),
            _ => &[],
        })
        .collect();
    let structs: HashMap<String, &[VarDecl]> = decls
        .iter()
        .filter_map(|d| match &d.def {
            TypeDef::Struct { fields } if !d.union => {
                Some((d.name.name.to_ascii_uppercase(), fields.as_slice()))
            }
            _ => None,
        })
        .collect();
    let mut consts = Constants::new();
    for u in units {
        for item in &u.items {
            if let LibraryElement::Pou(p) = item {
                if p.kind == PouKind::FunctionBlock {
                    consts.insert(block_key(&p.name.name), ConstNum::Int(0));
                }
            }
        }
    }
    // a type may name types declared after it: as many rounds as it takes, each adding at least one
    let mut left: Vec<&TypeDecl> = decls;
    loop {
        let before = left.len();
        let mut found = Vec::new();
        left.retain(|d| {
            let known = Known {
                consts: &consts,
                structs: &structs,
            };
            match declared(d, &known) {
                Ok(l) => {
                    found.push((d.name.name.clone(), l));
                    false
                }
                Err(_) => true,
            }
        });
        for (name, l) in found {
            insert(&mut consts, &name, l);
        }
        if left.is_empty() || left.len() == before {
            break;
        }
    }
    // the types left hold a type whose size is not known: each is marked with the innermost one
    // (`A` holds `B`, which holds `X` declared nowhere: `A` holds `X`), a declared one last
    let left_names: std::collections::HashSet<String> = left
        .iter()
        .map(|d| d.name.name.to_ascii_uppercase())
        .collect();
    let mut unmarked = left;
    for last in [false, true] {
        loop {
            let mut marks = Vec::new();
            unmarked.retain(|d| {
                let known = Known {
                    consts: &consts,
                    structs: &structs,
                };
                let Err(why) = declared(d, &known) else {
                    return true;
                };
                let inner = held_unknown(&why)
                    .is_some_and(|h| !left_names.contains(&h.to_ascii_uppercase()));
                if inner || last {
                    marks.push((d.name.name.clone(), why));
                    return false;
                }
                true
            });
            if marks.is_empty() {
                break;
            }
            for (name, why) in marks {
                mark_unknown(&mut consts, &name, &why);
            }
        }
    }
    consts
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ast::Ident;

    fn named(n: &str) -> TypeRef {
        TypeRef::Named(Ident::new(n, Default::default()))
    }

    #[test]
    fn elementary_strings_and_references_have_the_c_runtime_sizes() {
        let c = Constants::new();
        let size = |t: &TypeRef| of_type(t, &c).unwrap().size;
        assert_eq!(size(&named("BOOL")), 1);
        assert_eq!(size(&named("lreal")), 8);
        assert_eq!(size(&named("TIME")), 8);
        assert_eq!(size(&named("STRING")), 258);
        assert_eq!(size(&named("WSTRING")), 512);
        assert_eq!(
            of_type(
                &TypeRef::Ref {
                    kind: crate::ast::RefKind::Pointer,
                    target: Box::new(named("INT")),
                    span: Default::default(),
                },
                &c
            )
            .unwrap(),
            reference()
        );
    }

    #[test]
    fn an_unknown_type_and_a_block_say_why() {
        let mut c = Constants::new();
        c.insert(block_key("FB_X"), ConstNum::Int(0));
        assert!(of_type(&named("FB_X"), &c)
            .unwrap_err()
            .contains("function block"));
        assert!(of_type(&named("ST_Y"), &c)
            .unwrap_err()
            .contains("not known"));
    }
}
