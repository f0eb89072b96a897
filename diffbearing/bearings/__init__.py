"""Bearing types: each a sub-package (`ball`, `roller`) with its geometry, contact model and equilibrium."""
