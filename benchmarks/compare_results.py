"""Largest difference between two `diffbearing run --json` documents, output by output.

    python benchmarks/compare_results.py old.json new.json

For each output present in both: max |new − old| over its elements, relative to max |old| (so a
component that is zero up to round-off does not inflate the figure). Timings, titles, messages
and the solver's own residual (round-off by definition) are left out. Used to check that a
refactoring keeps results: run a scene with the old and the new code and compare.
"""

import json
import sys

import numpy as np

SKIPPED = ("title", "errors", "warnings", "not_computed", "residual")


def flat(tree: dict, prefix: str = "") -> dict:
    out = {}
    for key, value in tree.items():
        if isinstance(value, dict):
            out |= flat(value, f"{prefix}{key}.")
        else:
            out[f"{prefix}{key}"] = value
    return out


def differences(old: dict, new: dict) -> dict[str, float]:
    """{output key: max |new − old| / max |old|} (NaN where a value is missing on one side only)."""
    found = {}
    for key, value in old.items():
        if key.startswith("timing.") or key in SKIPPED or key not in new:
            continue
        a, b = np.array(value, dtype=float), np.array(new[key], dtype=float)
        if a.shape != b.shape or np.any(np.isnan(a) != np.isnan(b)):
            found[key] = float("nan")
            continue
        valid = ~np.isnan(a)
        scale = np.max(np.abs(a[valid])) if valid.any() else 0.0
        change = np.max(np.abs(a - b)[valid]) if valid.any() else 0.0
        found[key] = float(change / scale) if scale > 0 else float(change)
    return found


def main(old_path: str, new_path: str) -> None:
    old, new = (flat(json.load(open(path))) for path in (old_path, new_path))
    found = differences(old, new)
    for key, value in sorted(found.items(), key=lambda item: -np.nan_to_num(item[1], nan=np.inf)):
        print(f"{value:10.3e}  {key}")
    mismatched = [key for key, value in found.items() if np.isnan(value)]
    largest = max((value for value in found.values() if not np.isnan(value)), default=0.0)
    print(f"largest relative difference {largest:.3e} over {len(found)} outputs; shape or NaN pattern differs: "
          f"{mismatched or 'none'}; only in old: {sorted(set(old) - set(new)) or 'none'}; "
          f"only in new: {sorted(set(new) - set(old)) or 'none'}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
