//! pmac-backend (to be written).
