"""The application layer: scenes, adapters, models, runs, sweeps, reports, plots and the CLI.

It depends on the physics modules (`diffbearing.*`), never the other way round. Within it, data
flows one way: registry ← adapters ← schema ← scene ← sweep ← model ← report, plots ← cli.
"""
