//! Textual IEC 61131-3 source files: which language a file and each POU body is written in, and the
//! reading of Structured Text files (`.st`: POUs, TYPE, CONFIGURATION as matiec, RuSTy and IronPLC read
//! them), whose bodies may each be ST or IL.
//!
//! Input: a file's text. Output: a [`CompilationUnit`] whose declarations were parsed by the IL parser
//! (the declaration syntax is the same in both languages) and whose ST bodies are lowered to IL by
//! [`compile_pending`] once every unit's declarations are known (an ST body may call a FUNCTION of
//! another file). Invariants: a body is scanned once; the text the IL parser reads has the same length
//! and line structure as the file (ST bodies and pragmas are blanked, not removed), so every span is a
//! position in the file; an IL file holding ST gets one E0300, not one error per line.

use super::lexer::{lex, pragma_diagnostic, Kw, Problem, Tok, Token};
use crate::ast::{CompilationUnit, LibraryElement};
use crate::{FileId, Span};
use diagnostics::{code, Diagnostic, Diagnostics, Severity};
use std::ops::Range;

pub use super::list_bounds::library_qualified_bound;
use super::qualifiers::library_qualifiers;
pub use super::qualifiers::PROVIDED_LIBRARIES;
use super::refs::RefTypes;
use super::var_config::var_config_blocks;
pub use super::var_config::{apply_var_config, ConfigEntry};

/// The language a source text is read in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lang {
    /// IEC 61131-3 Instruction List (`.il` files, `LD`/`ST` bodies).
    Il,
    /// IEC 61131-3 Structured Text (`.st` files, `:=` / `IF` bodies).
    St,
    /// A PLCopen TC6 XML project (`.xml`).
    Xml,
}

impl Lang {
    /// The language's name for messages (`Structured Text (ST)`).
    pub fn name(self) -> &'static str {
        match self {
            Lang::Il => "instruction list (IL)",
            Lang::St => "Structured Text (ST)",
            Lang::Xml => "PLCopen XML",
        }
    }
}

/// A POU found in the text: its keyword, name and body range (between its declarations and its
/// `END_...`), and the language the body is written in.
#[derive(Debug, Clone)]
pub struct PouText {
    /// The POU's name as written.
    pub name: String,
    /// Byte range of the name.
    pub name_range: Range<usize>,
    /// Byte range of the body: after the declarations, up to the `END_*` keyword.
    pub body: Range<usize>,
    /// The body's language: ST when its ST statements outnumber the lines that start like IL instructions.
    pub lang: Lang,
    /// The `INITIAL_STEP` (or first `STEP name :`) of a body in textual SFC (lowered by the caller:
    /// [`PendingBody::sfc`]).
    pub sfc: Option<Range<usize>>,
    /// The first `PROPERTY name` of a body that is not a function block's property (a PROGRAM's),
    /// or `METHOD name` outside a function block (edition 3 object orientation not supported: E0303).
    pub oop: Option<Range<usize>>,
    /// The `METHOD ... END_METHOD` blocks of a function block (edition 3, without inheritance):
    /// compiled as actions with inputs, outputs and a result ([`MethodText`]).
    pub methods: Vec<MethodText>,
    /// The `PROPERTY ... END_PROPERTY` blocks of a function block: their accessors are compiled as
    /// methods ([`super::property`]).
    pub properties: Vec<super::property::PropertyText>,
    /// Not a POU: a CODESYS/RuSTy `ACTIONS ... END_ACTIONS` block (the `ACTIONS` keyword; `body` is
    /// the whole block). Its actions belong to the POU before it (see [`PouText::action_list`]).
    pub actions: Option<Range<usize>>,
    /// The `ACTION name [:] ... END_ACTION` of an `ACTIONS` block: name and its range, text range.
    pub action_list: Vec<(String, Range<usize>, Range<usize>)>,
    /// A modifier between `FUNCTION_BLOCK` and the name (`PUBLIC`, `INTERNAL`, `FINAL`,
    /// `ABSTRACT`: CODESYS and edition 3), skipped with W0304.
    pub modifier: Option<Range<usize>>,
    /// The `EXTENDS base` / `IMPLEMENTS itf` clause after the name (edition 3 inheritance, read by
    /// [`super::inherit`]); for an INTERFACE its `EXTENDS` clause.
    pub heritage: Option<Range<usize>>,
    /// The `;` that ends a POU's header (`FUNCTION F : BOOL;`, accepted by TwinCAT): blanked for
    /// the declarations' reader.
    pub header_semi: Option<Range<usize>>,
    /// Not a POU: an `INTERFACE name ... END_INTERFACE` block (edition 3: its methods are in
    /// `methods`, checked against the blocks that implement it; `body` is the whole block).
    pub interface: Option<Range<usize>>,
    /// A `CLASS ... END_CLASS` (edition 3, 6.6.5): read as a function block without a body, the
    /// range of its `CLASS` keyword (`st::classes`).
    pub class: Option<Range<usize>>,
}

/// One `METHOD [modifiers] Name [: Type] <VAR blocks> <statements> END_METHOD` of a function block.
#[derive(Debug, Clone)]
pub struct MethodText {
    /// The method's name as written.
    pub name: String,
    /// Byte range of the name.
    pub name_range: Range<usize>,
    /// End of the result type after `Name :` (`None`: the method returns nothing).
    pub ret_end: Option<usize>,
    /// Byte range of its variable blocks (empty when it has none).
    pub decls: Range<usize>,
    /// Byte range of its statements.
    pub stmts: Range<usize>,
    /// Byte range of the whole block, `METHOD` to `END_METHOD`.
    pub whole: Range<usize>,
    /// Its access specifier between `METHOD` and the name (none: PUBLIC).
    pub access: Option<crate::ast::Access>,
}

/// A method of a function block read from an ST file, waiting to be lowered with its block
/// ([`compile_pending`]).
#[derive(Debug, Clone)]
pub struct PendingMethod {
    /// The method's name.
    pub name: crate::ast::Ident,
    /// Its result (a variable named like the method), if it returns one.
    pub ret: Option<crate::ast::VarDecl>,
    /// Its VAR_INPUT, VAR_OUTPUT, VAR, VAR_TEMP and VAR_INST blocks (a VAR_INST block is read as
    /// a `VAR` block; its variables are in [`Self::inst`]).
    pub blocks: Vec<crate::ast::VarBlock>,
    /// Its statements' text and their offset in the file.
    pub text: String,
    /// Byte offset of `text` in the file.
    pub base: usize,
    /// The variables of its VAR_INST blocks (upper-case; TwinCAT): kept in the instance from call
    /// to call, where its other variables start again at each call.
    pub inst: Vec<String>,
    /// The byte ranges (in the file) of the assignments, among the statements, that give VAR_INST
    /// variables an initial value computed at run time (`pSelf : POINTER TO FB_X := THIS;`,
    /// `n : INT := THIS^.nBase;`, TwinCAT): run once per instance, at the method's first call
    /// (`method_inits`).
    pub once: Vec<Range<usize>>,
    /// The FB_init arguments of its own VAR / VAR_TEMP instances (`p : Randomizer(dist);`):
    /// CODESYS creates such an instance again at each call of the method, FB_init included, so
    /// the method starts with `p.FB_init(TRUE, FALSE, dist)` ([`lower_method`]).
    pub local_inits: Vec<super::fb_init_args::DeclArgs>,
    /// Declared `PRIVATE` or `PROTECTED` (see [`crate::ast::Action::access`]).
    pub access: Option<crate::ast::MemberAccess>,
    /// Its block declares another METHOD of its name after it (SIMATIC AX's overloading by
    /// parameters; one E1084 at the second, this first one kept): the IMPLEMENTS check does not
    /// compare it with the interface's, which may declare the other overload (one cause, one
    /// error).
    pub overloaded: bool,
}

/// An ST body waiting for the program's declarations: the POU (by the start of its name) and its text.
#[derive(Debug, Clone)]
pub struct PendingBody {
    /// The file the body is in.
    pub file: FileId,
    /// Byte offset of the POU's name (identifies the POU in the parsed unit).
    pub name_start: usize,
    /// Byte offset of `text` in the file (spans of the lowered IL point into the file).
    pub base: usize,
    /// The body's text.
    pub text: String,
    /// The POU's actions (an `ACTIONS` block after it): name, text, offset of the text.
    pub actions: Vec<(crate::ast::Ident, String, usize)>,
    /// The body is textual SFC ([`super::sfc`]): [`compile_pending`] leaves it to the SFC lowering of
    /// the caller (ladder-compiler's `sfc::text`).
    pub sfc: bool,
    /// The body is instruction list, parsed with the file's IL (an `.st` file may hold IL bodies):
    /// [`compile_pending`] keeps it, lowers only the actions (`actions`, each in ST or IL) and puts
    /// a copy of each where the body calls it (`CAL Act`).
    pub il: bool,
    /// The methods of a function block (see [`crate::actions`]: each runs, when called through an
    /// instance, as an action with hidden inputs and outputs `__M_<METHOD>_<var>` and result
    /// `__M_<METHOD>`).
    pub methods: Vec<PendingMethod>,
    /// Edition 3 object orientation: the block's `EXTENDS` / `IMPLEMENTS` / `FINAL` / `ABSTRACT`,
    /// or (with an empty `text`) an `INTERFACE` ([`super::inherit`] flattens and checks them before
    /// the bodies are lowered).
    pub oop: Option<Box<super::inherit::Oop>>,
    /// The FB_init arguments of the file's instance declarations (`fb : FB_X(n := 1)`), carried
    /// by one body of the file that is no POU's (`name_start` is `usize::MAX`, no text): matched
    /// with the blocks' FB_init inputs by [`super::fb_init`] once every file is read.
    pub fb_init_args: Vec<super::fb_init_args::DeclArgs>,
    /// The methods that `{attribute 'call_after_init'}` marks (on the method and on the block):
    /// run after each instance's FB_init ([`super::fb_init`]).
    pub after_init: Vec<crate::ast::Ident>,
    /// Not a POU's body: the methods (in `methods`) of a file that holds them without their block,
    /// `Block.Method.st` ([`super::lone_members`]), until they are attached to it.
    pub lone: Option<Box<super::lone_members::LoneMembers>>,
    /// The run-time initial values of the POU's own VAR / VAR_TEMP variables (a function called:
    /// `n : UDINT := MIN(250000, k / 25);`, CODESYS and TwinCAT), as assignments where they are
    /// written, and the text's offset in the file (`st::pou_inits`):
    /// run before the instance's FB_init and, where that does not reach, when the POU first runs.
    /// A derived block's list starts with its bases' ([`super::inherit`]), root first, each in
    /// its file.
    pub var_inits: Vec<VarInits>,
}

/// A POU's run-time initial values (`PendingBody::var_inits`): its file, the assignments (a text
/// of the declarations' length), the text's offset in the file, and the assignments of the
/// computed fields of structured initial values with the instance to put before their targets
/// (`pou_inits::prefix_fields`).
pub type VarInits = (
    FileId,
    String,
    usize,
    Vec<(Range<usize>, super::init_fields::InitTarget)>,
);

impl PendingBody {
    /// A body with no text, no action, method or FB_init argument, at `name_start` of `file`
    /// (`usize::MAX`: no POU's; the caller fills what it carries).
    pub fn empty(file: FileId, name_start: usize) -> Self {
        PendingBody {
            file,
            name_start,
            base: 0,
            text: String::new(),
            actions: Vec::new(),
            sfc: false,
            il: false,
            methods: Vec::new(),
            oop: None,
            fb_init_args: Vec::new(),
            after_init: Vec::new(),
            lone: None,
            var_inits: Vec::new(),
        }
    }

    /// The POU this body belongs to, found among `units` by its file and the start of its name;
    /// `None` for a body that is no POU's or one not in `units`.
    pub fn pou<'u>(&self, units: &'u [crate::ast::CompilationUnit]) -> Option<&'u crate::ast::Pou> {
        units
            .iter()
            .flat_map(|u| u.items.iter())
            .find_map(|i| match i {
                LibraryElement::Pou(p)
                    if p.name.span.file == self.file
                        && p.name.span.start as usize == self.name_start =>
                {
                    Some(p)
                }
                _ => None,
            })
    }

    /// The name of the POU this body belongs to ([`Self::pou`]).
    pub fn pou_name<'u>(
        &self,
        units: &'u [crate::ast::CompilationUnit],
    ) -> Option<&'u crate::ast::Ident> {
        self.pou(units).map(|p| &p.name)
    }
}

impl PendingBody {
    /// The body of a block that EXTENDS another (flattened by [`super::inherit`]).
    pub fn derived(&self) -> bool {
        matches!(self.oop.as_deref(), Some(super::inherit::Oop::Block(b)) if !b.extends.is_empty())
    }

    /// The file of method `k` (an inherited method is in its base's file).
    pub fn method_file(&self, k: usize) -> FileId {
        match self.oop.as_deref() {
            Some(super::inherit::Oop::Block(b)) if !b.method_files.is_empty() => {
                b.method_files.get(k).copied().unwrap_or(self.file)
            }
            // (a method exported to a file of its own is in that file: `lone_members`)
            _ => self.methods.get(k).map_or(self.file, |m| m.name.span.file),
        }
    }
}

/// IL operators (and the `&` forms): a line starting with one of these is an IL instruction.
const IL_OPS: &[&str] = &[
    "LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN", "OR", "ORN", "XOR", "XORN", "NOT", "ADD",
    "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT", "JMP", "JMPC", "JMPCN", "CAL",
    "CALC", "CALCN", "RET", "RETC", "RETCN",
];

pub(super) fn word<'a>(src: &'a str, t: &Token) -> &'a str {
    src.get(t.range.clone()).unwrap_or("")
}

pub(super) fn is_word(src: &str, t: &Token, w: &str) -> bool {
    matches!(t.tok, Tok::Ident | Tok::Kw(_)) && word(src, t).eq_ignore_ascii_case(w)
}

/// `VAR`, `VAR_INPUT` ... (upper-case): a variable block starts.
pub(super) fn is_var_keyword(w: &str) -> bool {
    matches!(
        w,
        "VAR"
            | "VAR_INPUT"
            | "VAR_OUTPUT"
            | "VAR_IN_OUT"
            | "VAR_TEMP"
            | "VAR_EXTERNAL"
            | "VAR_GLOBAL"
            | "VAR_ACCESS"
            | "VAR_CONFIG"
            | "VAR_INST"
            | "VAR_STAT"
            // TwinCAT's generic constants (`generic_constants`: read as VAR)
            | "VAR_GENERIC"
    )
}

/// Finds the POUs of a text and the language of each body.
pub fn scan(src: &str) -> Vec<PouText> {
    let (toks, _) = lex(src);
    scan_tokens(src, &toks).0
}

