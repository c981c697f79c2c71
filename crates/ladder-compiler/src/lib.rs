//! ladder-compiler (to be written).
