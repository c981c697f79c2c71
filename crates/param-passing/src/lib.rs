//! param-passing (to be written).