/// The POUs of a text (see [`scan`]) and the indexes of the tokens outside every POU, TYPE,
/// CONFIGURATION, RESOURCE, ACTIONS, INTERFACE and VAR block.
fn scan_tokens(src: &str, toks: &[Token]) -> (Vec<PouText>, Vec<usize>) {
    let mut out = Vec::new();
    let mut stray = Vec::new();
    let mut i = 0;
    let n = toks.len();
    // Skips to just after the token `end` (case-insensitive), from `i`.
    let skip_to = |mut i: usize, end: &str| {
        while i < n && !matches!(toks[i].tok, Tok::Eof) && !is_word(src, &toks[i], end) {
            i += 1;
        }
        (i + 1).min(n)
    };
    // `ACTION name [:] ... END_ACTION` from the token `k` (`ACTION`), ending by `limit` at the
    // latest: the action (its name, the name's range, its text's range) and the token after
    // its END_ACTION
    let one_action = |k: usize, limit: usize| {
        let name_tok = &toks[k + 1];
        let mut b = k + 2;
        if toks.get(b).is_some_and(|t| t.tok == Tok::Colon) {
            b += 1;
        }
        let text_start = toks[b - 1].range.end;
        let e = skip_to(b, "END_ACTION").min(limit);
        let text_end = toks[e - 1].range.start.max(text_start);
        let action = (
            word(src, name_tok).to_string(),
            name_tok.range.clone(),
            text_start..text_end,
        );
        (action, e)
    };
    while i < n && !matches!(toks[i].tok, Tok::Eof) {
        let t = &toks[i];
        let w = word(src, t).to_ascii_uppercase();
        // a block keyword after a word of stray text on the same line (`this function adds one`,
        // `on an external var of type byte`: PC WORX writes a POU's description as bare text) is
        // one more word of that text, not the start of a block that would swallow the POU after it
        if i > 0
            && stray.last() == Some(&(i - 1))
            && toks[i - 1].tok != Tok::Semi
            && !src
                .get(toks[i - 1].range.end..t.range.start)
                .unwrap_or("\n")
                .contains('\n')
            && super::stray_text::is_block_keyword(&w)
        {
            stray.push(i);
            i += 1;
            continue;
        }
        match w.as_str() {
            "TYPE" => i = skip_to(i + 1, "END_TYPE"),
            // a block `CONFIGURATION c`; a variable so named (`Configuration := 40`, TwinCAT:
            // W1418) is followed by no name
            "CONFIGURATION" | "RESOURCE"
                if !toks
                    .get(i + 1)
                    .is_some_and(|t| matches!(t.tok, Tok::Ident | Tok::Kw(_))) =>
            {
                i += 1
            }
            "CONFIGURATION" => i = skip_to(i + 1, "END_CONFIGURATION"),
            "RESOURCE" => i = skip_to(i + 1, "END_RESOURCE"),
            "ACTIONS" => {
                let start = t.range.clone();
                let j = skip_to(i + 1, "END_ACTIONS");
                let end = toks[j - 1].range.end;
                let mut action_list = Vec::new();
                let mut k = i + 1;
                while k < j {
                    if is_word(src, &toks[k], "ACTION")
                        && toks.get(k + 1).is_some_and(|t| t.tok == Tok::Ident)
                    {
                        let (action, e) = one_action(k, j);
                        action_list.push(action);
                        k = e;
                    } else {
                        k += 1;
                    }
                }
                out.push(actions_text("ACTIONS", start, end, action_list));
                i = j;
            }
            // `ACTION Name : ... END_ACTION` outside any POU and any ACTIONS block: a B&R
            // Automation Studio program's actions file (or actions after their POU): one text
            // named `ACTION` holding each action of the run
            "ACTION" if toks.get(i + 1).is_some_and(|t| t.tok == Tok::Ident) => {
                let start = t.range.clone();
                let mut action_list = Vec::new();
                let mut k = i;
                let mut end = start.end;
                while k < n
                    && is_word(src, &toks[k], "ACTION")
                    && toks.get(k + 1).is_some_and(|t| t.tok == Tok::Ident)
                {
                    let (action, e) = one_action(k, n);
                    action_list.push(action);
                    end = toks[e - 1].range.end;
                    k = e;
                    // `END_ACTION;`
                    if toks.get(k).is_some_and(|t| t.tok == Tok::Semi) {
                        end = toks[k].range.end;
                        k += 1;
                    }
                }
                out.push(actions_text("ACTION", start, end, action_list));
                i = k;
            }
            "INTERFACE" if toks.get(i + 1).is_some_and(|t| t.tok == Tok::Ident) => {
                let start = t.range.clone();
                let name_tok = &toks[i + 1];
                let j = skip_to(i + 2, "END_INTERFACE");
                let end = toks[j - 1].range.end;
                // `INTERFACE I EXTENDS I0, I1`: the clause up to the first METHOD (or the end)
                let inner = &toks[(i + 2).min(j)..j.saturating_sub(1).max(i + 2).min(n)];
                let heritage = inner
                    .first()
                    .filter(|t| is_word(src, t, "EXTENDS"))
                    .map(|t| {
                        let last = inner
                            .iter()
                            .take_while(|t| {
                                !is_word(src, t, "METHOD") && !is_word(src, t, "PROPERTY")
                            })
                            .last()
                            .map_or(t.range.end, |l| l.range.end);
                        t.range.start..last
                    });
                out.push(PouText {
                    name: word(src, name_tok).to_string(),
                    name_range: name_tok.range.clone(),
                    body: start.start..end,
                    lang: Lang::Il,
                    sfc: None,
                    oop: None,
                    methods: scan_methods(src, inner),
                    // `PROPERTY P : T GET END_GET SET END_SET END_PROPERTY`: the accessors a
                    // block that implements it must have, called through interface variables
                    properties: super::property::scan_properties(src, inner),
                    actions: None,
                    action_list: Vec::new(),
                    modifier: None,
                    heritage,
                    header_semi: None,
                    interface: Some(start.start..name_tok.range.end),
                    class: None,
                });
                i = j;
            }
            _ if is_var_keyword(&w) => i = skip_to(i + 1, "END_VAR"),
            "PROGRAM" | "FUNCTION" | "FUNCTION_BLOCK" | "CLASS"
                if w != "CLASS" || toks.get(i + 1).is_some_and(|t| t.tok == Tok::Ident) =>
            {
                let end_word = format!("END_{w}");
                // `CLASS Name ... END_CLASS`: a function block without a body (`classes`)
                let class = (w == "CLASS").then(|| t.range.clone());
                let w = if class.is_some() {
                    "FUNCTION_BLOCK".to_string()
                } else {
                    w
                };
                i += 1;
                // `FUNCTION_BLOCK PUBLIC FB_Brake` (CODESYS access specifier; FINAL and ABSTRACT of
                // edition 3), `PROGRAM INTERNAL MAIN` (TwinCAT): the modifier is not the name
                let modifiers: &[&str] = if w == "FUNCTION_BLOCK" {
                    &["PUBLIC", "INTERNAL", "FINAL", "ABSTRACT"]
                } else {
                    // `FUNCTION INTERNAL Integrate` (TwinCAT, stefanbesler/struckig)
                    &["PUBLIC", "INTERNAL"]
                };
                // several in a row (`FUNCTION_BLOCK INTERNAL ABSTRACT FB_Enumerator`, TwinCAT,
                // fisothemes/TwinCat-Dynamic-Collections): one range over all of them
                let mut modifier: Option<Range<usize>> = None;
                while toks.get(i + 1).is_some_and(|t| {
                    let next = word(src, t).to_ascii_uppercase();
                    t.tok == Tok::Ident
                        && !is_var_keyword(&next)
                        && ![
                            "END_FUNCTION_BLOCK",
                            "END_PROGRAM",
                            "END_FUNCTION",
                            "EXTENDS",
                            "IMPLEMENTS",
                        ]
                        .contains(&next.as_str())
                }) && toks
                    .get(i)
                    .is_some_and(|t| modifiers.iter().any(|k| is_word(src, t, k)))
                {
                    let r = toks[i].range.clone();
                    modifier = Some(modifier.map_or(r.clone(), |m| m.start..r.end));
                    i += 1;
                }
                let Some(name_tok) = toks.get(i).filter(|t| t.tok == Tok::Ident) else {
                    continue;
                };
                // `... of this function` then `FUNCTION Twice : INT`: a word of stray text before
                // a POU is no POU whose name is the next POU's keyword
                if ["PROGRAM", "FUNCTION", "FUNCTION_BLOCK"]
                    .iter()
                    .any(|k| is_word(src, name_tok, k))
                {
                    stray.push(i - 1);
                    continue;
                }
                let name = word(src, name_tok).to_string();
                let name_range = name_tok.range.clone();
                i += 1;
                // FUNCTION f : TYPE (STRING[20], ARRAY [..] OF T); FUNCTION_BLOCK fb EXTENDS b.
                if w == "FUNCTION" && toks.get(i).is_some_and(|t| t.tok == Tok::Colon) {
                    i += 1;
                    // (`ARRAY [..] OF ARRAY [..] OF T`: past each ARRAY's OF, to the element type)
                    while toks.get(i).is_some_and(|t| is_word(src, t, "ARRAY")) {
                        i = skip_to(i, "OF");
                    }
                    i += 1;
                    if let Some(open) = toks.get(i).map(|t| t.tok.clone()) {
                        let close = match open {
                            Tok::LBracket => Some(Tok::RBracket),
                            Tok::LParen => Some(Tok::RParen),
                            _ => None,
                        };
                        if let Some(c) = close {
                            while i < n && toks[i].tok != c && toks[i].tok != Tok::Eof {
                                i += 1;
                            }
                            i += 1;
                        }
                    }
                }
                // `FUNCTION F_SetStateParams : BOOL;` (TwinCAT accepts the `;` after the header,
                // pcdshub's lcls-twincat-motion): the header ends there
                let header_semi = toks
                    .get(i)
                    .filter(|t| t.tok == Tok::Semi)
                    .map(|t| t.range.clone());
                if header_semi.is_some() {
                    i += 1;
                }
                // the EXTENDS / IMPLEMENTS clause after the name, or after the block of generic
                // constants, where TwinCAT writes it (`FUNCTION_BLOCK Trace VAR_GENERIC CONSTANT
                // ... END_VAR IMPLEMENTS I_Trace`, read as a VAR block: `generic_constants`)
                let clause = |i: usize| {
                    toks.get(i).is_some_and(|t| {
                        ["EXTENDS", "IMPLEMENTS"].iter().any(|k| is_word(src, t, k))
                    })
                };
                let mut heritage = None;
                let mut body_start = 0;
                for _ in 0..2 {
                    let heritage_start = toks.get(i).map(|t| t.range.start);
                    while i < n && clause(i) {
                        // names, also qualified by a library's namespace (`TcUnit.FB_TestSuite`)
                        let name_end = |mut i: usize| {
                            while toks.get(i).is_some_and(|t| t.tok == Tok::Dot)
                                && toks.get(i + 1).is_some_and(|t| t.tok == Tok::Ident)
                            {
                                i += 2;
                            }
                            i
                        };
                        // `FUNCTION_BLOCK FB_T EXTENDS` then `VAR_INPUT` (the base's name left out,
                        // PeterZerlauth/Tc3_Component): the clause is the keyword alone, the VAR
                        // block stays a VAR block, and `inherit` says the name is missing
                        let named = toks.get(i + 1).is_some_and(|t| {
                            t.tok == Tok::Ident
                                && !is_var_keyword(&word(src, t).to_ascii_uppercase())
                                && !is_word(src, t, &end_word)
                                && !clause(i + 1)
                        });
                        i = if named { name_end(i + 2) } else { i + 1 };
                        while toks.get(i).is_some_and(|t| t.tok == Tok::Comma) {
                            i = name_end(i + 2);
                        }
                        // `IMPLEMENTS I_HMI;` (TwinCAT accepts the `;`): part of the clause
                        if toks.get(i).is_some_and(|t| t.tok == Tok::Semi) {
                            i += 1;
                        }
                        heritage = heritage_start
                            .zip(toks.get(i.min(n) - 1))
                            .map(|(s, t)| s..t.range.end);
                    }
                    body_start = toks.get(i.saturating_sub(1)).map_or(0, |t| t.range.end);
                    while i < n && is_var_keyword(&word(src, &toks[i]).to_ascii_uppercase()) {
                        i = skip_to(i + 1, "END_VAR");
                        body_start = toks.get(i.saturating_sub(1)).map_or(0, |t| t.range.end);
                    }
                    if heritage.is_some() || !clause(i) {
                        break;
                    }
                }
                let first = i.min(n - 1);
                let mut j = i;
                while j < n
                    && !matches!(toks[j].tok, Tok::Eof)
                    && !is_word(src, &toks[j], &end_word)
                {
                    j += 1;
                }
                let body_end = toks[j.min(n - 1)].range.start;
                let body_start = body_start.min(body_end);
                // `INITIAL_STEP`, or `STEP name :` (a chart without its initial step is still a chart)
                let body_toks = &toks[first..j.min(n - 1)];
                let sfc = body_toks
                    .iter()
                    .find(|t| is_word(src, t, "INITIAL_STEP"))
                    .or_else(|| {
                        body_toks
                            .windows(3)
                            .find(|w| {
                                is_word(src, &w[0], "STEP")
                                    && w[1].tok == Tok::Ident
                                    && w[2].tok == Tok::Colon
                            })
                            .map(|w| &w[0])
                    })
                    .map(|t| t.range.clone());
                let body_toks = &toks[first..j.min(n - 1)];
                // (a PROGRAM's methods and properties too, CODESYS and TwinCAT: `PRG.M(x)` from
                // another POU runs on the program's one instance, see `crate::actions`)
                let (methods, properties) = if w == "FUNCTION_BLOCK" || w == "PROGRAM" {
                    (
                        scan_methods(src, body_toks),
                        super::property::scan_properties(src, body_toks),
                    )
                } else {
                    (Vec::new(), Vec::new())
                };
                let oop = body_toks
                    .windows(2)
                    .find(|w| {
                        ((is_word(src, &w[0], "METHOD") && methods.is_empty())
                            || (is_word(src, &w[0], "PROPERTY")
                                && !properties
                                    .iter()
                                    .any(|p| p.whole.contains(&w[0].range.start))))
                            && w[1].tok == Tok::Ident
                    })
                    .map(|w| w[0].range.clone());
                out.push(PouText {
                    name,
                    name_range,
                    body: body_start..body_end,
                    lang: body_lang(src, &toks[first..j.min(n - 1)]),
                    sfc,
                    oop,
                    methods,
                    properties,
                    actions: None,
                    action_list: Vec::new(),
                    modifier,
                    heritage,
                    header_semi,
                    interface: None,
                    class,
                });
                i = j + 1;
            }
            _ => {
                stray.push(i);
                i += 1;
            }
        }
    }
    (out, stray)
}

/// The pending methods of POU `p`'s methods and properties' accessors (declarations read, their
/// `VAR_STAT` blocks named, their reference types applied) pushed on `methods`, each cut out of
/// `body` (blanked: positions stay); `(method_diags, diags)`: where a method's and a property's
/// diagnostics go (a derived block's methods are reported once its base is found).
fn pending_members(
    (file, src, p, stat_at): (FileId, &str, &PouText, &[usize]),
    references: &mut RefTypes,
    body: &mut String,
    methods: &mut Vec<PendingMethod>,
    (method_diags, diags): (&mut Diagnostics, &mut Diagnostics),
) {
    let owned = |access: Option<crate::ast::Access>, member: &str, at: Range<usize>, what| {
        access.map(|access| crate::ast::MemberAccess {
            access,
            owner: p.name.to_ascii_uppercase(),
            owner_name: p.name.clone(),
            member: member.to_string(),
            at: Span::new(file, at.start, at.end),
            what,
        })
    };
    for (k, m) in p.methods.iter().enumerate() {
        // a second METHOD of the same name (SIMATIC AX's overloading): one E1084, the first kept
        if let Some(first) = p.methods[..k]
            .iter()
            .find(|o| o.name.eq_ignore_ascii_case(&m.name))
        {
            diags.push(
                Diagnostic::error(
                    code::E1084,
                    format!("`{}` declares METHOD `{}` twice", p.name, m.name),
                )
                .at(Span::new(file, m.name_range.start, m.name_range.end))
                .with_primary_label("second METHOD of this name")
                .with_label(
                    Span::new(file, first.name_range.start, first.name_range.end),
                    "first declared here",
                )
                .with_hint(
                    "IEC 61131-3 ed. 3: a method's name is unique in its class or block; SIMATIC AX \
                     overloads methods by their parameters, ladderc does not: rename one (the \
                     first is the one compiled and called)",
                ),
            );
            blank(body, m.whole.clone());
            continue;
        }
        let mut pm = pending_method(file, src, m, method_diags);
        pm.overloaded = p.methods[k + 1..]
            .iter()
            .any(|o| o.name.eq_ignore_ascii_case(&m.name));
        // the widest access of the methods of its name (the E1084 above is the one error: a
        // call meant for a PUBLIC second one is no E1021 more)
        let access =
            p.methods
                .iter()
                .filter(|o| o.name.eq_ignore_ascii_case(&m.name))
                .map(|o| o.access)
                .reduce(|a, b| match (a, b) {
                    (None, _) | (_, None) => None,
                    (Some(crate::ast::Access::Public), _)
                    | (_, Some(crate::ast::Access::Public)) => Some(crate::ast::Access::Public),
                    (Some(crate::ast::Access::Private), x)
                    | (x, Some(crate::ast::Access::Private)) => x,
                    (x, _) => x,
                })
                .flatten();
        pm.access = owned(access, &m.name, m.name_range.clone(), "METHOD");
        super::var_stat::name_method_blocks(&mut pm, stat_at);
        references.apply_to_method(&mut pm.blocks, pm.ret.as_mut());
        methods.push(pm);
        blank(body, m.whole.clone());
    }
    for pr in &p.properties {
        for mut pm in super::property::pending_accessors(file, src, pr, diags) {
            // the accessor's own specifier (`GET PROTECTED`), else the property's
            let own = if pm.name.name.starts_with(super::property::GET_PREFIX) {
                pr.get_access
            } else {
                pr.set_access
            };
            pm.access = owned(
                own.or(pr.access),
                &pr.name,
                pr.name_range.clone(),
                "PROPERTY",
            );
            references.apply_to_method(&mut pm.blocks, pm.ret.as_mut());
            methods.push(pm);
        }
        blank(body, pr.whole.clone());
    }
}

/// Reads a method's declarations (its variable blocks, and its result as a variable named like the
/// method) with the IL parser, in place: diagnostics point into the file.
pub(super) fn pending_method(
    file: FileId,
    src: &str,
    m: &MethodText,
    diags: &mut Diagnostics,
) -> PendingMethod {
    let vars =
        |text: &str, base: usize, diags: &mut Diagnostics| read_var_blocks(file, text, base, diags);
    // `n : UDINT := SIZEOF(T) * k;`: read without its initial value, assigned when the method starts
    let super::method_inits::MemberText {
        blocks,
        inst,
        text,
        base,
        once,
    } = super::method_inits::member_text(
        file,
        src,
        m.decls.clone(),
        m.stmts.clone(),
        Span::new(file, m.name_range.start, m.name_range.end),
        diags,
    );
    // `Name : TYPE` read as the declaration `VAR Name : TYPE; END_VAR` (the name is at least 7
    // bytes into the file: after `METHOD `)
    let ret = m.ret_end.and_then(|end| {
        let decl = src.get(m.name_range.start..end)?;
        let base = m.name_range.start.checked_sub(4)?;
        let text = format!("VAR {decl};END_VAR");
        vars(&text, base, diags)
            .into_iter()
            .flat_map(|b| b.vars)
            .next()
    });
    PendingMethod {
        name: crate::ast::Ident::new(
            &m.name,
            Span::new(file, m.name_range.start, m.name_range.end),
        ),
        ret,
        blocks,
        text,
        base,
        inst,
        once,
        local_inits: Vec::new(),
        access: None,
        overloaded: false,
    }
}

/// The variable blocks of a method's or property accessor's declaration text (see
/// [`read_var_blocks`]), a `VAR_INST` block read as `VAR`, and the variables of its `VAR_INST`
/// blocks (upper-case).
pub(super) fn read_member_var_blocks(
    file: FileId,
    text: &str,
    base: usize,
    diags: &mut Diagnostics,
) -> (Vec<crate::ast::VarBlock>, Vec<String>) {
    let (mut decls, inst_at) = var_inst_as_var(text);
    // a pragma among the declarations (`{attribute 'hide'}` above a variable): reported and
    // blanked, as in a POU's declarations
    for pr in lex(text).1 {
        if let Problem::Pragma(r) = pr {
            let pragma = text.get(r.clone()).unwrap_or("{}");
            diags.push(pragma_diagnostic(
                pragma,
                Span::new(file, base + r.start, base + r.end),
            ));
            decls.replace_range(r.clone(), &" ".repeat(r.len()));
        }
    }
    let blocks = read_var_blocks(file, &decls, base, diags);
    let inst = blocks
        .iter()
        .filter(|b| inst_at.contains(&(b.span.start as usize).saturating_sub(base)))
        .flat_map(|b| b.vars.iter().map(|v| v.name.key()))
        .collect();
    (blocks, inst)
}

/// A method's declaration text with each `VAR_INST` keyword (TwinCAT, Beckhoff Infosys "VAR_INST":
/// a method variable stored in the function block instance, kept between calls) read as `VAR` of
/// the same length, and the offsets of those keywords in the text.
fn var_inst_as_var(text: &str) -> (String, Vec<usize>) {
    let (toks, _) = lex(text);
    let mut out = text.to_string();
    let mut at = Vec::new();
    for t in &toks {
        if text
            .get(t.range.clone())
            .is_some_and(|w| w.eq_ignore_ascii_case("VAR_INST"))
        {
            out.replace_range(t.range.clone(), "VAR     ");
            at.push(t.range.start);
        }
    }
    (out, at)
}

/// The variable blocks of a method's (or a property accessor's) declaration text, read by the IL
/// parser in place (`base`: the text's offset in the file), without VAR_GLOBAL blocks.
pub(super) fn read_var_blocks(
    file: FileId,
    text: &str,
    base: usize,
    diags: &mut Diagnostics,
) -> Vec<crate::ast::VarBlock> {
    match crate::parser::run(
        file,
        text,
        base,
        crate::lexer::Tok::UnitStart,
        diags,
        Vec::new(),
    ) {
        Some(crate::parser::Parsed::Unit(mut top)) => {
            let mut blocks: Vec<crate::ast::VarBlock> =
                top.implicit.take().map(|(_, v, _)| v).unwrap_or_default();
            // (a VAR_GLOBAL block would be a top-level item: not a method's)
            blocks.retain(|b| b.kind != crate::ast::VarKind::Global);
            blocks
        }
        _ => Vec::new(),
    }
}

/// The text with each `;` right after an `END_VAR` blanked, one W0017 at each that is no statement
/// (declarations, another object or the end of the text follow: `END_VAR; VAR ...`); `None` when
/// it has none. A `;` that a body follows is the body's empty statement (IEC 61131-3 edition 2's
/// `statement ::= NIL | ...`), blanked without a word: it does nothing either way.
fn end_var_semicolons(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
) -> Option<String> {
    let mut text: Option<String> = None;
    for (k, t) in toks.iter().enumerate().skip(1) {
        if t.tok != Tok::Semi || !is_word(src, &toks[k - 1], "END_VAR") {
            continue;
        }
        // a body follows unless the text ends or declarations or another object come next
        let body_follows = toks.get(k + 1).is_some_and(|n| {
            let w = word(src, n).to_ascii_uppercase();
            !(matches!(n.tok, Tok::Ident | Tok::Kw(_))
                && (is_var_keyword(&w)
                    || matches!(
                        w.as_str(),
                        "TYPE"
                            | "PROGRAM"
                            | "FUNCTION"
                            | "FUNCTION_BLOCK"
                            | "CLASS"
                            | "INTERFACE"
                            | "NAMESPACE"
                            | "CONFIGURATION"
                            | "RESOURCE"
                            | "METHOD"
                            | "PROPERTY"
                            | "ACTION"
                            | "ACTIONS"
                            | "END_CONFIGURATION"
                            | "END_RESOURCE"
                            | "END_NAMESPACE"
                    )))
        });
        if body_follows {
            blank(text.get_or_insert_with(|| src.to_string()), t.range.clone());
            continue;
        }
        diags.push(
            Diagnostic::new(
                code::W0017,
                Severity::Warning,
                "a `;` after END_VAR: skipped",
            )
            .at(Span::new(file, t.range.start, t.range.end))
            .with_primary_label("ends no declaration")
            .with_hint("IEC 61131-3 ends a block of declarations with END_VAR alone; delete the `;` (another IEC compiler refuses it)"),
        );
        blank(text.get_or_insert_with(|| src.to_string()), t.range.clone());
    }
    text
}

