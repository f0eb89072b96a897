"""Contact mechanics shared by the bearing types: Hertz point and line contacts, elliptic integrals,
surface influence coefficients and non-Hertzian normal contact."""
