"""Roller bearings (cylindrical, tapered): geometry, profiles, sliced (laminae) contact and the
equilibrium of ring and rollers."""