/// Blanks each variable declaration whose name is a keyword that opens or closes a block
/// (`Configuration : INT;`: B&R Automation Studio is case-sensitive and reserves only the
/// upper-case words), from the name to its `;`, with one E1031 at the name: read as the keyword,
/// the name would open a CONFIGURATION or TYPE and every block around it would be reported
/// unclosed. Only inside `VAR ... END_VAR`, only a name that starts a declaration (after the
/// block's keyword, a qualifier, `;` or `,`) and is followed by `:` or `,`. The POU holding one is
/// not compiled further (`compile_pending`: its E1031 is the one error).
///
/// A structure's field so named (`Type : USINT;`, `Configuration : ...` of B&R's own library
/// types) is no error: a field is only reached after `.` (`s.Type`), where no keyword can stand.
/// Each field name that the declaration grammar reads as a keyword (any word of
/// [`crate::lexer::classify`] that is no name there) is replaced by a name of the same length
/// (`_ype`), and its place and spelling are returned, for [`restore_field_names`] to put back
/// after the parse.
fn keyword_declarations(
    file: FileId,
    src: &str,
    toks: &[Token],
    diags: &mut Diagnostics,
    text: &mut Option<String>,
) -> Vec<(usize, String)> {
    // (`CONFIGURATION` and `RESOURCE` are names to the grammar: sema reports them, E1031, or
    // W1418 in a TwinCAT object)
    const BLOCK_WORDS: [&str; 5] = ["TYPE", "STRUCT", "PROGRAM", "FUNCTION", "FUNCTION_BLOCK"];
    let mut in_decl = false;
    let mut in_struct = false;
    let mut fields = Vec::new();
    let stubs = declaration_only_blocks(src, toks);
    // a declaration-only block named with an operator keyword (`{REDUND_OK} FUNCTION AND : ANY`,
    // B&R's system stub `operator.fun`, which declares AND, OR, XOR, NOT and MOD as functions
    // beside ADD and SHL): a name of the same length put back after the parse, so the stub is
    // read as the others are (not compiled, one note W0021, `split_blocks`), not one E0011 and
    // E0008 per stub hiding every other diagnostic of the project (before round 32)
    for r in &stubs {
        let Some(t) = toks
            .get(r.start + 1)
            .filter(|t| matches!(t.tok, Tok::Kw(_)))
        else {
            continue;
        };
        let name = word(src, t).to_string();
        if name.len() > 1 {
            let same_length = format!("_{}", &name[1..]);
            text.get_or_insert_with(|| src.to_string())
                .replace_range(t.range.clone(), &same_length);
            fields.push((t.range.start, name));
        }
    }
    // parentheses open in a declaration's initial value
    let mut depth = 0usize;
    let mut k = 0;
    while k < toks.len() {
        let t = &toks[k];
        k += 1;
        match t.tok {
            Tok::LParen if in_decl => depth += 1,
            Tok::RParen => depth = depth.saturating_sub(1),
            Tok::Semi => depth = 0,
            _ => {}
        }
        if !matches!(t.tok, Tok::Kw(_) | Tok::Ident) {
            continue;
        }
        let w = word(src, t).to_ascii_uppercase();
        // a field named with a keyword in a structure's initial value (`(Name := 'calc', Type :=
        // 2)`, as B&R Automation Studio writes them): as in its declaration, a name of the same
        // length put back after the parse (round 27, before: a parse cascade)
        if in_decl
            && depth > 0
            && k >= 2
            && matches!(toks[k - 2].tok, Tok::LParen | Tok::Comma)
            && toks.get(k).is_some_and(|n| n.tok == Tok::Assign)
            && BLOCK_WORDS.contains(&w.as_str())
        {
            let r = t.range.clone();
            let name = word(src, t).to_string();
            let same_length = format!("_{}", &name[1..]);
            text.get_or_insert_with(|| src.to_string())
                .replace_range(r.clone(), &same_length);
            fields.push((r.start, name));
            continue;
        }
        let followed_by_colon = toks
            .get(k)
            .is_some_and(|n| matches!(n.tok, Tok::Colon | Tok::Comma));
        let starts_decl = in_decl
            && k >= 2
            && (matches!(toks[k - 2].tok, Tok::Semi | Tok::Comma)
                || matches!(
                    word(src, &toks[k - 2]).to_ascii_uppercase().as_str(),
                    "RETAIN" | "CONSTANT" | "NON_RETAIN" | "PERSISTENT" | "STRUCT"
                )
                || is_var_keyword(&word(src, &toks[k - 2]).to_ascii_uppercase()));
        // (in a block of declarations only, B&R's `.fun` file: `Type : USINT;` in its VAR_INPUT,
        // as B&R's own libraries name inputs, read only as `blk(Type := x)` and `blk.Type`)
        let in_stub = stubs.iter().any(|r| r.contains(&(k - 1)));
        if (in_struct || in_stub) && starts_decl && followed_by_colon && !w.starts_with("END_") {
            let kind = crate::lexer::classify(&w);
            if kind != crate::lexer::Word::Ident && !kind.is_name() {
                // a field named with a keyword: a name of the same length (no keyword starts
                // with `_`), its spelling put back after the parse
                let r = t.range.clone();
                let name = word(src, t).to_string();
                let same_length = format!("_{}", &name[1..]);
                text.get_or_insert_with(|| src.to_string())
                    .replace_range(r.clone(), &same_length);
                fields.push((r.start, name));
            }
            continue;
        }
        let named = starts_decl
            && (BLOCK_WORDS.contains(&w.as_str()) || is_var_keyword(&w))
            && followed_by_colon;
        if named {
            let name = word(src, t);
            diags.push(
                Diagnostic::error(
                    code::E1031,
                    format!("`{name}` is reserved in IEC 61131-3 (a keyword): it cannot name a variable"),
                )
                .at(Span::new(file, t.range.start, t.range.end))
                .with_primary_label("a keyword")
                .with_hint(format!("rename the variable, for example `x{name}`")),
            );
            // the declaration up to its `;` (the names before it in `a, Type : INT;` stay: the
            // blank leaves `a, : INT;`, one E0011 more, never a block opened)
            let mut e = k;
            while e < toks.len()
                && !matches!(toks[e].tok, Tok::Semi | Tok::Eof)
                && !word(src, &toks[e]).eq_ignore_ascii_case("END_VAR")
                && !word(src, &toks[e]).eq_ignore_ascii_case("END_STRUCT")
            {
                e += 1;
            }
            let end = match toks.get(e) {
                Some(s) if s.tok == Tok::Semi => s.range.end,
                _ => toks[e - 1].range.end,
            };
            blank(
                text.get_or_insert_with(|| src.to_string()),
                t.range.start..end,
            );
            k = e;
            continue;
        }
        if is_var_keyword(&w) || w == "STRUCT" {
            in_decl = true;
            in_struct = w == "STRUCT";
        } else if w == "END_VAR" || w == "END_STRUCT" {
            in_decl = false;
            in_struct = false;
        }
    }
    fields
}

/// The token ranges (from `FUNCTION` or `FUNCTION_BLOCK` to its `END_`) of the blocks that hold
/// declarations only, no statement: B&R's `.fun` files, which declare a library's blocks (their
/// statements are in `.st` files, or in the B&R system for its own libraries).
fn declaration_only_blocks(src: &str, toks: &[Token]) -> Vec<std::ops::Range<usize>> {
    let upper = |k: usize| match toks.get(k) {
        Some(t) if matches!(t.tok, Tok::Kw(_) | Tok::Ident) => word(src, t).to_ascii_uppercase(),
        _ => String::new(),
    };
    let mut out = Vec::new();
    let mut k = 0;
    while k < toks.len() {
        let w = upper(k);
        let end_word = match w.as_str() {
            "FUNCTION" => "END_FUNCTION",
            "FUNCTION_BLOCK" => "END_FUNCTION_BLOCK",
            _ => {
                k += 1;
                continue;
            }
        };
        let start = k;
        k += 1;
        // the header (`FUNCTION F : INT`): names, `:` and keywords, up to the first VAR block
        let mut header = true;
        while k < toks.len() && !is_var_keyword(&upper(k)) && upper(k) != end_word {
            if !matches!(toks[k].tok, Tok::Kw(_) | Tok::Ident | Tok::Colon) {
                header = false;
                break;
            }
            k += 1;
        }
        while header && is_var_keyword(&upper(k)) {
            while k < toks.len() && upper(k) != "END_VAR" {
                k += 1;
            }
            k += 1;
        }
        if header && upper(k) == end_word {
            out.push(start..k + 1);
        }
        while k < toks.len() && upper(k) != end_word {
            k += 1;
        }
        k += 1;
    }
    out
}

/// Puts back the spelling of the structure fields and of the declaration-only blocks' variables
/// named with a keyword (`Type : USINT;`) that [`keyword_declarations`] replaced by names of the
/// same length for the parse; the variables' places are kept in the unit's
/// `keyword_parameters`, so that sema accepts their names.
fn restore_field_names(unit: &mut CompilationUnit, fields: &[(usize, String)]) {
    if fields.is_empty() {
        return;
    }
    // the fields named in structure initializers (`(Type := 2)`)
    fn in_init(i: &mut crate::ast::Initializer, fields: &[(usize, String)]) {
        match i {
            crate::ast::Initializer::Struct(es, _) => {
                for (n, v) in es {
                    if let Some((_, name)) =
                        fields.iter().find(|(s, _)| *s == n.span.start as usize)
                    {
                        n.name.clone_from(name);
                    }
                    in_init(v, fields);
                }
            }
            crate::ast::Initializer::Array(es, _) => {
                es.iter_mut().for_each(|e| in_init(&mut e.value, fields))
            }
            _ => {}
        }
    }
    for item in &mut unit.items {
        match item {
            LibraryElement::DataTypes(types) => {
                for t in types.iter_mut() {
                    match &mut t.def {
                        crate::ast::TypeDef::Struct { fields: decls } => decls
                            .iter_mut()
                            .filter_map(|d| d.init.as_mut())
                            .for_each(|i| in_init(i, fields)),
                        crate::ast::TypeDef::Alias { init: Some(i), .. } => in_init(i, fields),
                        _ => {}
                    }
                }
            }
            LibraryElement::Pou(p) => p
                .var_blocks
                .iter_mut()
                .flat_map(|b| b.vars.iter_mut())
                .filter_map(|d| d.init.as_mut())
                .for_each(|i| in_init(i, fields)),
            LibraryElement::GlobalVars(b) => b
                .vars
                .iter_mut()
                .filter_map(|d| d.init.as_mut())
                .for_each(|i| in_init(i, fields)),
            _ => {}
        }
    }
    let mut parameters = Vec::new();
    for item in &mut unit.items {
        if let LibraryElement::Pou(p) = item {
            // a stub named with an operator keyword (`FUNCTION AND : ANY`, `keyword_declarations`)
            if let Some((_, name)) = fields
                .iter()
                .find(|(s, _)| *s == p.name.span.start as usize)
            {
                p.name.name.clone_from(name);
            }
            for d in p.var_blocks.iter_mut().flat_map(|b| b.vars.iter_mut()) {
                let at = d.name.span.start as usize;
                if let Some((_, name)) = fields.iter().find(|(s, _)| *s == at) {
                    d.name.name.clone_from(name);
                    parameters.push(d.name.span);
                }
            }
            continue;
        }
        let LibraryElement::DataTypes(types) = item else {
            continue;
        };
        for t in types {
            if let crate::ast::TypeDef::Struct { fields: decls } = &mut t.def {
                for d in decls {
                    let at = d.name.span.start as usize;
                    if let Some((_, name)) = fields.iter().find(|(s, _)| *s == at) {
                        d.name.name.clone_from(name);
                    }
                }
            }
        }
    }
    unit.keyword_parameters.extend(parameters);
}

/// Blanks B&R Automation Studio's zero initializer `:= (0)` of a declaration (`gAxis_HW :
/// SdcHwCfg_typ := (0);`, `PID : MTBasicsPID := (0);` in its generated `.var` files): a structure,
/// an instance or an array declared so starts as its type's initial value (no `:=` at all), as
/// Automation Studio starts it with its members zero. Only inside `VAR ... END_VAR` and
/// `STRUCT ... END_STRUCT`, and only before a `;` (`x := (0);` in a body is an assignment). So
/// is the `(0)` of a repeated array element, `9((0))`, which becomes `9(())` (round 26).
fn zero_initializers(src: &str, toks: &[Token], text: &mut Option<String>) {
    let mut in_decl = false;
    for (k, t) in toks.iter().enumerate() {
        if matches!(t.tok, Tok::Kw(_) | Tok::Ident) {
            let w = word(src, t).to_ascii_uppercase();
            if is_var_keyword(&w) || w == "STRUCT" {
                in_decl = true;
            } else if w == "END_VAR" || w == "END_STRUCT" {
                in_decl = false;
            }
            continue;
        }
        // `9((0))` in an array's initial value (B&R's mapp types: `[(...),9((0))]`): nine elements
        // of the type's initial value, `9(())`, as `(0)` alone means
        if in_decl && matches!(t.tok, Tok::Int(_)) {
            if let [l, l2, z, r, r2, ..] = &toks[k + 1..] {
                if l.tok == Tok::LParen
                    && l2.tok == Tok::LParen
                    && z.tok == Tok::Int(0)
                    && r.tok == Tok::RParen
                    && r2.tok == Tok::RParen
                {
                    blank(text.get_or_insert_with(|| src.to_string()), z.range.clone());
                }
            }
            continue;
        }
        if !in_decl || t.tok != Tok::Assign {
            continue;
        }
        if let [l, z, r, semi, ..] = &toks[k + 1..] {
            if l.tok == Tok::LParen
                && z.tok == Tok::Int(0)
                && r.tok == Tok::RParen
                && semi.tok == Tok::Semi
            {
                blank(
                    text.get_or_insert_with(|| src.to_string()),
                    t.range.start..r.range.end,
                );
            }
        }
    }
}

/// Skips the `VAR ... END_VAR` blocks that start at `h`: the position after them, and the end of
/// the last closed one's `END_VAR` (`None` when no block starts there, or none is closed).
pub(super) fn skip_var_blocks(src: &str, toks: &[Token], mut h: usize) -> (usize, Option<usize>) {
    let n = toks.len();
    let mut end = None;
    while h < n && is_var_keyword(&word(src, &toks[h]).to_ascii_uppercase()) {
        while h < n && !is_word(src, &toks[h], "END_VAR") {
            h += 1;
        }
        if h < n {
            end = Some(toks[h].range.end);
            h += 1;
        }
    }
    (h, end)
}

/// The position of the name of the METHOD or PROPERTY whose keyword is at `k`, after its access
/// and inheritance modifiers (`METHOD PUBLIC FINAL M`, edition 3's `METHOD PUBLIC OVERRIDE M`); a
/// modifier followed by no name is the name.
pub(super) fn member_name_at(src: &str, toks: &[Token], k: usize) -> usize {
    const MODIFIERS: [&str; 7] = [
        "PUBLIC",
        "PRIVATE",
        "PROTECTED",
        "INTERNAL",
        "FINAL",
        "ABSTRACT",
        "OVERRIDE",
    ];
    let mut h = k + 1;
    while h + 1 < toks.len()
        && toks[h + 1].tok == Tok::Ident
        && MODIFIERS.iter().any(|m| is_word(src, &toks[h], m))
    {
        h += 1;
    }
    h
}

/// The access specifier among a member's modifier tokens (`METHOD PRIVATE M`, `PROPERTY
/// PROTECTED P`, `GET PROTECTED`): PRIVATE or PROTECTED; PUBLIC, INTERNAL (the project is one
/// namespace) or none: `None`, callable from anywhere (CODESYS's default for methods).
pub(super) fn member_access(src: &str, toks: &[Token]) -> Option<crate::ast::Access> {
    toks.iter().find_map(|t| {
        if is_word(src, t, "PRIVATE") {
            Some(crate::ast::Access::Private)
        } else if is_word(src, t, "PROTECTED") {
            Some(crate::ast::Access::Protected)
        } else {
            None
        }
    })
}

/// The `METHOD ... END_METHOD` blocks among a function block's body tokens. A block that does not
/// end with `END_METHOD` is left out (the body's parse reports it).
pub(super) fn scan_methods(src: &str, toks: &[Token]) -> Vec<MethodText> {
    let n = toks.len();
    let same_line = |a: usize, b: usize| !src.get(a..b).unwrap_or("\n").contains(['\n', '\r']);
    let mut out = Vec::new();
    let mut k = 0;
    while k < n {
        if !is_word(src, &toks[k], "METHOD") {
            k += 1;
            continue;
        }
        let mut h = member_name_at(src, toks, k);
        let Some(name_tok) = toks.get(h).filter(|t| t.tok == Tok::Ident) else {
            k += 1;
            continue;
        };
        let access = member_access(src, &toks[k + 1..h]);
        h += 1;
        let mut ret_end = None;
        if toks.get(h).is_some_and(|t| t.tok == Tok::Colon) {
            h += 1;
            while h < n
                && toks[h].tok != Tok::Semi
                && same_line(name_tok.range.end, toks[h].range.start)
                && !is_var_keyword(&word(src, &toks[h]).to_ascii_uppercase())
                // `METHOD Next : LREAL END_METHOD` on one line: an interface's method as a
                // TwinCAT `.TcIO` reads when its declaration ends without a line break
                && !is_word(src, &toks[h], "END_METHOD")
            {
                ret_end = Some(toks[h].range.end);
                h += 1;
            }
        }
        if toks.get(h).is_some_and(|t| t.tok == Tok::Semi) {
            h += 1;
        }
        let decl_start = toks.get(h).map_or(name_tok.range.end, |t| t.range.start);
        let (after, vars_end) = skip_var_blocks(src, toks, h);
        h = after;
        let decl_end = vars_end.unwrap_or(decl_start);
        let mut e = h;
        while e < n && !is_word(src, &toks[e], "END_METHOD") {
            e += 1;
        }
        if e >= n {
            break;
        }
        out.push(MethodText {
            name: word(src, name_tok).to_string(),
            name_range: name_tok.range.clone(),
            ret_end,
            decls: decl_start..decl_end,
            stmts: decl_end..toks[e].range.start,
            whole: toks[k].range.start..toks[e].range.end,
            access,
        });
        k = e + 1;
    }
    out
}

/// The language of a body's tokens: ST when ST statements (an assignment `:=` outside parentheses, a
/// statement keyword, a call statement `f(...)`) outnumber the lines that start like IL instructions
/// (an IL operator followed by its operand, a label), or when neither is found but a `;` is. An empty
/// body is IL.
fn body_lang(src: &str, toks: &[Token]) -> Lang {
    let mut st = 0usize;
    let mut il = 0usize;
    let mut depth = 0i32;
    let mut line_start = true;
    // an ST assignment not yet ended by its `;`: a line after it that starts with an IL operator
    // continues its expression (`q := a` then `OR b` then `OR c;`); IL writes `:=` only inside
    // the parentheses of a call
    let mut open_assignment = false;
    // likewise a condition after `IF`, `ELSIF`, `WHILE`, `UNTIL` (or a `CASE` selector) not yet
    // ended by its `THEN`, `DO`, `OF` or `;`: `IF (a = 1)` then `AND (b = 2)` then `THEN` (before:
    // a few such lines outnumbered the statements and the body was read as IL)
    let mut open_condition = false;
    for (k, t) in toks.iter().enumerate() {
        let next = toks.get(k + 1);
        let next_same_line = next.filter(|nt| {
            !src.get(t.range.end..nt.range.start)
                .unwrap_or("\n")
                .contains(['\n', '\r'])
        });
        if line_start {
            let mut m = k;
            while m + 1 < toks.len()
                && !src
                    .get(toks[m].range.end..toks[m + 1].range.start)
                    .unwrap_or("\n")
                    .contains(['\n', '\r'])
            {
                m += 1;
            }
            let line_end_semi = toks[m].tok == Tok::Semi;
            // a line that closes a parenthesis opened on an earlier line continues an ST
            // expression (`   OR BOOL_TO_BYTE(b5), 1) OR ...`): IL closes a deferred operation
            // with a `)` on a line of its own
            let closes_earlier = toks[k..=m]
                .iter()
                .scan(0i32, |d, t| {
                    match t.tok {
                        Tok::LParen | Tok::LBracket => *d += 1,
                        Tok::RParen | Tok::RBracket => *d -= 1,
                        _ => {}
                    }
                    Some(*d)
                })
                .any(|d| d < 0);
            let w = word(src, t).to_ascii_uppercase();
            match &t.tok {
                Tok::Kw(Kw::If | Kw::Case | Kw::For | Kw::While | Kw::Repeat | Kw::EndIf)
                | Tok::Kw(Kw::EndFor | Kw::EndWhile | Kw::EndCase | Kw::EndRepeat) => st += 1,
                Tok::Ident | Tok::Kw(_) if IL_OPS.contains(&w.as_str()) => {
                    let operand = next_same_line.is_none_or(|nt| {
                        !matches!(nt.tok, Tok::Assign | Tok::LBracket | Tok::Dot | Tok::Caret)
                    });
                    if operand
                        && !line_end_semi
                        && !closes_earlier
                        && !open_assignment
                        && !open_condition
                    {
                        il += 1;
                    }
                }
                Tok::Ident => match next_same_line.map(|nt| &nt.tok) {
                    Some(Tok::LParen | Tok::LBracket | Tok::Dot | Tok::Caret) => st += 1,
                    Some(Tok::Colon) if !line_end_semi => il += 1,
                    _ => {}
                },
                _ => {}
            }
        }
        match t.tok {
            Tok::LParen | Tok::LBracket => depth += 1,
            Tok::RParen | Tok::RBracket => depth -= 1,
            Tok::Assign if depth <= 0 => {
                st += 1;
                open_assignment = true;
            }
            Tok::Semi => {
                open_assignment = false;
                open_condition = false;
            }
            Tok::Kw(Kw::If | Kw::Elsif | Kw::While | Kw::Until | Kw::Case) => open_condition = true,
            Tok::Kw(Kw::Then | Kw::Do | Kw::Of) => open_condition = false,
            // ST-only words wherever they are (one-line POUs: `... END_VAR RETURN; END_FUNCTION`).
            Tok::Kw(Kw::Return | Kw::Exit | Kw::Continue) => st += 1,
            _ => {}
        }
        line_start = next_same_line.is_none();
    }
    // no statement and no instruction either (`a AND NOT b;`): a `;` is ST's, IL has none; an
    // empty body (`<ST><![CDATA[]]></ST>` of a TwinCAT block whose actions do the work) is ST
    if st > il || (il == 0 && toks.iter().any(|t| t.tok == Tok::Semi)) || toks.is_empty() {
        Lang::St
    } else {
        Lang::Il
    }
}

