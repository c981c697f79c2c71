//! drive-script (to be written).
