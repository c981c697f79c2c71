//! Semantic analysis of IL: symbols, types, current-result typing, labels, calls.
//!
//! Input: the parsed [`crate::ast::CompilationUnit`]s of one program (one namespace of POUs and types).
//! Output: the resolved [`model::Model`] and diagnostics (codes E1xxx/W1xxx).
//! Invariants: one mistake gives one diagnostic: an unresolvable name gives the `Error` type, which
//! silences every check that would follow from it. The rules implemented are in `README_sema.md`.
//!
//! Stages: `decls` (types, POU variables, globals, configurations) then `body` (each POU's IL body).

mod address_init;
mod bit_arith;
mod block_cycles;
mod body;
mod calls;
mod decl_order;
mod decls;
mod loose_enum;
mod memory;
pub mod model;
pub mod nesting;
mod places;
mod program_calls;
mod refs;
pub mod stdlib;
mod struct_cycles;
pub mod typing;

pub use decls::reserved_name;
pub use model::*;

use crate::ast::CompilationUnit;
use diagnostics::{code, Code, Diagnostic, Diagnostics};
use std::collections::HashMap;

thread_local! {
    /// The files that are TwinCAT 3 objects (`.TcPOU`, `.TcGVL` ...): see [`TwinCatFiles`].
    static TWINCAT_FILES: std::cell::RefCell<std::collections::HashSet<diagnostics::FileId>> =
        Default::default();
}

thread_local! {
    /// The files written for CODESYS or TwinCAT: see [`CodesysFiles`].
    static CODESYS_FILES: std::cell::RefCell<std::collections::HashSet<diagnostics::FileId>> =
        Default::default();
}

/// The files written for CODESYS or TwinCAT (TwinCAT 3 objects, CODESYS V2.3 exports and objects,
/// CODESYS's PLCopen XML), known to the analyses run while the guard lives: the vendor's meaning
/// applies there where it differs from IEC 61131-3 edition 3's (`s[i]` of a STRING is a BYTE at
/// offset `i`, 0 the first, not the i-th CHAR).
pub struct CodesysFiles {
    before: std::collections::HashSet<diagnostics::FileId>,
}

impl CodesysFiles {
    /// Makes `files` known until the guard is dropped (then the ones known before are again).
    pub fn set(files: impl IntoIterator<Item = diagnostics::FileId>) -> CodesysFiles {
        let files = files.into_iter().collect();
        CodesysFiles {
            before: CODESYS_FILES.with(|t| t.replace(files)),
        }
    }
}

impl Drop for CodesysFiles {
    fn drop(&mut self) {
        let before = std::mem::take(&mut self.before);
        CODESYS_FILES.with(|t| t.replace(before));
    }
}

/// Whether `file` was written for CODESYS or TwinCAT ([`CodesysFiles`]).
pub(crate) fn is_codesys_file(file: diagnostics::FileId) -> bool {
    CODESYS_FILES.with(|t| t.borrow().contains(&file))
}

/// The files read from TwinCAT 3 objects, known to the analyses run while the guard lives
/// (`TwinCatFiles::set(files)`): what TwinCAT accepts and IEC 61131-3 reserves is accepted there
/// (`Configuration`, `Resource` naming a variable: W1418).
pub struct TwinCatFiles {
    before: std::collections::HashSet<diagnostics::FileId>,
}

impl TwinCatFiles {
    /// Makes `files` known until the guard is dropped (then the ones known before are again).
    pub fn set(files: impl IntoIterator<Item = diagnostics::FileId>) -> TwinCatFiles {
        let files = files.into_iter().collect();
        TwinCatFiles {
            before: TWINCAT_FILES.with(|t| t.replace(files)),
        }
    }
}

impl Drop for TwinCatFiles {
    fn drop(&mut self) {
        let before = std::mem::take(&mut self.before);
        TWINCAT_FILES.with(|t| t.replace(before));
    }
}

/// Whether `file` is a TwinCAT 3 object ([`TwinCatFiles`]).
pub(crate) fn is_twincat_file(file: diagnostics::FileId) -> bool {
    TWINCAT_FILES.with(|t| t.borrow().contains(&file))
}

/// Analyses `units` together and returns the resolved model; problems go to `diags`.
pub fn analyze(units: &[CompilationUnit], diags: &mut Diagnostics) -> Model {
    analyze_with(units, diags, true)
}

/// [`analyze`] for code generation: the same model and diagnostics, but [`Model::names`] (what
/// each name used in a body refers to, for tools such as the language server; the C generation does
/// not read it) holds only the uses of a function's own name as its result. The table took a fifth
/// of the memory pages sema touches on 100,000 IL lines (crates/ladderc/BENCHMARKS.md, Round 17).
pub fn analyze_for_code(units: &[CompilationUnit], diags: &mut Diagnostics) -> Model {
    analyze_with(units, diags, false)
}

