"""The systems adapters."""