/// The language of a text given no file extension: XML when it starts with `<`, ST when one of its
/// POU bodies is ST, or when it holds no POU but a `{` pragma (a CODESYS global variable list
/// `{attribute 'qualified_only'} VAR_GLOBAL ...`: only the ST reader reads pragmas), or no POU but
/// ST statements (`body_lang`), IL otherwise.
pub fn detect(src: &str) -> Lang {
    let t = src.trim_start_matches('\u{feff}').trim_start();
    if t.starts_with('<') {
        return Lang::Xml;
    }
    let (toks, problems) = lex(src);
    let (pous, stray) = scan_tokens(src, &toks);
    if pous.iter().any(|p| p.lang == Lang::St)
        || (pous.is_empty() && problems.iter().any(|p| matches!(p, Problem::Pragma(_))))
        || (pous.is_empty() && declarations_only(src, &toks, &stray))
        // no POU, but ST statements (`IF start THEN` / `lamp := TRUE;` / `END_IF;`: a body
        // exported alone): read as ST, whose reader reports them once (E0307), where IL's gave
        // an error a line
        || (pous.is_empty()
            && toks.iter().any(|t| t.tok != Tok::Eof)
            && body_lang(src, &toks) == Lang::St)
        // 4CONTROL's `CONST ... END_CONST` (a `.cst` file of a MECT project), even empty: a
        // dialect of ST, whose reader gives its one E1095 (round 33: before, read as IL, an
        // unknown function `CONST`)
        || super::hash_directives::four_control_constants(FileId::default(), src).is_some()
    {
        Lang::St
    } else {
        Lang::Il
    }
}

/// Whether a text without POUs holds only declarations (`VAR_GLOBAL` lists, `TYPE` blocks, a
/// `NAMESPACE` around them: a CODESYS V2.3 GVL or DUT export): `stray` are the tokens outside
/// every block ([`scan_tokens`]); only a namespace's words may be there.
fn declarations_only(src: &str, toks: &[Token], stray: &[usize]) -> bool {
    let words = toks.iter().filter(|t| !matches!(t.tok, Tok::Eof)).count();
    words > stray.len()
        && stray.iter().all(|&k| {
            let t = &toks[k];
            is_word(src, t, "NAMESPACE")
                || is_word(src, t, "END_NAMESPACE")
                || (t.tok == Tok::Semi && k > 0 && is_word(src, &toks[k - 1], "END_NAMESPACE"))
                || (k > 0 && is_word(src, &toks[k - 1], "NAMESPACE") && t.tok == Tok::Ident)
                || (t.tok == Tok::Dot || t.tok == Tok::Ident)
                    && stray.contains(&(k.wrapping_sub(1)))
                    && toks[..k]
                        .iter()
                        .rev()
                        .take_while(|p| matches!(p.tok, Tok::Dot | Tok::Ident))
                        .any(|p| is_word(src, p, "NAMESPACE"))
        })
}

/// The text of an `ACTIONS` block (or, named `ACTION`, of actions outside any POU) from `start`
/// to `end`: its actions' names and statement ranges.
fn actions_text(
    name: &str,
    start: Range<usize>,
    end: usize,
    action_list: Vec<(String, Range<usize>, Range<usize>)>,
) -> PouText {
    PouText {
        name: name.into(),
        name_range: start.clone(),
        body: start.start..end,
        lang: Lang::Il,
        sfc: None,
        oop: None,
        methods: Vec::new(),
        properties: Vec::new(),
        actions: Some(start),
        action_list,
        modifier: None,
        heritage: None,
        header_semi: None,
        interface: None,
        class: None,
    }
}

/// Blanks `range` of `text`: every character but line ends becomes spaces of its byte length, so
/// positions do not move.
pub fn blank(text: &mut String, range: Range<usize>) {
    let Some(part) = text.get(range.clone()) else {
        return;
    };
    let blanked: String = part
        .chars()
        .flat_map(|c| {
            let (ch, n) = if c == '\n' || c == '\r' {
                (c, 1)
            } else {
                (' ', c.len_utf8())
            };
            std::iter::repeat_n(ch, n)
        })
        .collect();
    text.replace_range(range, &blanked);
}

/// Reads a text in `lang` (IL or ST; XML is not read here). IL: the text is parsed as IL, except that
/// POU bodies written in ST are reported once (E0300) and skipped. ST: declarations are parsed by the
/// IL parser; IL bodies stay (W0303 note); ST bodies are returned as [`PendingBody`]s for
/// [`compile_pending`]; pragmas outside bodies are reported (W0300/W0301) and skipped. The entries of
/// `VAR_CONFIG` blocks (IL or ST) are returned for [`apply_var_config`], which the caller runs once
/// every unit of the project is parsed (a configuration may name programs of other files).
pub fn parse_text(
    file: FileId,
    src: &str,
    implicit_name: &str,
    lang: Lang,
    diags: &mut Diagnostics,
) -> (CompilationUnit, Vec<PendingBody>, Vec<ConfigEntry>) {
    let before = diags.len();
    let mut out = parse_text_as_read(file, src, implicit_name, lang, diags);
    // `fb : FB_X<10>;`: the instance's generic values on its type (`generic_constants`)
    if lang == Lang::St && src.contains('<') {
        let instances = super::generic_constants::generic_instances(src, &lex(src).0);
        super::generic_constants::name_generic_instances(&instances, &mut out.0, &mut out.1);
    }
    // `ARRAY[0..RobotLibParams.TOOL_MAX - 1]`: the bound's qualifier was blanked (`list_bounds`)
    // before the constant was looked for; E0022 names it as written, and the list
    for d in diags.since_mut(before) {
        if d.code == code::E0022 {
            super::list_bounds::name_qualifier(d, src);
        }
    }
    out
}

