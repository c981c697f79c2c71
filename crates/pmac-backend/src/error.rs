//! Errors of the PMAC backend.
//!
//! Input: what went wrong in a stage (validation, streaming, I/O).
//! Output: a [`PmacError`] that carries a ready [`Diagnostic`] with a stable `E7xxx` code.
//! Invariant: every error converts into exactly one diagnostic; the message is one line without a period.

use diagnostics::{code, Diagnostic};

/// One backend error; `diagnostic()` gives the user-facing form.
#[derive(Debug, Clone, PartialEq)]
pub struct PmacError {
    diagnostic: Box<Diagnostic>,
}

impl PmacError {
    fn new(diagnostic: Diagnostic) -> Self {
        PmacError {
            diagnostic: Box::new(diagnostic),
        }
    }
    /// E7001: the coordinate system is not valid.
    pub fn coord_system(message: impl Into<String>) -> Self {
        Self::new(Diagnostic::error(code::E7001, message))
    }
    /// E7002: a move is not valid.
    pub fn invalid_move(index: usize, message: impl Into<String>) -> Self {
        Self::new(
            Diagnostic::error(
                code::E7002,
                format!("move {}: {}", index + 1, message.into()),
            )
            .with_hint("give one finite target per axis and positive finite limits"),
        )
    }
    /// E7003: a trajectory cannot be cut into PVT segments.
    pub fn trajectory(message: impl Into<String>) -> Self {
        Self::new(Diagnostic::error(code::E7003, message))
    }
    /// E7004: the controller replied with an error.
    pub fn controller(reply: &str) -> Self {
        Self::new(
            Diagnostic::error(
                code::E7004,
                format!("controller reported an error: {}", reply.trim()),
            )
            .with_note(
                "streaming stopped; the buffer was closed and the coordinate system aborted",
            ),
        )
    }
    /// E7005: transport (file, socket, timeout, protocol) failure.
    pub fn transport(message: impl Into<String>) -> Self {
        Self::new(Diagnostic::error(code::E7005, message))
    }
    /// E7006: program or PVT text outside what the checker reads.
    pub fn unreadable(line: usize, message: impl Into<String>) -> Self {
        Self::new(Diagnostic::error(
            code::E7006,
            format!("line {line}: {}", message.into()),
        ))
    }
    /// The diagnostic.
    pub fn diagnostic(&self) -> &Diagnostic {
        &self.diagnostic
    }
    /// The diagnostic, by value.
    pub fn into_diagnostic(self) -> Diagnostic {
        *self.diagnostic
    }
    /// The stable code, e.g. `E7004`.
    pub fn code(&self) -> &'static str {
        self.diagnostic.code.0
    }
}

impl std::fmt::Display for PmacError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.diagnostic.code, self.diagnostic.message)
    }
}

impl std::error::Error for PmacError {}

impl From<PmacError> for Diagnostic {
    fn from(e: PmacError) -> Self {
        *e.diagnostic
    }
}
