# collide.stationary_mean and collide.integrated_autocorrelation_time (python/statistics.cpp over
# core/statistics/batch_means.h): the equilibration cut and the error bar every recorded pressure
# gets, on series whose answers are known (white noise; a melt followed by noise), and refusals.
import numpy as np
import pytest

import collide


def test_white_noise_keeps_everything_and_its_error_is_the_naive_one():
    x = np.random.default_rng(1).normal(3.0, 2.0, 20000)
    e = collide.stationary_mean(x)
    assert e["equilibration_cut"] == 0 and e["used"] == 20000 and e["batches"] == 20
    assert abs(e["mean"] - 3.0) < 4 * e["error"]
    assert e["error"] == pytest.approx(2.0 / np.sqrt(20000), rel=0.4)
    assert collide.integrated_autocorrelation_time(x) == pytest.approx(0.5, abs=0.03)


def test_a_melt_is_cut_away_and_the_cut_is_the_candidate_with_most_effective_samples():
    x = np.random.default_rng(2).normal(0.0, 1.0, 4000)
    x[:600] += np.linspace(10.0, 0.0, 600)          # a transient of 600 entries
    e = collide.stationary_mean(x)
    cuts = [c for c, _ in e["candidates"]]
    assert cuts == list(range(0, 2001, 200))
    best = max(e["candidates"], key=lambda c: c[1])
    assert e["equilibration_cut"] == best[0] >= 400
    assert e["mean"] == pytest.approx(x[e["equilibration_cut"]:].mean())
    for cut, effective in e["candidates"]:
        tau = collide.integrated_autocorrelation_time(x[cut:])
        assert effective == pytest.approx((len(x) - cut) / max(1.0, 2 * tau))
    whole = collide.stationary_mean(x, cut_from_data=False)
    assert whole["equilibration_cut"] == 0 and whole["candidates"] == []
    assert abs(whole["mean"]) > 5 * e["error"]       # without the cut the melt biases the mean


@pytest.mark.parametrize("series, batches, words", [
    ([1.0, float("nan"), 2.0], 20, "entry 1 is not finite"),
    ([[1.0, 2.0], [3.0, 4.0]], 20, "1-D"),
    ([1.0], 20, "at least 2 entries"),
    ([1.0, 2.0, 3.0], 1, "batches"),
])
def test_refusals_name_what_is_wrong(series, batches, words):
    with pytest.raises(ValueError, match=words):
        collide.stationary_mean(np.array(series), batches=batches)
