"""examples/python/wall_statistics.py against numbers worked by hand."""

import math

import pytest

from needed import need

need(["scipy"], "the statistics need Debian's python3-scipy")
import wall_statistics  # noqa: E402  (examples/python, on sys.path by conftest.py)

T_975_DF3 = 3.182446305  # Student's t, 0.975 quantile, 3 degrees of freedom (tables)
T_975_DF2 = 4.302652730


def test_the_interval_over_walls_is_the_student_t_interval():
    # 1, 2, 3, 4: mean 2.5, sample sd sqrt(5/3), half-width t * sd / sqrt(4).
    cell = wall_statistics.interval([1, 2, None, 3, 4, float("nan")])
    half = T_975_DF3 * math.sqrt(5 / 3) / 2
    assert cell["n"] == 4 and cell["mean"] == 2.5
    assert cell["low"] == pytest.approx(2.5 - half, abs=1e-9) and cell["high"] == pytest.approx(2.5 + half, abs=1e-9)
    assert wall_statistics.interval([7]) == {"mean": 7.0, "low": None, "high": None, "n": 1}


def test_paired_differences_skip_walls_missing_either_value():
    # Differences 2, 3, 2 (the fourth wall has no b): mean 7/3, sd sqrt(1/3), t = 7 on 2
    # degrees of freedom, whose two-sided p is 1 - t / sqrt(2 + t^2).
    cell = wall_statistics.paired([3, 5, 4, 9], [1, 2, 2, None])
    half = T_975_DF2 * math.sqrt(1 / 3) / math.sqrt(3)
    assert cell["n"] == 3 and cell["mean"] == pytest.approx(7 / 3)
    assert cell["low"] == pytest.approx(7 / 3 - half, abs=1e-8)
    assert cell["p"] == pytest.approx(1 - 7 / math.sqrt(51), abs=1e-12)
    assert wall_statistics.paired([2, 3], [1, 2])["p"] is None  # equal differences: no test


def test_a_walls_mean_is_over_the_runs_that_have_the_key():
    runs = [[{"length": 10}, {"length": None}, {"length": 14}], [{"length": None}], [{"other": 1}]]
    assert wall_statistics.per_wall_mean(runs, "length") == [12.0, None, None]
