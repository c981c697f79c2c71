//! c-backend (to be written).
