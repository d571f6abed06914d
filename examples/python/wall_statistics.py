"""Statistics over walls, to the standard of docs/REPRODUCTION.md: each wall one
observation (its runs' mean), 95 % Student-t intervals over walls, paired differences
with the two-sided t-test. The baselines import it from their folder."""

import math

import numpy as np
from scipy import stats


def interval(values):
    """Mean and 95 % Student-t interval over walls (None values left out)."""
    values = np.asarray([v for v in values if v is not None and not math.isnan(v)], float)
    if values.size < 2:
        return {"mean": float(values.mean()) if values.size else None, "low": None, "high": None, "n": int(values.size)}
    half = stats.t.ppf(0.975, values.size - 1) * values.std(ddof=1) / math.sqrt(values.size)
    return {"mean": float(values.mean()), "low": float(values.mean() - half), "high": float(values.mean() + half),
            "n": int(values.size)}


def paired(a, b):
    """a - b over the walls where both have a value, with its t-interval and the two-sided p
    of the t-test over walls (None when the differences are all equal)."""
    pairs = [(x, y) for x, y in zip(a, b) if x is not None and y is not None]
    diff = np.array([x - y for x, y in pairs], float)
    result = interval(diff)
    constant = diff.size < 2 or np.allclose(diff, diff[0])
    result["p"] = None if constant else float(stats.ttest_1samp(diff, 0.0).pvalue)
    return result


def per_wall_mean(runs, key):
    """runs: per wall, a list of per-run dicts; the mean of key over the runs that have it."""
    out = []
    for wall in runs:
        values = [run[key] for run in wall if run.get(key) is not None]
        out.append(float(np.mean(values)) if values else None)
    return out
