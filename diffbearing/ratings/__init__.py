"""Ratings: ISO 281 and ISO/TS 16281 life, life modification, ISO 76 static safety, radial and axial
load factors, minimum load and the closed-form load distribution the standards rest on."""
