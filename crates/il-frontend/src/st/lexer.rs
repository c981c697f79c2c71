//! ST lexer (skeleton).
