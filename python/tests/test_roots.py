"""batch_roots against numpy: numpy.roots (companion-matrix eigenvalues,
LAPACK) on random quartics is the independent route; each of our roots
must satisfy the quartic to its backward-error bound as well."""

import numpy as np
import pytest

import delta_stability as ds


def _match(ours, theirs):
    """|ours − theirs| per root after pairing each of ours with the nearest
    of theirs (greedy, without reuse)."""
    theirs = list(theirs)
    gaps = []
    for z in ours:
        k = int(np.argmin([abs(z - t) for t in theirs]))
        gaps.append(abs(z - theirs.pop(k)))
    return np.array(gaps)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_quartics_agree_with_numpy_roots(seed):
    rng = np.random.default_rng(seed)
    c = rng.normal(size=(2000, 5)) * 10.0 ** rng.uniform(-3, 3, size=(2000, 5))
    ours = ds.batch_roots(c)
    assert ours.shape == (2000, 4) and ours.dtype == np.complex128
    worst = 0.0
    for row, r in zip(c, ours):
        theirs = np.roots(row)
        scale = max(1.0, max(abs(theirs)))
        # a well-separated root agrees to ~ε·condition; clusters less so
        worst = max(worst, float(np.median(_match(r, theirs) / scale)))
        # backward error of each of our roots, |P(λ)| / Σ|c_k||λ|^(4−k)
        for z in r:
            p = np.polyval(row, z)
            size = np.polyval(np.abs(row), abs(z))
            assert abs(p) <= 1e-12 * size, (row, z)
    assert worst < 1e-6


def test_the_stability_quartic_s_roots_are_quartic_s():
    q = ds.quartic("examples/tailless-delta-45.toml")
    r = ds.batch_roots(q.coefficients)
    assert r.shape == (4,)
    np.testing.assert_array_equal(r, q.roots)
    np.testing.assert_allclose(np.sort_complex(r), np.sort_complex(np.roots(q.coefficients)),
                               rtol=1e-12)


def test_order_and_shapes():
    # (λ² + 1)(λ² + 4λ + 13) = λ⁴ + 4λ³ + 14λ² + 4λ + 13: roots −2 ± 3i, ± i
    r = ds.batch_roots([[1, 4, 14, 4, 13]] * 3)
    np.testing.assert_allclose(r[0], [-2 + 3j, -2 - 3j, 1j, -1j], atol=1e-14)
    assert ds.batch_roots(np.ones((2, 3, 5))).shape == (2, 3, 4)
    assert ds.batch_roots(np.zeros((0, 5))).shape == (0, 4)
    # integer and float32 input is converted
    assert ds.batch_roots(np.array([[1, 0, 0, 0, -1]], dtype=np.int32)).shape == (1, 4)


def test_large_batches_run_in_parallel_and_agree_with_small_ones():
    rng = np.random.default_rng(7)
    c = rng.normal(size=(20000, 5))
    whole = ds.batch_roots(c)
    parts = np.concatenate([ds.batch_roots(c[i:i + 1000]) for i in range(0, 20000, 1000)])
    np.testing.assert_array_equal(whole, parts)


def test_rows_without_roots_raise_or_give_nan():
    c = np.array([[1, 2, 3, 4, 5], [0, 1, 2, 3, 4], [1, np.nan, 0, 0, 1]], dtype=float)
    with pytest.raises(ValueError, match=r"row 1 .*leading coefficient A is zero"):
        ds.batch_roots(c)
    r = ds.batch_roots(c, errors="nan")
    assert np.all(np.isfinite(r[0])) and np.all(np.isnan(r[1])) and np.all(np.isnan(r[2]))
    with pytest.raises(ValueError, match="shape"):
        ds.batch_roots(np.ones((3, 4)))
    with pytest.raises(ValueError, match="errors"):
        ds.batch_roots(c, errors="ignore")
