//! Displacement-controlled MDR: the foundation driven by a prescribed indentation history.