fn analyze_with(units: &[CompilationUnit], diags: &mut Diagnostics, all_names: bool) -> Model {
    let mut a = Analyzer {
        diags,
        model: Model::default(),
        type_names: HashMap::new(),
        pou_names: HashMap::new(),
        enum_values: HashMap::new(),
        free_globals: HashMap::new(),
        pending_aliases: HashMap::new(),
        resolving: Vec::new(),
        silent: false,
        all_names,
        enum_counter: 0,
        alias_chain_reported: false,
        undeclared_at: std::collections::HashSet::new(),
        written_inputs: std::collections::HashSet::new(),
        internal_accessed: std::collections::HashSet::new(),
        operator_functions: [None; 32],
        wide_chars_at: std::collections::HashSet::new(),
        long_strings_at: std::collections::HashSet::new(),
        reinterpreting_pous: std::collections::HashSet::new(),
        declaring_fields: false,
        keyword_parameters: units
            .iter()
            .flat_map(|u| u.keyword_parameters.iter().map(|s| (s.file, s.start)))
            .collect(),
        passing_any_address: false,
        counting_bit_string_pous: std::collections::HashSet::new(),
        integer_bits_pous: std::collections::HashSet::new(),
        loose_enum_pous: std::collections::HashSet::new(),
        loose_enum_inits: std::collections::HashSet::new(),
        copying_instance_pous: std::collections::HashSet::new(),
        unknown_enums: Vec::new(),
        unknown_enum_uses: std::collections::HashSet::new(),
        unknown_types: Vec::new(),
        declared_twice: std::collections::HashSet::new(),
    };
    let pous = a.declare(units);
    // a block holding an instance of itself by value has no size: E1080, the variable cut
    a.check_block_cycles();
    a.check_containment();
    // Room for every instruction's info (and about one name each) at once: no regrowth of big tables.
    let instrs: usize = pous.iter().map(|(_, p)| body::count_instrs(&p.body)).sum();
    a.model.instrs.reserve(instrs);
    if all_names {
        a.model.names.reserve(instrs);
    }
    for (id, pou) in pous {
        a.check_body(id, pou);
    }
    a.report_unknown_enums();
    a.count_unknown_types();
    without_sizes_of_unknown(a.diags);
    a.model
}

/// Leaves out of `diags` each E0022 of `SIZEOF(T)` in a constant expression whose `T` holds a type
/// that an E1003 of `diags` reports declared nowhere (or is that type): the E1003 names the one
/// cause ([`crate::type_sizes::held_unknown`]).
pub fn without_sizes_of_unknown(diags: &mut Diagnostics) {
    let unknown: Vec<String> = diags
        .iter()
        .filter(|d| d.code == code::E1003)
        .filter_map(|d| {
            let rest = d.message.strip_prefix("unknown type `")?;
            rest.split('`').next().map(str::to_string)
        })
        .collect();
    if !unknown.is_empty() {
        diags.retain(|d| {
            d.code != code::E0022
                || !unknown
                    .iter()
                    .any(|u| crate::type_sizes::is_about_unknown(&d.message, u))
        });
    }
}

