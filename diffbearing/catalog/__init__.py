"""Bearings by designation: boundary dimensions of the standards' dimension series
(`designations`), shipped as data read from the standards (`boundary_dimensions.csv`), and the
internal geometry estimated from them (`internal_geometry`)."""