/// [`parse_text`], its E0022 naming constants without their list's qualifier.
fn parse_text_as_read(
    file: FileId,
    src: &str,
    implicit_name: &str,
    lang: Lang,
    diags: &mut Diagnostics,
) -> (CompilationUnit, Vec<PendingBody>, Vec<ConfigEntry>) {
    let mut pending = Vec::new();
    let mut decl_args = Vec::new();
    let mut first_try = None;
    // `<<<<<<< HEAD` ... `>>>>>>> branch`: one E1039 per conflict, the first side read (`conflict_markers`)
    let resolved;
    let src = match super::conflict_markers::conflict_markers(file, src, diags) {
        Some(t) => {
            resolved = t;
            resolved.as_str()
        }
        None => src,
    };
    if lang == Lang::Il {
        // A valid IL file costs one parse: the bodies are looked at only when the IL parser
        // reported errors (then they are replaced by one E0300 if ST bodies explain them).
        let mut local = Diagnostics::new();
        let unit = crate::parse_named(file, src, implicit_name, &mut local);
        if !local.has_errors() {
            diags.extend(local);
            return (unit, pending, Vec::new());
        }
        // Siemens STL (`.awl`): one E0023 naming the dialect, not an error per line
        if let Some(d) = super::siemens_stl::siemens_stl(file, src) {
            diags.push(d);
            return (CompilationUnit::default(), pending, Vec::new());
        }
        // a rung drawn in text (`+--[ ]--( )--`): one E1091, not an E0001 per drawing character
        if let Some(d) = super::text_ladder::text_ladder(file, src) {
            diags.push(d);
            return (CompilationUnit::default(), pending, Vec::new());
        }
        first_try = Some((unit, local));
    }
    // 4CONTROL's resource file (`RESOURCE r` without a configuration): one E1094, the file not
    // compiled (`hash_directives`), before its `#IMPORT` lines are noted
    if lang == Lang::St {
        if let Some(d) = super::hash_directives::four_control_resource(file, src) {
            diags.push(d);
            return (CompilationUnit::default(), pending, Vec::new());
        }
    }
    // `#ifdef X` ... `#else` ... `#endif` (B&R's preprocessor): the sections not compiled and the
    // directive lines blanked (`hash_directives`), before `#word` could read as SCL's `#local`
    let preprocessed;
    let src = match (lang == Lang::St)
        .then(|| super::hash_directives::hash_directives(file, src, diags))
        .flatten()
    {
        Some(t) => {
            preprocessed = t;
            preprocessed.as_str()
        }
        None => src,
    };
    // 4CONTROL's `CONST ... END_CONST`: one E1095, the file not compiled (`hash_directives`)
    if lang == Lang::St {
        if let Some(d) = super::hash_directives::four_control_constants(file, src) {
            // (S7-SCL has a `CONST ... END_CONST` section too: its own marks name SCL)
            let (toks, problems) = lex(src);
            let d = super::scl::siemens_scl(file, src, &toks, &problems).unwrap_or(d);
            diags.push(d);
            return (CompilationUnit::default(), pending, Vec::new());
        }
    }
    let (mut toks, mut problems) = lex(src);
    if lang == Lang::St {
        if let Some(d) = super::scl::siemens_scl(file, src, &toks, &problems)
            .or_else(|| super::scl::simotion_unit(file, src, &toks))
            .or_else(|| {
                (!problems.is_empty())
                    .then(|| super::text_ladder::text_ladder(file, src))
                    .flatten()
            })
        {
            diags.push(d);
            return (CompilationUnit::default(), pending, Vec::new());
        }
    }
    let (unqualified, unreferenced, unlisted, uninitialised, conditioned, unimported, untasked);
    let unsemicoloned: String;
    // `{IF defined (X)}` ... `{END_IF}`: the sections not compiled blanked (`conditional`)
    let src = match super::conditional::conditional_sections(file, src, &problems, diags) {
        Some(t) => {
            conditioned = t;
            (toks, problems) = lex(&conditioned);
            conditioned.as_str()
        }
        None => src,
    };
    // `FUNCTION Pick<T : ANY_INT> : T` (RuSTy): one E1085, the POU blanked (`generic_headers`)
    let ungeneric;
    let src = match (lang == Lang::St)
        .then(|| super::generic_headers::generic_headers(file, src, &toks, diags))
        .flatten()
    {
        Some(t) => {
            ungeneric = t;
            (toks, problems) = lex(&ungeneric);
            ungeneric.as_str()
        }
        None => src,
    };
    let mut references = RefTypes::default();
    // the structure fields named with a keyword (`keyword_declarations`)
    let mut keyword_fields = Vec::new();
    let (uninstanced, unextended, unstatic): (String, String, String);
    let mut stat_at = Vec::new();
    // `VAR_GENERIC CONSTANT` and `fb : FB_X<10>;`: read as `VAR CONSTANT` and a plain instance,
    // whose values [`parse_text`] notes on its type (`generic_constants`)
    let ungeneric;
    let src = match super::generic_constants::generic_constants(file, src, &toks, diags) {
        Some(t) => {
            ungeneric = t;
            (toks, problems) = lex(&ungeneric);
            ungeneric.as_str()
        }
        None => src,
    };
    // `ARRAY[1..GVL.N]` in ST and IL declarations: the list's name blanked (`list_bounds`)
    let blanked_lists = super::list_bounds::unqualify_list_bounds(src, &toks);
    let lists_blanked = blanked_lists.is_some();
    let src = match blanked_lists {
        Some(t) => {
            unlisted = t;
            (toks, problems) = lex(&unlisted);
            unlisted.as_str()
        }
        None => src,
    };
    let src = if lang == Lang::St {
        // `fb : FB_X(a := 1);`: FB_init arguments, kept for `fb_init` (`fb_init_args`)
        let src =
            match super::fb_init_args::fb_init_arguments(file, src, &toks, diags, &mut decl_args) {
                Some(t) => {
                    uninitialised = t;
                    (toks, problems) = lex(&uninitialised);
                    uninitialised.as_str()
                }
                None => src,
            };
        // `END_VAR;`: the `;` blanked (W0017), so the blocks after it stay declarations
        // `s : MyStruct := (0);` (B&R Automation Studio): blanked, the type's initial value
        let mut unsemi = end_var_semicolons(file, src, &toks, diags);
        zero_initializers(src, &toks, &mut unsemi);
        // `Configuration : INT;` (B&R, case-sensitive, accepts it): one E1031, the declaration
        // blanked, so the block keyword opens no block (no cascade of E0008)
        keyword_fields = keyword_declarations(file, src, &toks, diags, &mut unsemi);
        let src = match unsemi {
            Some(t) => {
                unsemicoloned = t;
                (toks, problems) = lex(&unsemicoloned);
                unsemicoloned.as_str()
            }
            None => src,
        };
        let (blanked, refs) = RefTypes::blank_keywords(file, src, &toks);
        references = refs;
        let src = match blanked {
            Some(t) => {
                unreferenced = t;
                (toks, problems) = lex(&unreferenced);
                unreferenced.as_str()
            }
            None => src,
        };
        // `USING Siemens.Simatic.S71500.Tasks;`: blanked, one W1421 each (`using`; before the
        // qualifiers blank the file's own `NAMESPACE` words, which it reads)
        let src = match super::using::namespace_imports(file, src, &toks, diags) {
            Some(t) => {
                unimported = t;
                (toks, problems) = lex(&unimported);
                unimported.as_str()
            }
            None => src,
        };
        let src = match library_qualifiers(file, src, &toks, diags) {
            Some(t) => {
                unqualified = t;
                (toks, problems) = lex(&unqualified);
                unqualified.as_str()
            }
            None => src,
        };
        // `TASK Main : ProgramCycle;`: one E1048 each, blanked with the `WITH Main` (`using`)
        let src = match super::using::typed_tasks(file, src, &toks, diags) {
            Some(t) => {
                untasked = t;
                (toks, problems) = lex(&untasked);
                untasked.as_str()
            }
            None => src,
        };
        // `VAR_INST` outside a method: E0348, read as VAR
        let src = match super::var_inst::var_inst_outside_methods(file, src, &toks, diags) {
            Some(t) => {
                uninstanced = t;
                (toks, problems) = lex(&uninstanced);
                uninstanced.as_str()
            }
            None => src,
        };
        // `VAR_STAT`: read as VAR, the blocks named after the parse, hoisted once lowered (`var_stat`)
        let src = match super::var_stat::mark(file, src, &toks, diags) {
            Some((t, at)) => {
                unstatic = t;
                stat_at = at;
                (toks, problems) = lex(&unstatic);
                unstatic.as_str()
            }
            None => src,
        };
        // `TYPE ST_B EXTENDS ST_A : STRUCT`: a hidden first field of the base (struct_extends)
        match super::struct_extends::hide_bases(src, &toks) {
            Some(t) => {
                unextended = t;
                (toks, problems) = lex(&unextended);
                unextended.as_str()
            }
            None => src,
        }
    } else {
        src
    };
    let (pous, stray) = scan_tokens(src, &toks);
    // ST statements outside any POU (a CODESYS body copied without its `PROGRAM` header): one error,
    // and the IL parser does not read them (before: one IL error per line). An expression or a
    // call ended by `;` is one too (`table[k];`, `DSUB(TRUE, a, b, F);`: round 33, before read as
    // IL, two errors a line); in a `.st` file `;` ends a statement, it starts no comment
    let stray_st = lang == Lang::St
        && stray.iter().enumerate().any(|(n, &k)| {
            toks[k].tok == Tok::Assign
                || ["IF", "CASE", "FOR", "WHILE", "REPEAT"]
                    .iter()
                    .any(|w| is_word(src, &toks[k], w))
                || (toks[k].tok == Tok::Semi
                    && n > 0
                    && stray[n - 1] + 1 == k
                    && matches!(toks[k - 1].tok, Tok::RBracket | Tok::RParen))
        });
    // the declarations of such a body, its header missing (a CODESYS function block copied out
    // of its editor): blanked with the statements, so the file's one cause is one E0307
    let headless = stray_st
        .then(|| super::headless_body::find(src, &toks, &pous, &stray))
        .flatten();
    // a POU keyword that is a word of stray text (`... of this function` before `FUNCTION Twice`):
    // blanked, so the IL parser reports the stray text once and the POU after it stays whole
    let stray_keywords: Vec<Range<usize>> = stray
        .iter()
        .filter(|&&k| {
            ["PROGRAM", "FUNCTION", "FUNCTION_BLOCK"]
                .iter()
                .any(|w| is_word(src, &toks[k], w))
        })
        .map(|&k| toks[k].range.clone())
        .collect();
    // words outside every block of an `.st` file that has POUs (PC WORX writes a POU's description
    // as bare text between `(*@KEY@:DESCRIPTION*)` and `(*@KEY@:END_DESCRIPTION*)`): no implicit
    // IL program (that is an `.il` file's form), one error, and the POUs around them read
    let stray_text = lang == Lang::St
        && !stray_st
        && !pous.is_empty()
        && stray.iter().any(|&k| toks[k].tok != Tok::Semi);
    let stray: Vec<Range<usize>> = if stray_st || stray_text {
        stray
            .iter()
            .filter(|&&k| stray_st || toks[k].tok != Tok::Semi)
            .map(|&k| toks[k].range.clone())
            .collect()
    } else {
        Vec::new()
    };
    let var_config = var_config_blocks(file, src, &toks, diags);
    let type_modifiers: Vec<(std::ops::Range<usize>, String)> = (0..toks.len().saturating_sub(3))
        .filter(|&k| {
            is_word(src, &toks[k], "TYPE")
                && ["PUBLIC", "INTERNAL"]
                    .iter()
                    .any(|m| is_word(src, &toks[k + 1], m))
                && toks[k + 2].tok == Tok::Ident
                && toks[k + 3].tok == Tok::Colon
        })
        .map(|k| {
            (
                toks[k + 1].range.clone(),
                word(src, &toks[k + 2]).to_string(),
            )
        })
        .collect();
    // `VAR PUBLIC` (IEC 61131-3 ed. 3 access specifiers of a block's variables, Siemens AX): the
    // word changes nothing in one project (a variable named so, `VAR public : BOOL`, stays)
    // (also after the block's qualifiers: `VAR RETAIN PUBLIC`, `VAR CONSTANT PRIVATE`)
    let var_specifiers: Vec<(std::ops::Range<usize>, usize)> = (0..toks.len())
        .filter(|&k| is_word(src, &toks[k], "VAR"))
        .filter_map(|k| {
            let mut j = k + 1;
            while toks.get(j).is_some_and(|t| {
                ["RETAIN", "NON_RETAIN", "CONSTANT", "PERSISTENT"]
                    .iter()
                    .any(|q| is_word(src, t, q))
            }) {
                j += 1;
            }
            let spec = toks.get(j)?;
            let after = toks.get(j + 1)?;
            (["PUBLIC", "PRIVATE", "PROTECTED", "INTERNAL"]
                .iter()
                .any(|m| is_word(src, spec, m))
                && !matches!(after.tok, Tok::Colon | Tok::Comma))
            .then(|| (spec.range.clone(), toks[k].range.start))
        })
        .collect();
    drop(toks);
    let st_bodies: Vec<&PouText> = pous.iter().filter(|p| p.lang == Lang::St).collect();
    if let Some((unit, local)) = first_try {
        if st_bodies.is_empty() && var_config.0.is_empty() && !lists_blanked {
            diags.extend(local);
            return (unit, pending, Vec::new());
        }
        let mut text = src.to_string();
        // an IL file's VAR_CONFIG blocks (the IL parser has no rule for them) are read above
        for r in &var_config.0 {
            blank(&mut text, r.clone());
        }
        if let Some(first) = st_bodies.first() {
            let others = st_bodies.len() - 1;
            let names: Vec<&str> = st_bodies.iter().map(|p| p.name.as_str()).collect();
            let span = Span::new(file, first.body.start, first.body.end);
            let mut d = Diagnostic::error(
                code::E0300,
                format!(
                    "the body of `{}` is Structured Text, but this file is read as IL",
                    first.name
                ),
            )
            .at(trim_span(src, span))
            .with_primary_label("Structured Text")
            .with_hint("name the file `.st` or pass `--lang st` (ST files may hold IL bodies too)");
            if others > 0 {
                d = d.with_note(format!(
                    "{others} more POU bodies are ST too: {}",
                    names[1..].join(", ")
                ));
            }
            diags.push(d);
            for p in &st_bodies {
                blank(&mut text, p.body.clone());
            }
        }
        references.settle_initial_values(&mut text, &[]);
        let unit = crate::parse_named(file, &text, implicit_name, diags);
        return (unit, pending, var_config.1);
    }
    let mut text = src.to_string();
    for r in &stray_keywords {
        blank(&mut text, r.clone());
    }
    let lone_member = stray.first().and_then(|first| {
        let head = src.get(first.start..)?;
        ["METHOD", "PROPERTY"].into_iter().find(|w| {
            head.get(..w.len())
                .is_some_and(|h| h.eq_ignore_ascii_case(w))
                && head[w.len()..].starts_with(|c: char| c.is_whitespace())
        })
    });
    if let (Some(kind), Some(first), Some(last)) = (lone_member, stray.first(), stray.last()) {
        // a CODESYS export script's `Block.Method.st`: the method without its block (one error,
        // its declarations and statements blanked with it, so nothing else is read from them)
        let name_end = src[first.start..]
            .find(['\n', ':', '('])
            .map_or(first.end, |k| first.start + k);
        let unowned = Diagnostic::error(
            code::E1063,
            format!("a {} outside any FUNCTION_BLOCK", kind),
        )
        .at(trim_span(src, Span::new(file, first.start, name_end)))
        .with_primary_label(format!("this {} has no block", kind.to_ascii_lowercase()))
        .with_hint("give the block's file on the same command line, named so that this file's name is `Block.Member.st`, or move this text before the block's END_FUNCTION_BLOCK");
        // joined to its block once every file is read (`lone_members`)
        match super::lone_members::read(file, src, first.start, &stat_at, &mut references, diags) {
            Some(methods) => pending.push(PendingBody {
                methods,
                lone: Some(Box::new(super::lone_members::LoneMembers {
                    unowned,
                    owner: None,
                })),
                ..PendingBody::empty(file, usize::MAX)
            }),
            None => diags.push(unowned),
        }
        blank(&mut text, first.start..last.end);
    } else if let (true, Some(first), Some(last)) = (stray_text, stray.first(), stray.last()) {
        diags.push(super::stray_text::text_outside_pous(
            file, src, &stray, first, last,
        ));
        for r in &stray {
            blank(&mut text, r.clone());
        }
    } else if let (Some(first), Some(last)) = (stray.first(), stray.last()) {
        let lines = src[first.start..last.end].lines().count();
        diags.push(
            Diagnostic::error(
                code::E0307,
                "statements outside any POU: in a Structured Text file they belong in a PROGRAM, FUNCTION_BLOCK or FUNCTION",
            )
            .at(trim_span(src, Span::new(file, first.start, last.end)))
            .with_primary_label(format!(
                "not compiled (the statements outside POUs span {lines} line{})",
                if lines == 1 { "" } else { "s" }
            ))
            .with_hint(match &headless {
                Some(body) => body.hint(implicit_name),
                None => format!(
                    "wrap them in `PROGRAM {implicit_name}` ... `END_PROGRAM` with their declarations in a VAR block (a CODESYS body exported alone lacks both)"
                ),
            }),
        );
        for r in stray.iter().chain(headless.iter().flat_map(|b| &b.blocks)) {
            blank(&mut text, r.clone());
        }
    }
    // `TYPE INTERNAL BlockInterval : STRUCT ...` (CODESYS/TwinCAT access specifier of a DUT,
    // stefanbesler/struckig): as for a POU, the modifier changes nothing in one project
    for (k, type_name) in &type_modifiers {
        {
            let r = k.clone();
            let m = src.get(r.clone()).unwrap_or("").to_ascii_uppercase();
            diags.push(
                Diagnostic::warning(
                    code::W0304,
                    format!("`TYPE {m}` of `{type_name}`: the modifier is ignored"),
                )
                .at(Span::new(file, r.start, r.end))
                .with_primary_label("ignored")
                .with_hint("PUBLIC and INTERNAL say whether a library's (or namespace's) user may reach the declaration; ladderc compiles the files given as one project, every declaration reachable, so the word changes nothing; remove it to silence this"),
            );
            blank(&mut text, r);
        }
    }
    // the access specifiers of a class's and a function block's own blocks are kept (set on the
    // parsed blocks: `classes::set_access`); elsewhere (a PROGRAM's, a FUNCTION's) ignored
    let in_block = |at: usize| {
        pous.iter().any(|p| {
            p.name_range.end <= at
                && at < p.body.end
                && p.actions.is_none()
                && p.interface.is_none()
                && src
                    .get(..p.modifier.as_ref().map_or(p.name_range.start, |m| m.start))
                    .and_then(|h| h.split_whitespace().last())
                    .is_some_and(|k| {
                        k.eq_ignore_ascii_case("FUNCTION_BLOCK") || k.eq_ignore_ascii_case("CLASS")
                    })
        })
    };
    let mut kept_access: Vec<(usize, crate::ast::Access)> = Vec::new();
    for (r, var_at) in &var_specifiers {
        let m = src.get(r.clone()).unwrap_or("").to_ascii_uppercase();
        if in_block(*var_at) {
            let access = match m.as_str() {
                "PRIVATE" => crate::ast::Access::Private,
                "PROTECTED" => crate::ast::Access::Protected,
                _ => crate::ast::Access::Public,
            };
            kept_access.push((*var_at, access));
            blank(&mut text, r.clone());
            continue;
        }
        diags.push(
            Diagnostic::warning(
                code::W0304,
                format!("`VAR {m}`: the access specifier is ignored"),
            )
            .at(Span::new(file, r.start, r.end))
            .with_primary_label("ignored")
            .with_hint("outside a CLASS or FUNCTION_BLOCK an access specifier restricts nothing: the variables are read as the POU's VAR (reachable as `inst.x`, W1412); remove the word to silence this"),
        );
        blank(&mut text, r.clone());
    }
    // the global variables of this file, which a POU's initial value may read at run time (the
    // project's other files: `pou_inits::set_project_globals`)
    let file_globals: std::collections::HashSet<String> =
        super::pou_inits::global_variable_names(src)
            .into_iter()
            .collect();
    // the ranges of `:= expr` computed at run time: a reference's initial value among them is
    // no E0305 (`RefTypes::settle_initial_values`)
    let mut computed: Vec<Range<usize>> = Vec::new();
    for p in &pous {
        if let Some(r) = &p.modifier {
            // FINAL and ABSTRACT are checked with inheritance (`super::inherit`)
            let m = src
                .get(r.clone())
                .unwrap_or("")
                .to_ascii_uppercase()
                .split_whitespace()
                .filter(|w| *w != "FINAL" && *w != "ABSTRACT")
                .collect::<Vec<_>>()
                .join(" ");
            if !m.is_empty() {
                diags.push(
                    Diagnostic::warning(
                        code::W0304,
                        format!(
                            "`{} {m}` of `{}`: the modifier is ignored",
                            src.get(..r.start)
                                .and_then(|h| h.split_whitespace().last())
                                .map_or("FUNCTION_BLOCK".to_string(), str::to_ascii_uppercase),
                            p.name
                        ),
                    )
                    .at(Span::new(file, r.start, r.end))
                    .with_primary_label("ignored")
                    .with_hint("PUBLIC and INTERNAL say whether a library's (or namespace's) user may reach the declaration; ladderc compiles the files given as one project, every declaration reachable, so the word changes nothing; remove it to silence this"),
                );
            }
            blank(&mut text, r.clone());
        }
    }
    // ST: pragmas and comments read without nesting outside bodies are reported here (those inside
    // ST bodies by the ST parser), and blanked for the declarations' reader; an `{attribute
    // 'to_string'}` is read (the first type declared after it gets it)
    let mut to_string_at: Vec<usize> = Vec::new();
    let mut strict_at: Vec<usize> = Vec::new();
    let mut redund_reported = false;
    for pr in &problems {
        if let Problem::FlatComment(r) = pr {
            if !st_bodies
                .iter()
                .any(|p| p.body.start <= r.start && r.end <= p.body.end)
            {
                diags.push(super::lexer::flat_comment_diagnostic(Span::new(
                    file, r.start, r.end,
                )));
                blank(&mut text, r.clone());
            }
        }
        if let Problem::Pragma(r) = pr {
            if !st_bodies
                .iter()
                .any(|p| p.body.start <= r.start && r.end <= p.body.end)
            {
                let pragma = src.get(r.clone()).unwrap_or("{}");
                if is_attribute(pragma, "to_string") {
                    to_string_at.push(r.end);
                } else if is_attribute(pragma, "strict") {
                    strict_at.push(r.end);
                } else if super::lexer::is_redundancy_pragma(pragma) {
                    // B&R's `{REDUND_ERROR}` before each of a library's blocks: one note a file
                    if !redund_reported {
                        redund_reported = true;
                        diags.push(
                            pragma_diagnostic(pragma, Span::new(file, r.start, r.end))
                                .with_note("a B&R redundancy pragma (for redundant controllers); the file's others are ignored too, without a note"),
                        );
                    }
                } else if !super::fb_init::is_call_after_init(pragma) {
                    diags.push(pragma_diagnostic(pragma, Span::new(file, r.start, r.end)));
                }
                blank(&mut text, r.clone());
            }
        }
    }
    for (pi, p) in pous.iter().enumerate() {
        if p.interface.is_some() {
            // an INTERFACE: its methods' signatures, checked against the blocks that implement it
            // (with their POINTER TO / REFERENCE TO parameters, as a block's methods: E0335
            // compared `POINTER TO LREAL` with `LREAL` before)
            let mut methods: Vec<PendingMethod> = p
                .methods
                .iter()
                .map(|m| {
                    let mut pm = pending_method(file, src, m, diags);
                    super::var_stat::name_method_blocks(&mut pm, &stat_at);
                    references.apply_to_method(&mut pm.blocks, pm.ret.as_mut());
                    pm
                })
                .collect();
            for pr in &p.properties {
                for mut pm in super::property::pending_accessors(file, src, pr, diags) {
                    references.apply_to_method(&mut pm.blocks, pm.ret.as_mut());
                    methods.push(pm);
                }
            }
            // their `POINTER TO` / `REFERENCE TO` types, as the blocks' methods get them
            for pm in &mut methods {
                references.apply_to_method(&mut pm.blocks, pm.ret.as_mut());
            }
            pending.push(PendingBody {
                file,
                name_start: p.name_range.start,
                base: p.body.start,
                text: String::new(),
                actions: Vec::new(),
                sfc: false,
                il: false,
                methods: Vec::new(),
                oop: Some(Box::new(super::inherit::Oop::interface(
                    file, src, p, methods,
                ))),
                fb_init_args: Vec::new(),
                after_init: Vec::new(),
                lone: None,
                var_inits: Vec::new(),
            });
            blank(&mut text, p.body.clone());
            continue;
        }
        if let Some(r) = &p.actions {
            // the actions of the ST POU just before the block: inlined where its body calls them;
            // or of the chart just before it, whatever its statements look like (a chart of one
            // step, `INITIAL_STEP S0 : A(N); END_STEP TRANSITION FROM S0 TO S0 := go;`, has a
            // label-like `S0 :` and one `:=`, which `body_lang` counts as IL: before round 31 its
            // actions were refused, E0304, and the chart named unknown actions, E3122)
            let owner = pi.checked_sub(1).and_then(|k| pous.get(k)).filter(|q| {
                q.actions.is_none() && (q.lang == Lang::St || q.sfc.is_some()) && q.oop.is_none()
            });
            // ... or of the IL POU just before it (CODESYS V2.3 exports an IL program with its
            // actions so): its body stays the IL read below, the actions are lowered with it
            let il_owner = pi.checked_sub(1).and_then(|k| pous.get(k)).filter(|q| {
                q.actions.is_none()
                    && q.lang == Lang::Il
                    && q.oop.is_none()
                    && q.heritage.is_none()
                    && q.methods.is_empty()
                    && q.properties.is_empty()
                    && !p.action_list.is_empty()
                    && pending
                        .last()
                        .is_none_or(|pb| pb.name_start != q.name_range.start)
            });
            if let Some(q) = il_owner {
                pending.push(PendingBody {
                    base: q.body.start,
                    il: true,
                    ..PendingBody::empty(file, q.name_range.start)
                });
            }
            let owner = owner.or(il_owner);
            if let (Some(q), Some(pb)) = (owner, pending.last_mut()) {
                if pb.name_start == q.name_range.start && !p.action_list.is_empty() {
                    for (name, name_range, text) in &p.action_list {
                        pb.actions.push((
                            crate::ast::Ident::new(
                                name,
                                Span::new(file, name_range.start, name_range.end),
                            ),
                            src.get(text.clone()).unwrap_or("").to_string(),
                            text.start,
                        ));
                    }
                    blank(&mut text, p.body.clone());
                    continue;
                }
            }
            if p.name == "ACTION" {
                // a B&R program folder's actions file: the actions go to the folder's program
                // (`ladderc`'s `br_programs`), or to the block its file name names (`lone_members`)
                let first = &p.action_list[0];
                let unowned = Diagnostic::error(
                    code::E1060,
                    format!("action `{}` outside any POU: no program or block it belongs to", src.get(first.1.clone()).unwrap_or("")),
                )
                .at(Span::new(file, r.start, first.1.end))
                .with_primary_label("not compiled")
                .with_hint("give the B&R program folder's `_CYCLIC` file on the same command line, or put the actions in an `ACTIONS ... END_ACTIONS` block right after their POU");
                pending.push(PendingBody {
                    actions: p
                        .action_list
                        .iter()
                        .map(|(name, name_range, text)| {
                            (
                                crate::ast::Ident::new(
                                    name,
                                    Span::new(file, name_range.start, name_range.end),
                                ),
                                src.get(text.clone()).unwrap_or("").to_string(),
                                text.start,
                            )
                        })
                        .collect(),
                    lone: Some(Box::new(super::lone_members::LoneMembers {
                        unowned,
                        owner: None,
                    })),
                    ..PendingBody::empty(file, usize::MAX)
                });
                blank(&mut text, p.body.clone());
                continue;
            }
            diags.push(
                Diagnostic::error(
                    code::E0304,
                    "an ACTIONS block is supported only right after a POU whose body is ST or IL",
                )
                .at(Span::new(file, r.start, r.end))
                .with_primary_label("the block starts here; it is not compiled")
                .with_hint("put the block after the POU whose ST or IL body calls its actions, or write each action's statements where it is called"),
            );
            blank(&mut text, p.body.clone());
            continue;
        }
        if let Some(r) = &p.header_semi {
            blank(&mut text, r.clone());
        }
        if p.sfc.is_some() {
            // `FUNCTION_BLOCK Seq EXTENDS FB_Base IMPLEMENTS I_X` with an SFC body (TwinCAT lets
            // any function block extend another, whatever the language of its body: Infosys
            // "Extending a function block"): the declarations are read without the clause, and
            // the block is flattened with its bases as an ST block is (`super::inherit`; before
            // round 29 the clause was read as the first instruction: E0015)
            if let Some(h) = &p.heritage {
                blank(&mut text, h.clone());
            }
            let oop = super::inherit::Oop::block(file, src, p);
            // the methods and properties of a chart's block (TwinCAT, CODESYS) are cut out of the
            // chart (blanked, so positions stay) and lowered with the block
            let mut body = src.to_string();
            let mut methods = Vec::new();
            let mut method_diags = Diagnostics::new();
            pending_members(
                (file, src, p, &stat_at),
                &mut references,
                &mut body,
                &mut methods,
                (&mut method_diags, diags),
            );
            diags.extend(method_diags);
            // initial values read from other variables, as in an ST block (W1433; before round
            // 31 E1025 in a chart's block): assigned before the chart's first scan
            // (`compile_pending`, then the chart, ladderc's `lower_textual_sfc`)
            let var_inits = super::pou_inits::pou_var_inits(
                (file, src, p.name_range.end..p.body.start),
                &mut text,
                false,
                &file_globals,
                &mut computed,
                diags,
            );
            pending.push(PendingBody {
                file,
                name_start: p.name_range.start,
                base: p.body.start,
                text: body.get(p.body.clone()).unwrap_or("").to_string(),
                actions: Vec::new(),
                sfc: true,
                il: false,
                methods,
                oop: oop.map(Box::new),
                fb_init_args: Vec::new(),
                after_init: Vec::new(),
                lone: None,
                var_inits,
            });
            blank(&mut text, p.body.clone());
            continue;
        }
        if let Some(h) = &p.heritage {
            // `FUNCTION_BLOCK Child EXTENDS Base`: the declarations are read without the clause
            blank(&mut text, h.clone());
        }
        let in_block = src
            .get(..p.modifier.as_ref().map_or(p.name_range.start, |m| m.start))
            .and_then(|h| h.split_whitespace().last())
            .is_some_and(|k| k.eq_ignore_ascii_case("FUNCTION_BLOCK"));
        if let (Some(r), true) = (&p.oop, in_block) {
            // a function block's PROPERTY that scan_properties could not read, or a METHOD
            // that is not one (`METHOD Twice : INT;` among the declarations, no END_METHOD)
            let method = src
                .get(r.clone())
                .is_some_and(|k| k.eq_ignore_ascii_case("METHOD"));
            let d = if method {
                Diagnostic::error(
                    code::E0100,
                    format!("`{}`: this METHOD cannot be read", p.name),
                )
                .at(Span::new(file, r.start, r.end))
                .with_primary_label("METHOD without its body or its END_METHOD")
                .with_hint("a method is written after the block's declarations and body: `METHOD name : type`, its declarations, its statements, then `END_METHOD` (in TwinCAT, a Method object of the block); there is no forward `METHOD name : type;` line; the body of this POU is not compiled")
            } else {
                Diagnostic::error(
                    code::E0100,
                    format!("`{}`: this PROPERTY cannot be read", p.name),
                )
                .at(Span::new(file, r.start, r.end))
                .with_primary_label("PROPERTY without its type, its accessors or its END_PROPERTY")
                .with_hint("write `PROPERTY name : type`, then `GET ... END_GET` and/or `SET ... END_SET`, then `END_PROPERTY`; the body of this POU is not compiled")
            };
            diags.push(d);
            blank(&mut text, p.body.clone());
            continue;
        }
        if let Some(r) = p.oop.as_ref() {
            let what = src.get(r.clone()).unwrap_or("METHOD").to_ascii_uppercase();
            diags.push(
                Diagnostic::error(
                    code::E0303,
                    format!(
                        "`{}` holds a {what}: object-oriented extensions (IEC 61131-3 ed. 3, CODESYS) are not supported",
                        p.name
                    ),
                )
                .at(Span::new(file, r.start, r.end))
                .with_primary_label(format!("{what} starts here"))
                .with_hint("write the method as a FUNCTION (or an action as part of the body); the body of this POU is not compiled"),
            );
            blank(&mut text, p.body.clone());
            continue;
        }
        // EXTENDS / IMPLEMENTS / FINAL / ABSTRACT of a function block (edition 3): flattened and
        // checked by `super::inherit` once every file is read
        let oop = super::inherit::Oop::block(file, src, p);
        // (its methods and properties left out: a block whose members are all its code, TwinCAT's
        // empty body, has no body and is ST)
        let blank_body = src.get(p.body.clone()).is_none_or(|b| {
            lex(b).0.iter().all(|t| {
                let at = p.body.start + t.range.start;
                matches!(t.tok, Tok::Eof)
                    || p.methods.iter().any(|m| m.whole.contains(&at))
                    || p.properties.iter().any(|q| q.whole.contains(&at))
            })
        });
        // (the keyword before the name, past modifiers: `FUNCTION_BLOCK PUBLIC B`)
        let function = src
            .get(..p.name_range.start)
            .unwrap_or("")
            .split_whitespace()
            .rev()
            .take(3)
            .find(|w| {
                ["FUNCTION", "FUNCTION_BLOCK", "PROGRAM", "CLASS"]
                    .iter()
                    .any(|k| w.eq_ignore_ascii_case(k))
            })
            .is_some_and(|w| w.eq_ignore_ascii_case("FUNCTION"));
        // initial values computed at run time (`pou_inits::pou_run_time_inits`) are ST
        // statements: an empty body is then ST
        let run_time_inits = blank_body
            && p.name_range.end < p.body.start
            && super::pou_inits::pou_run_time_inits(
                &text,
                p.name_range.end..p.body.start,
                function,
                &file_globals,
            )
            .is_some();
        let lang = if (oop.is_some()
            || !p.methods.is_empty()
            || !p.properties.is_empty()
            || run_time_inits)
            && blank_body
        {
            Lang::St
        } else {
            p.lang
        };
        if let (Some(h), Lang::Il) = (&p.heritage, lang) {
            diags.push(
                Diagnostic::error(
                    code::E0303,
                    format!(
                        "`{}` has an EXTENDS or IMPLEMENTS clause and an instruction list body: inheritance is compiled for Structured Text bodies only",
                        p.name
                    ),
                )
                .at(Span::new(file, h.start, h.end))
                .with_primary_label("the clause starts here")
                .with_hint("write the body in Structured Text (SUPER^ is not defined for IL in CODESYS and TwinCAT either); the body of this POU is not compiled"),
            );
            blank(&mut text, p.body.clone());
            continue;
        }
        if lang != Lang::St {
            for pr in &p.properties {
                diags.push(
                    Diagnostic::error(
                        code::E0303,
                        format!(
                            "PROPERTY `{}` of `{}`: the properties of a function block whose body is instruction list are not compiled",
                            pr.name, p.name
                        ),
                    )
                    .at(Span::new(file, pr.name_range.start, pr.name_range.end))
                    .with_primary_label("not compiled")
                    .with_hint("write the block's body in ST (its accessors are compiled as methods of an ST block), or read the variable the property stands for"),
                );
                blank(&mut text, pr.whole.clone());
            }
        }
        if let Some(at) = begin_il_section(src, p.body.clone()) {
            // `BEGIN_IL` ... `END_IL`: IL inside an ST body (Straton / K5 / Kollmorgen KAS
            // workbenches). IEC 61131-3 writes a body in one language; one error, and the body
            // is not compiled (as ST it would be one error per IL line).
            diags.push(
                Diagnostic::error(
                    code::E1046,
                    format!(
                        "`{}`: `BEGIN_IL` ... `END_IL` (an instruction list section inside an ST body) is a workbench extension, not IEC 61131-3",
                        p.name
                    ),
                )
                .at(Span::new(file, at, at + "BEGIN_IL".len()))
                .with_primary_label("IL section in an ST body")
                .with_hint("write the section in ST, or move its instructions into a FUNCTION or FUNCTION_BLOCK whose body is IL and call it; the body of this POU is not compiled"),
            );
            blank(&mut text, p.body.clone());
            continue;
        }
        match lang {
            Lang::St => {
                // the methods are cut out of the body (blanked, so positions stay) and lowered
                // with the block
                let mut body = src.to_string();
                let mut methods = Vec::new();
                // a derived block's methods are reported once its base is found (no cascade
                // after E0330 when the base is a library's)
                let mut oop = oop;
                let mut deferred = Diagnostics::new();
                let derived =
                    matches!(&oop, Some(super::inherit::Oop::Block(b)) if !b.extends.is_empty());
                let mut now = Diagnostics::new();
                let method_sink = if derived { &mut deferred } else { &mut now };
                pending_members(
                    (file, src, p, &stat_at),
                    &mut references,
                    &mut body,
                    &mut methods,
                    (method_sink, diags),
                );
                diags.extend(now);
                if let Some(super::inherit::Oop::Block(b)) = &mut oop {
                    // a bound naming another file's constant (E0022) is reported now: the file is
                    // then read again with the other files' constants known (Struckig's tests:
                    // `ARRAY[0..ParameterList.MaxDoFs]` in a method of a TcUnit test suite)
                    let (now, later): (Vec<_>, Vec<_>) = deferred
                        .into_vec()
                        .into_iter()
                        .partition(|d| d.code == code::E0022);
                    diags.extend(now);
                    b.deferred = later;
                }
                // the run-time initial values of its own variables: assignments, left out of the
                // declarations
                let var_inits = super::pou_inits::pou_var_inits(
                    (file, src, p.name_range.end..p.body.start),
                    &mut text,
                    function,
                    &file_globals,
                    &mut computed,
                    diags,
                );
                pending.push(PendingBody {
                    file,
                    name_start: p.name_range.start,
                    base: p.body.start,
                    text: body.get(p.body.clone()).unwrap_or("").to_string(),
                    actions: Vec::new(),
                    sfc: false,
                    il: false,
                    methods,
                    oop: oop.map(Box::new),
                    fb_init_args: Vec::new(),
                    after_init: super::fb_init::after_init_methods(file, src, p, diags),
                    lone: None,
                    var_inits,
                });
                blank(&mut text, p.body.clone());
            }
            _ if !src.get(p.body.clone()).unwrap_or("").trim().is_empty() => {
                let span = Span::new(file, p.name_range.start, p.name_range.end);
                diags.push(
                    Diagnostic::new(
                        code::W0303,
                        Severity::Note,
                        format!("the body of `{}` is instruction list: read as IL", p.name),
                    )
                    .at(span)
                    .with_hint("ST files may hold IL bodies, as matiec allows"),
                );
            }
            _ => {}
        }
    }
    // A comment never closed takes the rest of the file, its `END_PROGRAM` ... too: the body's
    // parse reports it (E0102); a missing `END_*` after its opening follows from it.
    let unclosed = problems.iter().find_map(|p| match p {
        Problem::UnterminatedComment(r) => Some(r.start),
        _ => None,
    });
    // the global lists outside the POUs: their initial values computed at run time, once before
    // the first cycle (`pou_inits::global_run_time_inits`, `fb_init::add_init_calls`)
    let mut global_inits: Vec<VarInits> = Vec::new();
    let mut inside: Vec<Range<usize>> = pous
        .iter()
        .map(|p| p.name_range.start..p.body.end.max(p.name_range.end))
        .collect();
    inside.sort_by_key(|r| r.start);
    let mut outside = Vec::new();
    let mut at = 0;
    for r in inside {
        if r.start > at {
            outside.push(at..r.start);
        }
        at = at.max(r.end);
    }
    outside.push(at..text.len());
    for region in outside {
        let Some(super::pou_inits::Found {
            cut,
            inits,
            prefixed,
            unplaceable,
        }) = super::pou_inits::global_run_time_inits(&text, region.clone(), &file_globals)
        else {
            continue;
        };
        for (name, at) in &unplaceable {
            diags.push(super::pou_inits::unplaceable_error(
                src.get(name.clone()).unwrap_or(""),
                Span::new(file, at.start, at.end),
            ));
        }
        let placed =
            |(name, _): &&(Range<usize>, Range<usize>)| !unplaceable.iter().any(|(n, _)| n == name);
        if let (Some((name, value)), true) = (cut.iter().find(placed), global_inits.is_empty()) {
            diags.push(super::pou_inits::computed_global_warning(
                src.get(name.clone()).unwrap_or(""),
                Span::new(file, value.start, value.end),
            ));
        }
        for (_, r) in cut {
            computed.push(r.clone());
            blank(&mut text, r);
        }
        global_inits.push((file, inits, region.start, prefixed));
    }
    if !global_inits.is_empty() {
        pending.push(PendingBody {
            var_inits: global_inits,
            ..PendingBody::empty(file, usize::MAX)
        });
    }
    for r in &var_config.0 {
        blank(&mut text, r.clone());
    }
    references.settle_initial_values(&mut text, &computed);
    let mut local = Diagnostics::new();
    let mut unit = crate::parse_named(file, &text, implicit_name, &mut local);
    super::classes::set_access(&mut unit, file, src, &pous, &kept_access, &mut local);
    super::var_stat::name_blocks(&mut unit, file, &stat_at);
    restore_field_names(&mut unit, &keyword_fields);
    references.apply(&mut unit, &mut local);
    let marked = types_after(&unit, &to_string_at);
    unit.to_string_types.extend(marked);
    let marked = types_after(&unit, &strict_at);
    unit.strict_types.extend(marked);
    match unclosed {
        Some(at) => diags.extend(local.into_vec().into_iter().filter(|d| {
            !(d.code == code::E0008 && d.span.is_some_and(|s| s.start as usize >= at))
        })),
        None => diags.extend(end_at_end_of_file(file, src, &pous, local)),
    }
    if !decl_args.is_empty() {
        pending.push(PendingBody {
            fb_init_args: decl_args,
            ..PendingBody::empty(file, usize::MAX)
        });
    }
    (unit, pending, var_config.1)
}

