"""The bearings adapters."""