/// The analysis state shared by the stages.
pub(crate) struct Analyzer<'d> {
    pub(crate) diags: &'d mut Diagnostics,
    pub(crate) model: Model,
    /// Upper-case name -> user type.
    pub(crate) type_names: HashMap<String, TypeId>,
    /// Upper-case name -> POU.
    pub(crate) pou_names: HashMap<String, PouId>,
    /// Upper-case enumerated value -> the enumerations declaring it, with the value's index.
    pub(crate) enum_values: HashMap<String, Vec<(TypeId, usize)>>,
    /// Upper-case name -> index in `Model::globals` (VAR_GLOBAL blocks outside configurations).
    pub(crate) free_globals: HashMap<String, usize>,
    /// Aliases declared but not yet resolved (resolved on first use, so order does not matter).
    pub(crate) pending_aliases: HashMap<TypeId, crate::ast::TypeDecl>,
    /// Aliases being resolved (to report cycles).
    pub(crate) resolving: Vec<TypeId>,
    /// While set, diagnostics are dropped (first pass over a body).
    pub(crate) silent: bool,
    /// Whether [`Model::names`] records every name used in a body, or only a function's own name
    /// used as its result ([`analyze_for_code`]).
    pub(crate) all_names: bool,
    pub(crate) enum_counter: u32,
    /// E0213 (an alias chain longer than `parser::MAX_TYPE_NESTING`) was reported.
    pub(crate) alias_chain_reported: bool,
    /// Where E1001 "undeclared name" was reported (file, start): one ST statement lowered to several
    /// IL instructions (a FOR loop reads its variable four times) reports the name once.
    pub(crate) undeclared_at: std::collections::HashSet<(crate::FileId, u32)>,
    /// (POU, upper-case block type, upper-case variable) whose W1412 was given; (POU, `program P`,
    /// empty) once E1001 reported `P.x` in the POU; (POU, `undeclared X`, empty) once E1001
    /// reported the undeclared name `X` there (its other uses are not reported).
    pub(crate) internal_accessed: std::collections::HashSet<(u32, String, String)>,
    /// The standard function of each simple operator (`ADD` -> ADD), indexed by `Op as usize`, looked
    /// up on first use ([`stdlib::function`] searches the catalogue by name).
    pub(crate) operator_functions: [Option<Option<&'static stdlib::StdFunction>>; 32],
    /// Where W1416 (a STRING literal with a character beyond U+00FF) was reported (file, start): a
    /// literal read twice (an ST statement lowered to several IL instructions) is reported once.
    pub(crate) wide_chars_at: std::collections::HashSet<(crate::FileId, u32)>,
    /// Where W1468 (a `STRING(n)` longer than the 254-character capacity) was reported (file, start):
    /// a declaration's type resolved twice is reported once.
    pub(crate) long_strings_at: std::collections::HashSet<(crate::FileId, u32)>,
    /// The POUs where W1425 (a pointer stored into a pointer to another type) was reported: once
    /// per POU.
    pub(crate) reinterpreting_pous: std::collections::HashSet<PouId>,
    /// While set, [`Analyzer::declare_vars`] declares a structure's fields: a field may be named
    /// with a keyword (`Continue : BOOL;`, B&R and CODESYS before edition 3), read only after `.`.
    pub(crate) declaring_fields: bool,
    /// The places (file, start) of the variables of declaration-only blocks (B&R's `.fun` files)
    /// named with a keyword (`Type : USINT;`): accepted, as structure fields are.
    pub(crate) keyword_parameters: std::collections::HashSet<(diagnostics::FileId, u32)>,
    /// The argument being checked is the hidden address of an ANY input (`In__PVALUE`,
    /// `crate::st::any_inputs`): a `POINTER TO BYTE` to any argument by design, no W1425.
    pub(crate) passing_any_address: bool,
    /// The POUs where W1436 (a bit string counted as an unsigned integer) was reported: once per
    /// POU.
    pub(crate) counting_bit_string_pous: std::collections::HashSet<PouId>,
    /// The POUs where W1438 (an integer used as a bit string) was reported: once per POU.
    pub(crate) integer_bits_pous: std::collections::HashSet<PouId>,
    /// The POUs where W1439 (an enumeration used as an integer) was reported: once per POU.
    pub(crate) loose_enum_pous: std::collections::HashSet<PouId>,
    /// The enumerations whose W1439 for an integer initial value was reported: once each.
    pub(crate) loose_enum_inits: std::collections::HashSet<TypeId>,
    /// The POUs where W1437 (an FB instance copied whole) was reported: once per POU.
    pub(crate) copying_instance_pous: std::collections::HashSet<PouId>,
    /// The declarations of the inputs whose W1411 (written inside their POU) was reported: once per
    /// input, at its first write.
    pub(crate) written_inputs: std::collections::HashSet<crate::Span>,
    /// The unknown enumerations named in `Type#Value` (upper-case name, as written, first use, how
    /// many other uses): one E1001 each at its first use, the other uses counted in its message
    /// ([`Analyzer::report_unknown_enums`], once every body is checked).
    pub(crate) unknown_enums: Vec<(String, String, crate::Span, usize)>,
    /// The uses counted in `unknown_enums` (file, start): one ST statement lowered to several IL
    /// instructions counts once.
    pub(crate) unknown_enum_uses: std::collections::HashSet<(crate::FileId, u32)>,
    /// The unknown types of declarations (upper-case name, the E1003's span, the other uses): one
    /// E1003 per name at its first use, its message counting the uses as the PLCopen XML reader's
    /// E3009 does ([`Analyzer::count_unknown_types`]).
    pub(crate) unknown_types: Vec<(String, crate::Span, Vec<crate::Span>)>,
    /// The POU and type names declared more than once (upper case), each an E1002: a call of
    /// such a function (SIMATIC AX overloads `CountDigits(LINT)` and `CountDigits(ULINT)`) is not
    /// checked against the one declaration kept, the E1002 is its cause.
    pub(crate) declared_twice: std::collections::HashSet<String>,
}