/// The diagnostics of an ST file's declarations, with a last POU left open at the end of the file
/// (`PROGRAM p VAR .. END_VAR x := 1;` and no `END_PROGRAM`: the text of a CODESYS or TwinCAT POU
/// as their editors show it, declaration and implementation one after the other) taken as closed
/// there: warning W0014 instead of the E0008 of its missing `END_*`. Only the last POU, only when
/// nothing else in the file is left open (no other E0008) and only when its body holds no POU,
/// TYPE or CONFIGURATION keyword (a missing `END_*` before another POU stays E0008).
fn end_at_end_of_file(
    file: FileId,
    src: &str,
    pous: &[PouText],
    local: Diagnostics,
) -> Vec<Diagnostic> {
    let mut out = local.into_vec();
    let Some(last) = pous
        .iter()
        .rev()
        .find(|p| p.actions.is_none() && p.interface.is_none())
    else {
        return out;
    };
    let body = src.get(last.body.clone()).unwrap_or("");
    let at_end = src.get(last.body.end..).unwrap_or("").trim().is_empty();
    let kw = src
        .get(..last.name_range.start)
        .and_then(|head| head.split_whitespace().last())
        .map(str::to_ascii_uppercase)
        .filter(|k| ["PROGRAM", "FUNCTION", "FUNCTION_BLOCK"].contains(&k.as_str()))
        .or_else(|| {
            // `FUNCTION_BLOCK PUBLIC name`: the keyword is the word before the modifier
            let head = src.get(..last.modifier.as_ref()?.start)?;
            head.split_whitespace().last().map(str::to_ascii_uppercase)
        });
    let Some(kw) = kw else {
        return out;
    };
    // words, not comments: `// this program ...` is no POU
    let nested = lex(body).0.iter().any(|t| {
        [
            "PROGRAM",
            "FUNCTION",
            "FUNCTION_BLOCK",
            "TYPE",
            "CONFIGURATION",
            "RESOURCE",
        ]
        .iter()
        .any(|k| is_word(body, t, k))
    });
    let missing = format!("missing `END_{kw}`");
    let open: Vec<usize> = (0..out.len())
        .filter(|&i| out[i].code == code::E0008)
        .collect();
    let [only] = open[..] else {
        return out;
    };
    if !at_end
        || nested
        || out[only].message != missing
        || out[only]
            .span
            .is_none_or(|s| (s.start as usize) < last.body.end)
    {
        return out;
    }
    let name = Span::new(file, last.name_range.start, last.name_range.end);
    let here = out[only].span.unwrap_or(name);
    out[only] = Diagnostic::warning(
        code::W0014,
        format!(
            "`{}` ends at the end of the file without `END_{kw}`: read as if it were there",
            last.name
        ),
    )
    .at(here)
    .with_primary_label(format!("`END_{kw}` supplied here"))
    .with_label(name, format!("`{kw}` opened here"))
    .with_hint(format!(
        "IEC 61131-3 closes every POU with `END_{kw}` (CODESYS and TwinCAT editors show a POU without it); write it to make the file portable"
    ));
    out
}

/// The first line of `span`'s text, without surrounding white space.
pub(super) fn trim_span(src: &str, span: Span) -> Span {
    let (s, e) = (span.start as usize, span.end as usize);
    let part = src.get(s..e).unwrap_or("");
    let lead = part.len() - part.trim_start().len();
    let rest = &part[lead..];
    let line = rest.split(['\n', '\r']).next().unwrap_or("").trim_end();
    Span::new(span.file, s + lead, s + lead + line.len())
}

/// The FUNCTIONs of `units` without result type whose pending body assigns the function's name
/// (`F := ...` at a statement's start, found by tokens), upper case: their body's E0354 is the one
/// error (before round 32 each call using the value was one more E0354: three errors for a B&R
/// function whose `.fun` declaration was not given).
fn missing_result_assigners(
    units: &[CompilationUnit],
    pending: &[PendingBody],
) -> std::collections::HashSet<String> {
    let mut out = std::collections::HashSet::new();
    for pb in pending.iter().filter(|pb| !pb.sfc && !pb.il) {
        let Some(p) = pb.pou(units) else {
            continue;
        };
        if p.kind != crate::ast::PouKind::Function || p.return_type.is_some() {
            continue;
        }
        let (toks, _) = lex(&pb.text);
        let assigned = toks.windows(2).enumerate().any(|(k, w)| {
            w[0].tok == Tok::Ident
                && w[1].tok == Tok::Assign
                && pb.text[w[0].range.clone()].eq_ignore_ascii_case(&p.name.name)
                && (k == 0
                    || matches!(
                        toks[k - 1].tok,
                        Tok::Semi | Tok::Kw(Kw::Then | Kw::Else | Kw::Do)
                    ))
        });
        if assigned {
            out.insert(p.name.key());
        }
    }
    out
}

/// Lowers the pending ST bodies into their POUs. `units` must hold every unit of the program (the
/// declarations of all of them are visible to every body).
pub fn compile_pending(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
    diags: &mut Diagnostics,
) {
    compile_pending_with_library(units, pending, &[], diags);
}

/// [`compile_pending`], the bodies also seeing the global constants of a block library the
/// program is checked against later (`library_constants`: name and elementary type, e.g. Tc2_MC2's
/// `MC_Positive_Direction : USINT`), where the program declares no global of that name: a value
/// computed from them (`SEL(c, MC_Positive_Direction, MC_Negative_Direction)` given to a block's
/// input) is kept in a temporary of their type, not of the DINT an unknown value would get.
pub fn compile_pending_with_library(
    units: &mut [CompilationUnit],
    pending: &[PendingBody],
    library_constants: &[(&str, &str)],
    diags: &mut Diagnostics,
) {
    // structures that EXTEND others get their bases' fields (from any unit)
    super::struct_extends::flatten(units);
    if pending.is_empty() {
        super::var_stat::hoist(units);
        return;
    }
    // a FUNCTION's ANY inputs: their hidden size, class and address inputs (`any_inputs`), the
    // address when the function's body reads `.pValue` or passes the input on
    let body_of = |at: Span| {
        pending
            .iter()
            .find(|b| b.file == at.file && b.name_start == at.start as usize)
            .map(|b| b.text.as_str())
    };
    super::any_inputs::split_decls(units, &body_of);
    // methods exported one file each joined to their blocks
    let joined;
    let pending = match super::lone_members::attach(units, pending, diags) {
        Some(v) => {
            joined = v;
            &joined[..]
        }
        None => pending,
    };
    // variable-length in-outs (`ARRAY [*] OF T`): their hidden address and bound inputs (`varlen`)
    let split;
    let pending = match super::varlen::split_decls(units, pending) {
        Some(v) => {
            split = v;
            &split[..]
        }
        None => pending,
    };
    // a METHOD's ANY inputs split as a function's (`any_inputs`), before the methods join
    let split_methods;
    let pending = match super::any_inputs::split_method_inputs(pending) {
        Some(v) => {
            split_methods = v;
            &split_methods[..]
        }
        None => pending,
    };
    // the blocks whose text declares an FB_init (before a block that is not compiled loses it),
    // and the blocks that are not compiled because their base is no block of the project (E0330:
    // a library's base, `EXTENDS TcBaseModuleRegistered`, may declare the FB_init their instances'
    // arguments go to, so those arguments are no E0329 more)
    let blocks: std::collections::HashSet<String> = units
        .iter()
        .flat_map(|u| u.items.iter())
        .filter_map(|i| match i {
            LibraryElement::Pou(p) if p.kind == crate::ast::PouKind::FunctionBlock => {
                Some(p.name.key())
            }
            _ => None,
        })
        .collect();
    // the variables of `.fun` declarations named with a keyword (`Type`), read only as
    // `blk(Type := x)` and `blk.Type`: no reason not to compile the block's body
    let keyword_parameters: std::collections::HashSet<(FileId, u32)> = units
        .iter()
        .flat_map(|u| u.keyword_parameters.iter().map(|s| (s.file, s.start)))
        .collect();
    let declares_fb_init: std::collections::HashSet<String> = pending
        .iter()
        .filter(|pb| {
            pb.methods.iter().any(|m| m.name.is("FB_init"))
                || matches!(pb.oop.as_deref(), Some(super::inherit::Oop::Block(b))
                    if b.extends.iter().any(|e| !blocks.contains(&e.key())))
        })
        .filter_map(|pb| pb.pou_name(units).map(|n| n.key()))
        .collect();
    // a METHOD's own instances declared with FB_init arguments: FB_init at each call
    let localised;
    let pending = match methods_take_local_args(pending, &declares_fb_init) {
        Some(v) => {
            localised = v;
            &localised[..]
        }
        None => pending,
    };
    // implicit enumerations (`state : (IDLE, RUN);`) named, so their values are typed by context
    let named;
    let pending = match super::implicit_enums::name_all(units, pending) {
        Some(v) => {
            named = v;
            &named[..]
        }
        None => pending,
    };
    // edition 3 inheritance: derived blocks flattened (their bases' variables, methods, actions)
    let flat;
    let mut interfaces = Vec::new();
    let mut inits = Vec::new();
    let mut bases = std::collections::HashMap::new();
    let mut derived = std::collections::HashMap::new();
    let pending = match super::inherit::flatten(units, pending, diags) {
        Some(v) => {
            flat = v.bodies;
            interfaces = v.interfaces;
            inits = v.inits;
            bases = v.bases;
            derived = v.derived;
            &flat[..]
        }
        None => pending,
    };
    // code a derived block inherits is lowered again in it: its errors are reported once
    let mut inherited = Diagnostics::new();
    // the hidden variables of the methods first: other POUs' calls read their results
    // (`c.Add(1)` is `c.__M_ADD`)
    for pb in pending.iter().filter(|pb| !pb.methods.is_empty()) {
        for unit in units.iter_mut() {
            for item in unit.items.iter_mut() {
                let LibraryElement::Pou(p) = item else {
                    continue;
                };
                if p.name.span.file == pb.file && p.name.span.start as usize == pb.name_start {
                    add_method_vars(p, &pb.methods, diags);
                }
            }
        }
    }
    // an ACTION named like a variable of its block (its methods': in add_method_vars)
    for pb in pending.iter().filter(|pb| !pb.actions.is_empty()) {
        for unit in units.iter() {
            for item in unit.items.iter() {
                let LibraryElement::Pou(p) = item else {
                    continue;
                };
                if p.name.span.file == pb.file && p.name.span.start as usize == pb.name_start {
                    let actions = pb
                        .actions
                        .iter()
                        .map(|(a, _, _)| ("an action", a.name.clone(), a.span));
                    member_name_clashes(p, actions, diags);
                }
            }
        }
    }
    let mut decls = super::Declarations::from_units(units);
    for (name, ty) in library_constants {
        decls
            .globals
            .entry(name.to_ascii_uppercase())
            .or_insert_with(|| super::infer::named(ty, Span::new(FileId(0), 0, 0)));
    }
    decls.assigns_missing_result = missing_result_assigners(units, pending);
    for pb in pending.iter().filter(|pb| !pb.methods.is_empty()) {
        for unit in units.iter() {
            for item in unit.items.iter() {
                let LibraryElement::Pou(p) = item else {
                    continue;
                };
                if p.name.span.file == pb.file && p.name.span.start as usize == pb.name_start {
                    decls.methods.insert(
                        p.name.key(),
                        pb.methods.iter().map(super::types::MethodSig::of).collect(),
                    );
                }
            }
        }
    }
    // variables of an interface type: their calls dispatch on the instance they hold
    for i in interfaces {
        decls.methods.insert(i.name.key(), i.methods.clone());
        decls.interfaces.insert(i.name.key(), i);
    }
    decls.bases = bases;
    // the type of a chart's steps, which its actions read (`Step.X`, `Step.T`)
    // (and a derived block's body, which reads its bases' charts)
    let runs_chart = |pb: &&PendingBody| {
        (pb.sfc && !pb.actions.is_empty())
            || matches!(pb.oop.as_deref(),
                Some(super::inherit::Oop::Block(b)) if !b.super_charts.is_empty())
    };
    if let Some(pb) = pending.iter().find(runs_chart) {
        let at = Span::new(pb.file, pb.base, pb.base);
        decls.add_type(super::sfc::step_type(at));
    }
    decls.derived = derived;
    // the charts of the bases whose body is SFC, by the base's name: a derived block's
    // `SUPER^()` runs one (`super_chart_call`), and its body reads their steps' flags
    let charts: std::collections::HashMap<String, &PendingBody> = pending
        .iter()
        .filter(|pb| pb.sfc)
        .filter_map(|pb| {
            let p = units
                .iter()
                .flat_map(|u| u.items.iter())
                .find_map(|i| match i {
                    LibraryElement::Pou(p)
                        if p.name.span.file == pb.file
                            && p.name.span.start as usize == pb.name_start =>
                    {
                        Some(p.name.key())
                    }
                    _ => None,
                })?;
            Some((p, pb))
        })
        .collect();
    // (a chart's body is lowered by the caller, its actions and methods here)
    for pb in pending.iter().filter(|pb| {
        !pb.sfc || !pb.actions.is_empty() || !pb.methods.is_empty() || !pb.var_inits.is_empty()
    }) {
        let diags: &mut Diagnostics = if pb.derived() {
            &mut inherited
        } else {
            &mut *diags
        };
        for unit in units.iter_mut() {
            let mut standalone = Vec::new();
            for item in unit.items.iter_mut() {
                let LibraryElement::Pou(p) = item else {
                    continue;
                };
                if p.name.span.file != pb.file || p.name.span.start as usize != pb.name_start {
                    continue;
                }
                // a variable named with a keyword (`IF : BOOL`) cannot be read in ST: sema
                // reports it once at the declaration (E1031), and the body is not parsed into a
                // cascade of syntax errors
                let keyword_var = p.var_blocks.iter().flat_map(|b| b.vars.iter()).any(|v| {
                    crate::sema::reserved_name(&v.name.name) == Some("a keyword")
                        && !keyword_parameters.contains(&(v.name.span.file, v.name.span.start))
                            // (no ST keyword: the body reads them as names; W1418 / W1451 in
                            // TwinCAT)
                            && !["CONFIGURATION", "RESOURCE", "R_EDGE", "F_EDGE"]
                                .iter()
                                .any(|k| v.name.name.eq_ignore_ascii_case(k))
                });
                // (a declaration the parser could not read, `OF : BOOL;`, is already E1031 there)
                let dropped_keyword_var = diags.iter().any(|d| {
                    d.code == code::E1031
                        && d.span.is_some_and(|s| {
                            s.file == p.span.file && s.start >= p.span.start && s.end <= p.span.end
                        })
                });
                if keyword_var || dropped_keyword_var {
                    continue;
                }
                let span = Span::new(pb.file, pb.base, pb.base + pb.text.len());
                if pb.il {
                    // an IL body's actions, each in ST or IL: lowered with the POU and put where
                    // the body calls them
                    let (temps, actions) = il_body_actions(pb, &decls, p, diags);
                    p.var_blocks.extend(temps);
                    standalone.extend(actions);
                    continue;
                }
                // a chart's actions read its steps' flags (`Fill.T`, `S0.x`)
                let mut chart_steps = if pb.sfc && !pb.actions.is_empty() {
                    super::sfc::step_names(pb.file, &pb.text)
                } else {
                    Vec::new()
                };
                // `SUPER^()` of a base whose body is a chart: a call of a hidden action, kept
                // as one `CAL` for the caller to replace by a scan of the chart
                let mut super_charts: Vec<(crate::ast::Ident, Vec<crate::IlStmt>)> = Vec::new();
                if let Some(super::inherit::Oop::Block(b)) = pb.oop.as_deref() {
                    for (hidden, base) in &b.super_charts {
                        let Some(chart) = charts.get(&base.to_ascii_uppercase()) else {
                            continue;
                        };
                        chart_steps.extend(super::sfc::step_names(chart.file, &chart.text));
                        super_charts.push((
                            crate::ast::Ident::new(hidden, p.name.span),
                            vec![super_chart_call(base, p.name.span)],
                        ));
                    }
                }
                let (body, temps, actions) = super::compile_body_with_actions(
                    pb.file,
                    if pb.sfc { "" } else { &pb.text },
                    pb.base,
                    &decls,
                    p,
                    (&pb.actions, &chart_steps),
                    &super_charts,
                    span,
                    diags,
                );
                p.body = body;
                p.var_blocks.extend(temps);
                // interface variables with an initial value, and variables whose initial value
                // calls a function: assigned when the POU first runs
                let own: Vec<&super::interface_vars::Init> = inits
                    .iter()
                    .filter(|i| i.pou == Some(p.name.span))
                    .collect();
                let computed: Vec<super::ast::Stmt> = pb
                    .var_inits
                    .iter()
                    .flat_map(|(file, text, base, prefixed)| {
                        let mut stmts = super::parse_statements_of(*file, text, *base, p, diags);
                        super::init_fields::prefix_fields(&mut stmts, prefixed);
                        stmts
                    })
                    .collect();
                let at_instance_init = !computed.is_empty();
                let init = super::interface_vars::initial_values(&decls, p, &own, computed, diags);
                // ... and when each instance is initialised, before its FB_init, as CODESYS and
                // TwinCAT initialise declarations (`fb_init` calls every `INIT_PREFIX` method)
                // (a PROGRAM's one instance too: before the first cycle, `fb_init`)
                if at_instance_init
                    && matches!(
                        p.kind,
                        crate::ast::PouKind::FunctionBlock | crate::ast::PouKind::Program
                    )
                {
                    let span = p.name.span;
                    standalone.push(crate::ast::Action {
                        pou: p.name.clone(),
                        name: crate::ast::Ident::new(
                            format!("{}_VARS", super::method_inits::INIT_PREFIX),
                            span,
                        ),
                        body: crate::actions::instantiate(&init, "__VINIT_", span),
                        temps: None,
                        method_inputs: Some(Vec::new()),
                        method_outputs: Vec::new(),
                        method_defaults: Vec::new(),
                        diagnostics: Vec::new(),
                        access: None,
                    });
                }
                if !init.is_empty() {
                    let mut body = init.clone();
                    body.append(&mut p.body);
                    p.body = body;
                }
                standalone.extend(actions);
                let mut methods = Vec::new();
                for (k, m) in pb.methods.iter().enumerate() {
                    // VAR_INST initial values computed from the instance: when it is initialised
                    if let Some(a) = lower_instance_init(pb.method_file(k), &decls, p, m) {
                        standalone.push(a);
                    }
                    // (`SUPER^()` in a middle level's body, a hidden method here: its base's
                    // chart; round 32, before: E1019 `__C000` unknown)
                    let file = pb.method_file(k);
                    let lowered = lower_method_as(file, &decls, p, m, (None, &super_charts), diags);
                    if let Some(mut a) = lowered {
                        if !init.is_empty() {
                            let tag = format!("__ITF{k}_");
                            let mut body = crate::actions::instantiate(&init, &tag, a.name.span);
                            body.append(&mut a.body);
                            a.body = body;
                        }
                        methods.push(a);
                    }
                }
                inline_own_method_calls(p, &mut methods, diags);
                standalone.extend(methods);
            }
            unit.items
                .extend(standalone.into_iter().map(LibraryElement::Action));
        }
    }
    // FB_init: each instance's, before the first cycle, with its declaration's arguments
    // (and the global lists' interface variables their instances, before it)
    let global_itf = super::interface_vars::global_initial_values(&inits, diags);
    super::fb_init::add_init_calls(
        units,
        pending,
        (&declares_fb_init, global_itf),
        &mut decls,
        diags,
    );
    // VAR_STAT: one copy for every instance and call, now that the bodies are lowered
    super::var_stat::hoist(units);
    let seen: std::collections::HashSet<_> = diags
        .iter()
        .map(|d| (d.code, d.message.clone(), d.span.map(|s| (s.start, s.end))))
        .collect();
    let mut once = std::collections::HashSet::new();
    for d in inherited {
        let key = (d.code, d.message.clone(), d.span.map(|s| (s.start, s.end)));
        if !seen.contains(&key) && once.insert(key) {
            diags.push(d);
        }
    }
}

