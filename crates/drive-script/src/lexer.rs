//! Lexer: script text to tokens with byte spans.
//!
//! Input: the whole script text. Output: tokens (`S::` marker, `;`, identifiers, integers, operators) and
//! the byte ranges of characters that are not part of the language. Comments (`//` to end of line) and
//! whitespace are dropped. Invariant: token ranges are increasing, non-overlapping and on UTF-8 boundaries.

#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Tok {
    /// `S::` (case-insensitive `s::` too).
    Start,
    Semi,
    Ident(String),
    /// The magnitude of an integer literal (a leading `-` is a separate token); `None` if it does not fit in
    /// u64 or is malformed (`10ms`); the flag is true for hex (`0x...`).
    Int(Option<u64>, bool),
    /// `=` or `==`.
    Eq,
    /// `<>` or `!=`.
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    Plus,
    Minus,
    Star,
    Slash,
    Percent,
    Amp,
    Pipe,
    Caret,
    Tilde,
    LParen,
    RParen,
    Comma,
    /// A character outside the language.
    Bad(char),
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Token {
    pub tok: Tok,
    pub start: usize,
    pub end: usize,
}

pub fn lex(text: &str) -> Vec<Token> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        let start = i;
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        if c == b'/' && bytes.get(i + 1) == Some(&b'/') {
            while i < bytes.len() && !matches!(bytes[i], b'\n' | b'\r') {
                i += 1;
            }
            continue;
        }
        if (c == b'S' || c == b's')
            && bytes.get(i + 1) == Some(&b':')
            && bytes.get(i + 2) == Some(&b':')
        {
            out.push(Token {
                tok: Tok::Start,
                start,
                end: i + 3,
            });
            i += 3;
            continue;
        }
        if c.is_ascii_alphabetic() || c == b'_' {
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            out.push(Token {
                tok: Tok::Ident(text[start..i].to_string()),
                start,
                end: i,
            });
            continue;
        }
        if c.is_ascii_digit() {
            // The whole alphanumeric run is one literal, so `10ms` is one bad literal, not `10` then `ms`.
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            let run: String = text[start..i].chars().filter(|c| *c != '_').collect();
            let hex_digits = run.strip_prefix("0x").or_else(|| run.strip_prefix("0X"));
            let hex = hex_digits.is_some();
            let value = match hex_digits {
                Some(hex) if !hex.is_empty() => u64::from_str_radix(hex, 16).ok(),
                Some(_) => None,
                None => run.parse::<u64>().ok(),
            };
            out.push(Token {
                tok: Tok::Int(value, hex),
                start,
                end: i,
            });
            continue;
        }
        let two = |a: u8, b: u8| c == a && bytes.get(i + 1) == Some(&b);
        let (tok, len) = if two(b'=', b'=') {
            (Tok::Eq, 2)
        } else if two(b'<', b'>') || two(b'!', b'=') {
            (Tok::Ne, 2)
        } else if two(b'<', b'=') {
            (Tok::Le, 2)
        } else if two(b'>', b'=') {
            (Tok::Ge, 2)
        } else {
            let t = match c {
                b';' => Tok::Semi,
                b'=' => Tok::Eq,
                b'<' => Tok::Lt,
                b'>' => Tok::Gt,
                b'+' => Tok::Plus,
                b'-' => Tok::Minus,
                b'*' => Tok::Star,
                b'/' => Tok::Slash,
                b'%' => Tok::Percent,
                b'&' => Tok::Amp,
                b'|' => Tok::Pipe,
                b'^' => Tok::Caret,
                b'~' => Tok::Tilde,
                b'(' => Tok::LParen,
                b')' => Tok::RParen,
                b',' => Tok::Comma,
                _ => {
                    let ch = text[i..].chars().next().unwrap_or('\u{fffd}');
                    let len = ch.len_utf8();
                    out.push(Token {
                        tok: Tok::Bad(ch),
                        start,
                        end: i + len,
                    });
                    i += len;
                    continue;
                }
            };
            (t, 1)
        };
        out.push(Token {
            tok,
            start,
            end: i + len,
        });
        i += len;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(s: &str) -> Vec<Tok> {
        lex(s).into_iter().map(|t| t.tok).collect()
    }

    #[test]
    fn paper_statement_lexes() {
        let t = kinds("S:: THEN DO_0=HIGH AND RelativeTargetPosition=10000; // c");
        assert_eq!(t[0], Tok::Start);
        assert_eq!(t[1], Tok::Ident("THEN".into()));
        assert_eq!(t[3], Tok::Eq);
        assert_eq!(t[8], Tok::Int(Some(10000), false));
        assert_eq!(t.last(), Some(&Tok::Semi));
    }

    #[test]
    fn operators_hex_and_bad_characters() {
        assert_eq!(
            kinds("<> != <= >= == 0x1F 10ms @"),
            vec![
                Tok::Ne,
                Tok::Ne,
                Tok::Le,
                Tok::Ge,
                Tok::Eq,
                Tok::Int(Some(31), true),
                Tok::Int(None, false),
                Tok::Bad('@')
            ]
        );
    }

    #[test]
    fn identifier_starting_with_s_is_not_a_statement_start() {
        assert_eq!(kinds("SetPosition"), vec![Tok::Ident("SetPosition".into())]);
    }
}
