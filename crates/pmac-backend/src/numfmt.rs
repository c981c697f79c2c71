//! Number formatting for PMAC text.
//!
//! Input: finite f64 values and a number of decimals.
//! Output: the shortest decimal text with at most that many decimals (`1600`, `53.852`, `-0.5`).
//! Invariants: no exponent, no trailing zeros or dot, never `-0`.

/// `x` rounded to `decimals` places, trailing zeros removed.
pub fn num(x: f64, decimals: usize) -> String {
    let mut s = format!("{:.*}", decimals, x);
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".to_string();
    }
    s
}

/// The value `num` would print, parsed back.
pub fn rounded(x: f64, decimals: usize) -> f64 {
    num(x, decimals).parse().unwrap_or(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn trims_and_rounds() {
        assert_eq!(num(1600.0, 6), "1600");
        assert_eq!(num(53.851648, 3), "53.852");
        assert_eq!(num(-0.0000001, 3), "0");
        assert_eq!(num(-2.50, 3), "-2.5");
        assert_eq!(num(10500.0, 3), "10500");
        assert_eq!(rounded(82.93233, 3), 82.932);
    }
}
