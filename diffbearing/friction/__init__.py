"""Friction torque: the load-dependent (Palmgren) and the SKF four-source models."""