/// Declares the hidden variables of a function block's methods: `__M_<METHOD>_<name>` for each
/// VAR_INPUT (an input of the block), VAR_OUTPUT (an output), VAR and VAR_TEMP (a temporary: a
/// method's variables do not keep their values from call to call), VAR_INST (a local of the block:
/// kept, initialised once with the instance), and the result `__M_<METHOD>` (an output). A
/// VAR_IN_OUT of a method is a VAR_IN_OUT of the block: a call from outside (`inst.M(x := v)`) binds
/// it as a call of the instance binds the block's own; a call inside the block reads and writes the
/// argument itself (see `st::lower::method_in_out`).
pub fn add_method_vars(
    p: &mut crate::ast::Pou,
    methods: &[PendingMethod],
    diags: &mut Diagnostics,
) {
    use crate::actions::{method_result, method_var};
    use crate::ast::{VarBlock, VarKind};
    let mut inputs = Vec::new();
    let mut outputs = Vec::new();
    let mut temps = Vec::new();
    let mut in_outs = Vec::new();
    let mut defaults = Vec::new();
    let mut own_defaults = Vec::new();
    let mut kept = Vec::new();
    let mut stat = Vec::new();
    let mut externals: Vec<VarBlock> = Vec::new();
    member_name_clashes(p, methods.iter().map(method_member), diags);
    for m in methods {
        let names = m.blocks.iter().flat_map(|b| b.vars.iter());
        crate::actions::remember_spellings(&m.name.name, names.map(|v| v.name.name.as_str()));
        if let Some(r) = &m.ret {
            let mut v = r.clone();
            v.name.name = method_result(&m.name.name);
            v.init = None;
            outputs.push(v.clone());
            // never written: the default value the result starts each call with
            v.name.name = method_default(&m.name.name);
            defaults.push(v);
        }
        for b in &m.blocks {
            let list = match b.kind {
                VarKind::Input => &mut inputs,
                VarKind::Output => &mut outputs,
                VarKind::Local | VarKind::Temp => &mut temps,
                VarKind::InOut => &mut in_outs,
                VarKind::External => {
                    // VAR_EXTERNAL (edition 3's grammar lets a method declare `external_var_decls`
                    // as a function does): the global itself, declared on the block once
                    for v in &b.vars {
                        let key = v.name.key();
                        let clash = p.var_blocks.iter().chain(externals.iter()).any(|o| {
                            o.vars.iter().any(|w| w.name.key() == key)
                                && !matches!(o.kind, VarKind::External)
                        });
                        if clash {
                            diags.push(
                                Diagnostic::error(
                                    code::E0303,
                                    format!(
                                        "method `{}`: VAR_EXTERNAL `{}` has the name of a variable of the block",
                                        m.name.name, v.name.name
                                    ),
                                )
                                .at(v.name.span)
                                .with_primary_label("the block declares this name already")
                                .with_hint("rename the block's variable: inside the method the name would mean both"),
                            );
                            continue;
                        }
                        let known = p
                            .var_blocks
                            .iter()
                            .chain(externals.iter())
                            .any(|o| o.vars.iter().any(|w| w.name.key() == key));
                        if !known {
                            externals.push(VarBlock {
                                access: None,
                                name: None,
                                kind: VarKind::External,
                                constant: b.constant,
                                retain: false,
                                vars: vec![v.clone()],
                                span: b.span,
                            });
                        }
                    }
                    continue;
                }
                _ => {
                    diags.push(
                        Diagnostic::error(
                            code::E0303,
                            format!(
                                "method `{}`: this variable block is not supported in a method",
                                m.name.name
                            ),
                        )
                        .at(b.span)
                        .with_primary_label("not supported in a method")
                        .with_hint("methods take VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR, VAR_TEMP and VAR_EXTERNAL; pass what the method changes through the block's own variables"),
                    );
                    continue;
                }
            };
            let is_stat = b
                .name
                .as_ref()
                .is_some_and(|n| n.name == super::var_stat::MARK);
            for v in &b.vars {
                let mut v = v.clone();
                let inst = m.inst.contains(&v.name.key());
                let per_call = match b.kind {
                    VarKind::Input => true,
                    VarKind::Local | VarKind::Temp => !inst && !is_stat,
                    _ => false,
                };
                // a local of the block's own type (an instance of its own class, IEC 61131-3
                // ed. 3 6.6.5) is no variable of the instance (a C local of the call): its copy
                // of the initial value is one too (the instance cannot hold one inside itself)
                let own = !matches!(b.kind, VarKind::Input) && holds_pou(&v.ty, &p.name);
                if per_call && !matches!(v.ty, crate::ast::TypeRef::Ref { .. }) {
                    // never written: the value a call that leaves the input out passes, and the
                    // value a local starts each call with (`Declarations::local_resets_per_call`)
                    let mut d = v.clone();
                    d.name.name = crate::actions::method_input_default(&m.name.name, &v.name.name);
                    if own {
                        own_defaults.push(d);
                    } else {
                        defaults.push(d);
                    }
                }
                v.name.name = method_var(&m.name.name, &v.name.name);
                if is_stat {
                    // VAR_STAT: one copy per method, shared by every instance (`var_stat::hoist`)
                    stat.push(v);
                } else if inst {
                    // VAR_INST: a variable of the instance, initialised once with it
                    kept.push(v);
                } else {
                    list.push(v);
                }
            }
        }
    }
    p.var_blocks.extend(externals);
    let span = p.span;
    for (kind, vars, name) in [
        (VarKind::Input, inputs, None),
        (VarKind::Output, outputs, None),
        (VarKind::InOut, in_outs, None),
        (VarKind::Temp, temps, None),
        (VarKind::Temp, own_defaults, None),
        (VarKind::Local, defaults, None),
        (VarKind::Local, kept, None),
        (
            VarKind::Local,
            stat,
            Some(crate::ast::Ident::new(super::var_stat::MARK, span)),
        ),
    ] {
        if !vars.is_empty() {
            p.var_blocks.push(VarBlock {
                access: None,
                name,
                kind,
                constant: false,
                retain: false,
                vars,
                span,
            });
        }
    }
}

