//! ST call statements of a FUNCTION whose result is dropped (`Simulatie_invoer();`,
//! `Step(c);`): normal ST in CODESYS and TwinCAT, which run the function for its side effects and
//! drop its result.
//!
//! The ST lowering turns such a statement into IL that computes the function's value and leaves it
//! as the current result, unused; sema's IL check of unused results (W1001, "store it (ST x)")
//! would report it at the next statement's first load. Before round 34 it did: an IL hint in an
//! ST file, and a "replaced here" label on a literal of the next statement.
//!
//! Input: the spans of those call statements, recorded by the lowering (`record`) as it lowers
//! them. Output: `is_dropped`, which sema asks before it reports an unused result. Invariants:
//! the table is per thread and per compilation ([`forget`] empties it as a compilation starts
//! reading its inputs, as `crate::actions::forget_spellings` does for its table); an IL file's
//! instructions are never recorded, so an IL result left unused keeps its W1001.

use diagnostics::Span;
use std::cell::RefCell;
use std::collections::HashSet;

thread_local! {
    /// The recorded call statements.
    static DROPPED: RefCell<HashSet<Span>> = RefCell::new(HashSet::new());
}

/// Records `span`, an ST call statement of a function whose result the statement drops.
pub(crate) fn record(span: Span) {
    DROPPED.with(|d| d.borrow_mut().insert(span));
}

/// Whether the instruction at `span` computes the result of an ST call statement that drops it.
pub(crate) fn is_dropped(span: Span) -> bool {
    DROPPED.with(|d| d.borrow().contains(&span))
}

/// Forgets every recorded statement (called as a compilation starts reading its inputs).
pub fn forget() {
    DROPPED.with(|d| d.borrow_mut().clear());
}
