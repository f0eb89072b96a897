"""The effects adapters."""