/// E1002 for each METHOD, PROPERTY or ACTION (`members`, as their hidden names: a property's
/// accessors `__GET_P` / `__SET_P`) of block `p` named like one of its variables, apart from case
/// or not (IEC 61131-3 names are case-insensitive, and a block's variables, methods, properties
/// and actions share its namespace: before round 27 the program compiled, and `Z` inside the
/// block meant the variable or the method's result depending on where it was read). Located at
/// the later of the two declarations; reported once per member (a derived block that inherits
/// both reaches them again).
pub fn member_name_clashes(
    p: &crate::ast::Pou,
    members: impl Iterator<Item = (&'static str, String, Span)>,
    diags: &mut Diagnostics,
) {
    let mut done = std::collections::HashSet::new();
    for (what, name, span) in members {
        let key = name.to_ascii_uppercase();
        if !done.insert(key.clone()) {
            continue; // a property's second accessor
        }
        let var = p
            .var_blocks
            .iter()
            .filter(|b| !matches!(b.kind, crate::ast::VarKind::External))
            .flat_map(|b| b.vars.iter())
            .find(|v| v.name.key() == key);
        let Some(v) = var else { continue };
        let (at, first, first_what, second_what) =
            if v.name.span.file == span.file && v.name.span.start > span.start {
                (v.name.span, span, what, "a variable")
            } else {
                (span, v.name.span, "a variable", what)
            };
        let already = diags
            .iter()
            .any(|d| d.code == code::E1002 && d.span == Some(at));
        if already {
            continue;
        }
        diags.push(
            Diagnostic::error(
                code::E1002,
                format!(
                    "`{}` of `{}` is declared twice: as {first_what} and as {second_what}",
                    name, p.name.name
                ),
            )
            .at(at)
            .with_primary_label("declared again here")
            .with_label(first, "first declared here")
            .with_hint("a block's variables, methods, properties and actions share one namespace, and names are case-insensitive: rename one of them"),
        );
    }
}

/// A method as [`member_name_clashes`] sees it: "method" or "property", its name as written (a
/// property's, not its accessor's hidden `__GET_P`), where.
fn method_member(m: &PendingMethod) -> (&'static str, String, Span) {
    if !super::property::is_accessor(&m.name.name) {
        return ("a method", m.name.name.clone(), m.name.span);
    }
    // the Get accessor's result and the Set accessor's input are named as the property
    let written = m
        .ret
        .iter()
        .chain(m.blocks.iter().flat_map(|b| b.vars.iter()))
        .find(|v| v.name.span == m.name.span)
        .map(|v| v.name.name.clone())
        .unwrap_or_else(|| m.name.name[super::property::GET_PREFIX.len()..].to_string());
    ("a property", written, m.name.span)
}

/// The pending bodies with the FB_init arguments of each METHOD's own VAR / VAR_TEMP instance
/// (struckig's `p : Randomizer(_positionDist);`) moved from the file's list to the method's
/// [`PendingMethod::local_inits`], when the instance's block declares an FB_init (`declares`,
/// upper-case) and one list is given for it (not an array's); `None` when there is none.
fn methods_take_local_args(
    pending: &[PendingBody],
    declares: &std::collections::HashSet<String>,
) -> Option<Vec<PendingBody>> {
    use crate::ast::{TypeRef, VarKind};
    let local_of = |m: &PendingMethod, a: &super::fb_init_args::DeclArgs| {
        a.elements.is_empty()
            && declares.contains(&a.ty_name.to_ascii_uppercase())
            && m.blocks
                .iter()
                .filter(|b| matches!(b.kind, VarKind::Local | VarKind::Temp))
                .flat_map(|b| b.vars.iter())
                .any(|v| {
                    !m.inst.contains(&v.name.key())
                        && matches!(&v.ty, TypeRef::Named(n) if n.span == a.ty)
                })
    };
    let any = pending.iter().any(|pb| {
        pb.fb_init_args.iter().any(|a| {
            pending
                .iter()
                .flat_map(|q| &q.methods)
                .any(|m| local_of(m, a))
        })
    });
    if !any {
        return None;
    }
    let mut out = pending.to_vec();
    let mut taken = Vec::new();
    for pb in out.iter_mut() {
        pb.fb_init_args.retain(|a| {
            let local = pending
                .iter()
                .flat_map(|q| &q.methods)
                .any(|m| local_of(m, a));
            if local {
                taken.push(a.clone());
            }
            !local
        });
    }
    for pb in out.iter_mut() {
        for m in pb.methods.iter_mut() {
            for a in &taken {
                if local_of(m, a) {
                    m.local_inits.push(a.clone());
                }
            }
        }
    }
    Some(out)
}

/// `p.FB_init(TRUE, FALSE, args)` for each of `m`'s own instances declared with FB_init
/// arguments ([`PendingMethod::local_inits`]), placed before the first statement written after
/// the declaration (after the initial values computed before it): the instance is created again
/// at each call, as CODESYS does, a fresh one (`bInitRetains := TRUE, bInCopyCode := FALSE`, as
/// at a download).
fn add_local_fb_inits(m: &PendingMethod, stmts: &mut Vec<super::ast::Stmt>) {
    use super::ast::{Accessor, Arg, ArgDir, Expr, Place, PlaceBase, Stmt, StmtKind};
    use crate::ast::{LiteralKind, TypeRef};
    for a in m.local_inits.iter().rev() {
        let Some(v) = m
            .blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .find(|v| matches!(&v.ty, TypeRef::Named(n) if n.span == a.ty))
        else {
            continue;
        };
        let formal = a.args.iter().any(|x| x.name.is_some());
        let system = |name: &str, value: bool| Arg {
            name: formal.then(|| crate::ast::Ident::new(name, a.span)),
            dir: ArgDir::Input,
            value: Expr::literal(LiteralKind::Bool(value), a.span),
            span: a.span,
        };
        let mut args = vec![system("bInitRetains", true), system("bInCopyCode", false)];
        args.extend(a.args.iter().cloned());
        let call = Stmt {
            kind: StmtKind::Call {
                callee: Place {
                    base: PlaceBase::Name(v.name.clone()),
                    accessors: vec![Accessor::Field(crate::ast::Ident::new("FB_init", a.span))],
                    span: a.span,
                },
                args,
            },
            span: a.span,
        };
        let at = stmts
            .iter()
            .position(|s| s.span.start >= a.span.end)
            .unwrap_or(stmts.len());
        stmts.insert(at, call);
    }
}

/// The hidden, never written variable holding the default value of method `m`'s result: the
/// result is set to it when the method starts (a method's result, like a function's, does not keep
/// the value of the previous call: IEC 61131-3 ed. 3, 6.6.1.2; CODESYS "Method").
fn method_default(m: &str) -> String {
    format!("__MZ_{}", m.to_ascii_uppercase())
}

/// The actions of `p`, a POU whose body is instruction list (`pb.il`): each action's text in IL
/// or ST (as [`body_lang`] tells), the ST ones lowered in `p`'s scope (they may call the others);
/// a copy of each is put where `p`'s IL body calls it (`CAL Act`, `CALC Act`, `CAL Prog.Act`,
/// [`crate::actions::inline_calls`]). Returns the temporaries of the lowering and the actions
/// on their own, for calls through an instance ([`crate::actions::link`]).
fn il_body_actions(
    pb: &PendingBody,
    decls: &super::Declarations,
    p: &mut crate::ast::Pou,
    diags: &mut Diagnostics,
) -> (Vec<crate::ast::VarBlock>, Vec<crate::ast::Action>) {
    let mut st_actions = Vec::new();
    let mut il_actions = Vec::new();
    for (name, text, base) in &pb.actions {
        if body_lang(text, &lex(text).0) == Lang::St {
            st_actions.push((name.clone(), text.clone(), *base));
        } else {
            let declared: Vec<&str> = p
                .var_blocks
                .iter()
                .flat_map(|b| b.vars.iter())
                .map(|v| v.name.name.as_str())
                .collect();
            let body = crate::parse_body_declared(name.span.file, text, *base, diags, &declared);
            il_actions.push((name.clone(), body));
        }
    }
    let span = Span::new(pb.file, pb.base, pb.base);
    let (_, temps, mut actions) = super::compile_body_with_actions(
        pb.file,
        "",
        pb.base,
        decls,
        p,
        (&st_actions, &[]),
        &il_actions,
        span,
        diags,
    );
    for (name, body) in &il_actions {
        actions.push(crate::ast::Action {
            pou: p.name.clone(),
            name: name.clone(),
            body: body.clone(),
            temps: None,
            method_inputs: None,
            method_outputs: Vec::new(),
            method_defaults: Vec::new(),
            access: None,
            diagnostics: Vec::new(),
        });
    }
    let map: std::collections::HashMap<String, Vec<crate::ast::IlStmt>> = actions
        .iter()
        .map(|a| (a.name.key(), a.body.clone()))
        .collect();
    let is_var = crate::actions::declares(p);
    let mut body = std::mem::take(&mut p.body);
    crate::actions::drop_own_name(&mut body, p, &map, &is_var);
    let mut next = 0;
    let mut local = Diagnostics::new();
    p.body = crate::actions::inline_calls(body, &map, &is_var, "__A", &mut next, &mut local);
    // an IL action's own calls of the others, for its runs through an instance
    for a in actions
        .iter_mut()
        .filter(|a| il_actions.iter().any(|(n, _)| n.key() == a.name.key()))
    {
        let mut own = std::mem::take(&mut a.body);
        crate::actions::drop_own_name(&mut own, p, &map, &is_var);
        a.body = crate::actions::inline_calls(own, &map, &is_var, "__A", &mut next, &mut local);
    }
    // a recursion is found from every place that enters it: reported once per call
    let mut seen = std::collections::HashSet::new();
    for d in local {
        if seen.insert((d.code, d.span.map(|s| (s.start, s.end)), d.message.clone())) {
            diags.push(d);
        }
    }
    // the ST actions' own diagnostics, as where an ST body calls them
    for a in &mut actions {
        for d in std::mem::take(&mut a.diagnostics) {
            diags.push(d);
        }
    }
    (temps, actions)
}

/// Puts a copy of a method's statements where the block's body, or one of its methods, calls it
/// (`M(...)` inside the block, lowered to `CAL M` by [`super::PouLowering`]); a method that calls
/// itself, directly or through another, is E0106 at the call.
pub fn inline_own_method_calls(
    p: &mut crate::ast::Pou,
    methods: &mut [crate::ast::Action],
    diags: &mut Diagnostics,
) {
    if methods.is_empty() {
        return;
    }
    let map: std::collections::HashMap<String, Vec<crate::ast::IlStmt>> = methods
        .iter()
        .map(|a| (a.name.key(), a.body.clone()))
        .collect();
    let is_var = crate::actions::declares(p);
    let mut next = 0;
    let mut local = Diagnostics::new();
    p.body = crate::actions::inline_calls(
        std::mem::take(&mut p.body),
        &map,
        &is_var,
        crate::actions::METHOD_CALL_PREFIX,
        &mut next,
        &mut local,
    );
    for a in methods.iter_mut() {
        a.body = crate::actions::inline_calls(
            std::mem::take(&mut a.body),
            &map,
            &is_var,
            crate::actions::METHOD_CALL_PREFIX,
            &mut next,
            &mut local,
        );
    }
    // a recursion is found from every place that enters it: reported once per call
    let mut seen = std::collections::HashSet::new();
    for d in local {
        if seen.insert((d.code, d.span.map(|s| (s.start, s.end)), d.message.clone())) {
            diags.push(d);
        }
    }
}

/// Lowers a method of the function block `p` (its hidden variables already declared) into an
/// [`Action`](crate::ast::Action) for [`crate::actions::link`]: its statements are lowered where the
/// method's own names are its variables (they shadow the block's), then those names become the
/// hidden ones, its labels get a prefix of their own and `RETURN` leaves the method.
pub fn lower_method(
    file: FileId,
    decls: &super::Declarations,
    p: &mut crate::ast::Pou,
    m: &PendingMethod,
    diags: &mut Diagnostics,
) -> Option<crate::ast::Action> {
    lower_method_as(file, decls, p, m, (None, &[]), diags)
}

/// The hidden method that computes the VAR_INST initial values of method `m` (its
/// [`PendingMethod::once`] assignments, guarded by their flag) when an instance is initialised,
/// before its FB_init ([`super::fb_init`]), named `method_inits::INIT_PREFIX` + the
/// method's name. `None` when `m` has none.
pub fn lower_instance_init(
    file: FileId,
    decls: &super::Declarations,
    p: &mut crate::ast::Pou,
    m: &PendingMethod,
) -> Option<crate::ast::Action> {
    if m.once.is_empty() {
        return None;
    }
    let mut only = m.clone();
    // the assignments alone, where they are written (their diagnostics come with the method's)
    only.text = super::method_inits::blank(&m.text);
    for r in &m.once {
        let (Some(a), Some(b)) = (r.start.checked_sub(m.base), r.end.checked_sub(m.base)) else {
            continue;
        };
        if let Some(t) = m.text.get(a..b) {
            only.text.replace_range(a..b, t);
        }
    }
    let name = crate::ast::Ident::new(
        format!(
            "{}{}",
            super::method_inits::INIT_PREFIX,
            m.name.name.to_ascii_uppercase()
        ),
        m.name.span,
    );
    let mut quiet = Diagnostics::new();
    let a = lower_method_as(file, decls, p, &only, (Some(&name), &[]), &mut quiet);
    if quiet.has_errors() {
        return None;
    }
    a
}

/// [`lower_method`], the action named `action` (default: the method's name; the method's variables
/// keep the method's hidden names either way); `il_actions`: the block's actions already IL that
/// the method may call (the hidden actions `SUPER^()` of a chart base calls, `super_chart_call`:
/// the body of a middle level of a chain, a hidden method, runs its base's chart).
fn lower_method_as(
    file: FileId,
    decls: &super::Declarations,
    p: &mut crate::ast::Pou,
    m: &PendingMethod,
    (action, il_actions): (
        Option<&crate::ast::Ident>,
        &[(crate::ast::Ident, Vec<crate::IlStmt>)],
    ),
    diags: &mut Diagnostics,
) -> Option<crate::ast::Action> {
    use crate::actions::{instantiate, method_result, method_var};
    use crate::ast::{VarBlock, VarKind};
    // (its VAR_EXTERNAL are the block's: `add_method_vars`)
    let mut own: Vec<VarBlock> = m
        .blocks
        .iter()
        .filter(|b| !matches!(b.kind, VarKind::External))
        .cloned()
        .collect();
    if let Some(r) = &m.ret {
        own.push(VarBlock::locals(vec![r.clone()], r.span));
    }
    let mut rename: std::collections::HashMap<String, String> = Default::default();
    let mut rename_back: Vec<(String, String)> = Vec::new();
    for v in own.iter().flat_map(|b| b.vars.iter()) {
        let new = if m.ret.as_ref().is_some_and(|r| r.name.key() == v.name.key()) {
            method_result(&m.name.name)
        } else {
            method_var(&m.name.name, &v.name.name)
        };
        rename.insert(v.name.key(), new);
    }
    // the block as the method sees it: its own variables (not the methods' hidden ones, and not
    // those the method's names shadow), then the method's
    let mut view = p.clone();
    view.body = Vec::new();
    for b in &mut view.var_blocks {
        // (the hidden variables of the block's methods stay: a call of another method stores
        // into them)
        b.vars.retain(|v| !rename.contains_key(&v.name.key()));
    }
    view.var_blocks.extend(own);
    // `THIS^.x` where the method declares its own `x` (`THIS^.nId := nId;` in an FB_init): the
    // block's variable, read in the text as a hidden name of the same length that the view declares
    // and the renaming below turns back into `x`
    let text = this_shadowed(&m.text, p, &rename, &mut view, &mut rename_back);
    let mut stmts = super::parse_statements_of(file, &text, m.base, p, diags);
    super::method_inits::run_once(&mut stmts, &m.once, m.name.span);
    if action.is_none() {
        add_local_fb_inits(m, &mut stmts);
    }
    let mut low = super::PouLowering::new(decls, &view);
    if !il_actions.is_empty() {
        low.set_il_actions(il_actions.to_vec());
    }
    // its REFERENCE TO variables that start again at each call (not VAR_INST, not VAR_STAT)
    low.per_call_refs = m
        .blocks
        .iter()
        .filter(|b| matches!(b.kind, VarKind::Local | VarKind::Temp) && b.name.is_none())
        .flat_map(|b| b.vars.iter())
        .filter(|v| !m.inst.contains(&v.name.key()))
        .filter(|v| {
            matches!(
                v.ty,
                crate::ast::TypeRef::Ref {
                    kind: crate::ast::RefKind::Reference,
                    ..
                }
            )
        })
        .map(|v| v.name.key())
        .collect();
    let mut body = low.statements(&stmts, diags);
    // `ADR('text')`: the literal's hidden copy, one global (`var_stat::hoist`) per place
    if let Some(c) = low.take_literal_copies(m.name.span) {
        p.var_blocks.push(c);
    }
    if let Some(t) = low.finish(m.name.span) {
        let mut t: VarBlock = t;
        for v in &mut t.vars {
            let new = format!(
                "{}_{}",
                method_result(&m.name.name),
                v.name.name.trim_start_matches('_')
            );
            rename.insert(v.name.key(), new.clone());
            v.name.name = new;
        }
        t.kind = VarKind::Temp;
        p.var_blocks.push(t);
    }
    rename.extend(rename_back);
    // `THIS^.Hash(k)` where the method declares `Hash : DWORD`: the call stays the block's method
    let methods = decls.methods.get(&p.name.key());
    // (and `THIS^.GetExpression(...)` inside `METHOD GetExpression : IExpression`: the method
    // itself, not its result, so a recursive call is the E0106 that says so; round 32, before:
    // E1018 "`GetExpression` is IExpression, not an FB instance")
    let calls_kept = m
        .blocks
        .iter()
        .flat_map(|b| b.vars.iter())
        .filter(|v| methods.is_some_and(|ms| ms.iter().any(|s| v.name.is(&s.name))))
        .filter(|v| !matches!(&v.ty, crate::ast::TypeRef::Named(t) if decls.pou(&t.name).is_some()))
        .map(|v| v.name.key())
        .chain(
            m.ret
                .as_ref()
                .filter(|r| !matches!(&r.ty, crate::ast::TypeRef::Named(t) if decls.pou(&t.name).is_some()))
                .map(|_| m.name.key()),
        )
        .collect();
    crate::rename::Renames {
        bases: rename,
        calls_kept,
        ..Default::default()
    }
    .apply(&mut body);
    // `LD from` `ST to` of hidden variables, at the start of the method's statements
    let copy = |from: String, to: String| {
        let var = |name: String| {
            crate::ast::Operand::Var(crate::ast::VarRef {
                base: crate::ast::Ident::new(name, m.name.span),
                accessors: Default::default(),
                span: m.name.span,
            })
        };
        [(crate::ast::Op::Ld, from), (crate::ast::Op::St, to)].map(|(op, name)| {
            crate::ast::IlStmt::Instr(crate::ast::Instruction {
                kind: crate::ast::InstrKind::Simple {
                    op,
                    negate: false,
                    operand: Some(var(name)),
                },
                span: m.name.span,
            })
        })
    };
    if m.ret.is_some() {
        // the result starts at its default value each call
        body.splice(
            0..0,
            copy(method_default(&m.name.name), method_result(&m.name.name)),
        );
    }
    if action.is_none() {
        // its VAR and VAR_TEMP start at their initial values at each call, also at the second of
        // two calls in one scan (the block's temporaries start so once per scan)
        let resets: Vec<crate::ast::IlStmt> = m
            .blocks
            .iter()
            .filter(|b| matches!(b.kind, VarKind::Local | VarKind::Temp))
            .filter(|b| {
                b.name
                    .as_ref()
                    .is_none_or(|n| n.name != super::var_stat::MARK)
            })
            .flat_map(|b| b.vars.iter())
            .filter(|v| !m.inst.contains(&v.name.key()) && decls.local_resets_per_call(&v.ty))
            .flat_map(|v| {
                copy(
                    crate::actions::method_input_default(&m.name.name, &v.name.name),
                    method_var(&m.name.name, &v.name.name),
                )
            })
            .collect();
        body.splice(0..0, resets);
    }
    let body = instantiate(
        &body,
        &format!("{}_L", method_result(&action.unwrap_or(&m.name).name)),
        m.name.span,
    );
    // (a non-formal call binds the inputs and in-outs in declaration order, CODESYS)
    let inputs = m
        .blocks
        .iter()
        .filter(|b| matches!(b.kind, VarKind::Input | VarKind::InOut))
        .flat_map(|b| b.vars.iter().map(|v| v.name.clone()))
        .collect();
    // (the positional arguments after them bind the outputs, IEC 61131-3 ed. 3, 6.6.1.4.2)
    let outputs = m
        .blocks
        .iter()
        .filter(|b| matches!(b.kind, VarKind::Output))
        .flat_map(|b| b.vars.iter().map(|v| v.name.clone()))
        .collect();
    Some(crate::ast::Action {
        pou: p.name.clone(),
        name: action.unwrap_or(&m.name).clone(),
        body,
        temps: None,
        method_inputs: Some(if action.is_some() { Vec::new() } else { inputs }),
        method_outputs: if action.is_some() {
            Vec::new()
        } else {
            outputs
        },
        method_defaults: if action.is_some() || super::fb_init::is_special_method(&m.name.name) {
            Vec::new()
        } else {
            m.blocks
                .iter()
                .filter(|b| b.kind == VarKind::Input)
                .flat_map(|b| b.vars.iter())
                .filter_map(|v| {
                    let reference = matches!(v.ty, crate::ast::TypeRef::Ref { .. });
                    (reference || decls.resets_per_call(&v.ty)).then(|| (v.name.clone(), reference))
                })
                .collect()
        },
        diagnostics: Vec::new(),
        access: if action.is_some() {
            None
        } else {
            m.access.clone()
        },
    })
}

/// The prefix of the hidden name that reads `THIS^.x` in a method that declares its own `x`: as
/// long as `THIS^.`, so that positions do not move.
const THIS_PREFIX: &str = "__THS_";

/// `text` (a method's statements) with each `THIS^.x`, where `x` is a variable of the block `p`
/// that the method's own `x` shadows (`rename` holds the method's names), written `__THS_x`; `view`
/// declares `__THS_x` as the block's `x`, and `back` maps it to `x` for the renaming after the
/// lowering.
fn this_shadowed(
    text: &str,
    p: &crate::ast::Pou,
    rename: &std::collections::HashMap<String, String>,
    view: &mut crate::ast::Pou,
    back: &mut Vec<(String, String)>,
) -> String {
    if !text.contains('^') {
        return text.to_string();
    }
    let (toks, _) = lex(text);
    let mut out = text.to_string();
    for w in toks.windows(4) {
        if !(is_word(text, &w[0], "THIS")
            && w[1].tok == Tok::Caret
            && w[2].tok == Tok::Dot
            && w[3].tok == Tok::Ident)
        {
            continue;
        }
        let x = word(text, &w[3]);
        let key = x.to_ascii_uppercase();
        if !rename.contains_key(&key) {
            continue;
        }
        let Some(v) = p
            .var_blocks
            .iter()
            .flat_map(|b| b.vars.iter())
            .find(|v| v.name.key() == key)
        else {
            continue;
        };
        let hidden = format!("{THIS_PREFIX}{x}");
        if w[3].range.end - w[0].range.start != hidden.len() {
            continue;
        }
        out.replace_range(w[0].range.start..w[3].range.end, &hidden);
        if !back.iter().any(|(k, _)| *k == hidden.to_ascii_uppercase()) {
            back.push((hidden.to_ascii_uppercase(), v.name.name.clone()));
            let mut decl = v.clone();
            decl.name.name = hidden;
            view.var_blocks
                .push(crate::ast::VarBlock::locals(vec![decl], v.span));
        }
    }
    out
}

/// Where a `BEGIN_IL` line (the IL section of Straton-style workbenches) starts in `body`, if one
/// does: the word alone on its line (a comment may follow; `begin_il := x;` is a statement).
fn begin_il_section(src: &str, body: std::ops::Range<usize>) -> Option<usize> {
    let text = src.get(body.clone())?;
    let mut at = 0;
    for line in text.split_inclusive('\n') {
        let t = line.trim_start();
        let head = t.get(.."BEGIN_IL".len());
        let rest = t.get("BEGIN_IL".len()..).map(str::trim);
        let alone =
            rest.is_some_and(|r| r.is_empty() || r.starts_with("(*") || r.starts_with("//"));
        if alone && head.is_some_and(|h| h.eq_ignore_ascii_case("BEGIN_IL")) {
            return Some(body.start + at + (line.len() - t.len()));
        }
        at += line.len();
    }
    None
}

/// Whether a pragma is `{attribute 'name'}` (`name` in lower case): `'to_string'` (CODESYS, TwinCAT:
/// `TO_STRING` of the enumeration declared below it gives the value's name), `'strict'` (its
/// values are no integers).
fn is_attribute(pragma: &str, name: &str) -> bool {
    let p = pragma.to_ascii_lowercase();
    let p = p.trim_start_matches('{').trim_end_matches('}').trim();
    p.strip_prefix("attribute").is_some_and(|rest| {
        rest.trim()
            .strip_prefix('\'')
            .and_then(|r| r.strip_suffix('\''))
            == Some(name)
    })
}

/// The first type declared after each attribute ending at an offset of `ends` in `unit` (an
/// attribute is written on the line above its TYPE).
fn types_after(unit: &CompilationUnit, ends: &[usize]) -> Vec<crate::ast::Ident> {
    if ends.is_empty() {
        return Vec::new();
    }
    let types: Vec<&crate::ast::TypeDecl> = unit.type_decls().collect();
    ends.iter()
        .filter_map(|&end| {
            types
                .iter()
                .filter(|t| t.name.span.start as usize >= end)
                .min_by_key(|t| t.name.span.start)
                .map(|t| t.name.clone())
        })
        .collect()
}

/// Whether a variable of type `ty` holds an instance of the POU `pou` by value (through arrays).
fn holds_pou(ty: &crate::ast::TypeRef, pou: &crate::ast::Ident) -> bool {
    match ty {
        crate::ast::TypeRef::Named(n) => n.is(&pou.name),
        crate::ast::TypeRef::Array { element, .. } => holds_pou(element, pou),
        _ => false,
    }
}

/// The prefix of the instance a `CAL` names where a derived block's `SUPER^()` runs the chart of
/// its base (`__SUPER_SFC_<base>`): replaced by a scan of that chart when charts are lowered
/// (ladderc's `lower_textual_sfc`); never a name of the program (two underscores in a row).
pub const SUPER_CHART_CALL: &str = "__SUPER_SFC_";

/// `CAL __SUPER_SFC_<base>` at `span`.
fn super_chart_call(base: &str, span: Span) -> crate::IlStmt {
    use crate::ast::{CallArgs, Condition, InstrKind, Instruction, VarRef};
    crate::IlStmt::Instr(Instruction {
        kind: InstrKind::Call {
            cond: Condition::Always,
            instance: Box::new(VarRef {
                base: crate::ast::Ident::new(format!("{SUPER_CHART_CALL}{base}"), span),
                accessors: Default::default(),
                span,
            }),
            args: CallArgs::None,
        },
        span,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bodies_are_found_and_classified() {
        let src = "TYPE t : INT; END_TYPE\nFUNCTION f : INT\nVAR_INPUT a : INT; END_VAR\n  f := a + 1;\nEND_FUNCTION\n\
                   FUNCTION_BLOCK fb\nVAR_INPUT s : BOOL; END_VAR VAR_OUTPUT q : BOOL; END_VAR\n  LD s\n  ST q\nEND_FUNCTION_BLOCK\n\
                   PROGRAM main\nVAR x : fb; END_VAR\n  x(s := TRUE);\nEND_PROGRAM\n\
                   CONFIGURATION c RESOURCE r ON PLC PROGRAM i WITH t : main; END_RESOURCE END_CONFIGURATION\n";
        let p = scan(src);
        let got: Vec<(&str, Lang)> = p.iter().map(|p| (p.name.as_str(), p.lang)).collect();
        assert_eq!(
            got,
            vec![("f", Lang::St), ("fb", Lang::Il), ("main", Lang::St)]
        );
        assert_eq!(src[p[0].body.clone()].trim(), "f := a + 1;");
        assert_eq!(detect(src), Lang::St);
        assert_eq!(detect("  <?xml version='1.0'?>"), Lang::Xml);
        assert_eq!(
            detect("FUNCTION F : REAL VAR_INPUT IN : BYTE; END_VAR RETURN; END_FUNCTION"),
            Lang::St
        );
        assert_eq!(
            detect("PROGRAM p\nVAR x : INT; END_VAR\nLD 1\nST x ; store\nEND_PROGRAM"),
            Lang::Il
        );
    }

    #[test]
    fn il_with_formal_calls_and_labels_is_il() {
        let src = "PROGRAM p\nVAR t : TON; x : BOOL; END_VAR\nCAL t(IN := x, PT := T#1s)\nL1: LD t.Q\nJMPC L1\nEND_PROGRAM";
        assert_eq!(scan(src)[0].lang, Lang::Il);
        let st = "PROGRAM p\nVAR t : TON; x : BOOL; END_VAR\nt(IN := x,\n  PT := T#1s);\nx := t.Q\n  AND x;\nEND_PROGRAM";
        assert_eq!(scan(st)[0].lang, Lang::St);
    }
}