impl Analyzer<'_> {
    /// The E1003 of an unknown type used by several declarations says how many (`(3 uses)`), with
    /// a label at each other use (which reported nothing).
    fn count_unknown_types(&mut self) {
        for (_, first, others) in std::mem::take(&mut self.unknown_types) {
            if others.is_empty() {
                continue;
            }
            self.diags.update(|d| {
                if d.code == code::E1003 && d.span == Some(first) && !d.message.ends_with(" uses)")
                {
                    d.message = format!("{} ({} uses)", d.message, others.len() + 1);
                    for s in &others {
                        d.labels.push(diagnostics::Label {
                            span: *s,
                            message: "also used here".into(),
                        });
                    }
                }
            });
        }
    }

    /// One E1001 per unknown enumeration of `Type#Value` (a vendor library's `ReadArea#Output`
    /// used 8 times is one cause), at its first use, its message counting the other uses.
    fn report_unknown_enums(&mut self) {
        for (_, name, span, others) in std::mem::take(&mut self.unknown_enums) {
            let message = match others {
                0 => format!("unknown enumeration `{name}`"),
                1 => format!("unknown enumeration `{name}` (used once more, not reported)"),
                n => format!("unknown enumeration `{name}` (used {n} more times, not reported)"),
            };
            self.error(code::E1001, span, message)
                .label("no such type")
                .hint(
                    "declare it in a TYPE block (or give the library that declares it with --lib)",
                );
        }
    }
    pub(crate) fn error(
        &mut self,
        code: Code,
        span: crate::Span,
        message: impl Into<String>,
    ) -> Diag<'_> {
        let d = (!self.silent).then(|| Diagnostic::error(code, message).at(span));
        Diag {
            sink: self.diags,
            d,
        }
    }
    pub(crate) fn warning(
        &mut self,
        code: Code,
        span: crate::Span,
        message: impl Into<String>,
    ) -> Diag<'_> {
        let d = (!self.silent).then(|| Diagnostic::warning(code, message).at(span));
        Diag {
            sink: self.diags,
            d,
        }
    }
    /// W1416 when the single-byte STRING literal `lit` holds a character beyond U+00FF (stored as
    /// `?`, as the C holds a STRING's characters one byte each, ISO 8859-1); once per literal.
    pub(crate) fn check_single_byte(&mut self, lit: &crate::ast::Literal) {
        let crate::ast::LiteralKind::String { wide: false, value } = &lit.kind else {
            return;
        };
        let Some((first, count)) = typing::beyond_single_byte(value) else {
            return;
        };
        if self.silent || !self.wide_chars_at.insert((lit.span.file, lit.span.start)) {
            return;
        }
        let message = if count > 1 {
            format!(
                "`{first}` (U+{:04X}) and {} more characters are not single-byte characters (a STRING holds ISO 8859-1, U+0000-U+00FF): each is stored as `?`",
                u32::from(first),
                count - 1
            )
        } else {
            format!(
                "`{first}` (U+{:04X}) is not a single-byte character (a STRING holds ISO 8859-1, U+0000-U+00FF): it is stored as `?`",
                u32::from(first)
            )
        };
        drop(
            self.warning(code::W1416, lit.span, message)
            .label("STRING literal")
            .hint("write the text as a WSTRING literal in double quotes (\"...\") into a WSTRING variable, or keep STRING text to the characters U+0000-U+00FF ($hh escapes)"),
        );
    }
    pub(crate) fn type_name(&self, ty: &Type) -> String {
        self.model.type_name(ty)
    }
}

/// A diagnostic under construction; pushed when dropped, unless it repeats one of the last
/// [`RECENT`] pushed (a declaration of several names, `p1, p2 : UnknownType := (x := 1)`, resolves
/// its type and its initial value once per name: one diagnostic, not one per name at the same place).
pub(crate) struct Diag<'a> {
    sink: &'a mut Diagnostics,
    d: Option<Diagnostic>,
}

impl Diag<'_> {
    pub(crate) fn label(mut self, m: impl Into<String>) -> Self {
        self.d = self.d.take().map(|d| d.with_primary_label(m));
        self
    }
    pub(crate) fn also(mut self, span: crate::Span, m: impl Into<String>) -> Self {
        self.d = self.d.take().map(|d| d.with_label(span, m));
        self
    }
    pub(crate) fn hint(mut self, m: impl Into<String>) -> Self {
        self.d = self.d.take().map(|d| d.with_hint(m));
        self
    }
}

/// How many of the diagnostics pushed last a new one is compared with (bounded, so that a file with
/// many errors costs no quadratic time).
const RECENT: usize = 32;

impl Drop for Diag<'_> {
    fn drop(&mut self) {
        if let Some(mut d) = self.d.take() {
            // the user's names, not the hidden ones of methods' variables (`Take.o`, not
            // `__M_TAKE_O`): a default's message then equals its variable's, and is not repeated
            crate::actions::show_user_names(&mut d);
            if !self.sink.iter().rev().take(RECENT).any(|p| *p == d) {
                self.sink.push(d);
            }
        }
    }
}
