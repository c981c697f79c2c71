//! motion-lib (to be written).
