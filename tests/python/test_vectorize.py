"""The one vectorisation helper (src/bindings/vectorize.hpp, gecko._vectorize): a bad element is
named by its index in the caller's shape, and results do not depend on how the loop is split."""
import numpy as np
import pytest

import gecko


def test_error_names_the_index_in_the_callers_shape():
    m = np.array([[0.5, 0.2, 0.1], [0.3, 1.5, 0.1]])
    with pytest.raises(ValueError, match=r"m = 1.5 is out of range.*\(at index \(1, 1\)\)$"):
        gecko.ellint_k(m)
    with pytest.raises(ValueError, match=r"\(at index 2\)$"):
        gecko.ellint_k([0.1, 0.2, 3.0, 4.0])


@pytest.mark.parametrize("scalar", [3.0, np.float64(3.0), np.array(3.0)])
def test_a_scalar_has_no_index(scalar):
    # a scalar (0-d) input: the message names the argument and its value, and no index
    with pytest.raises(ValueError, match=r"m = 3 is out of range: need m <= 1$"):
        gecko.ellint_k(scalar)
    with pytest.raises(ValueError, match=r"\(at index 0\)$"):
        gecko.ellint_k([scalar])
    # the same through gecko._vectorize.with_index (contact_state's loop), not the raw "(at element 0)"
    seta = gecko.TwoLevelSeta()
    with pytest.raises(ValueError, match=r"Fn = nan is out of range: need a finite normal force$"):
        seta.contact_state(scalar * np.nan, 1.0)
    with pytest.raises(ValueError, match=r"Fn = nan is out of range: need a finite normal force \(at index 1\)$"):
        seta.contact_state([0.0, scalar * np.nan], 1.0)
    with pytest.raises(ValueError, match=r"force \(at index \(1, 0\)\)$"):
        seta.contact_state([[0.0], [np.nan]], [1.0, 2.0])


def test_smallest_failing_index_on_a_threaded_loop():
    m = np.full(200_000, 0.5)
    m[150_000] = 2.0   # in the second thread's block
    m[60_000] = 3.0    # in the first
    with pytest.raises(ValueError, match=r"m = 3 .*\(at index 60000\)$"):
        gecko.ellint_k(m)


def test_large_threaded_loop_equals_elementwise_calls():
    rng = np.random.default_rng(3)
    phi, m = rng.uniform(0, 1.5, 100_000), rng.uniform(-5, 1, 100_000)
    big = gecko.ellint_f(phi, m)
    idx = rng.integers(0, phi.size, 200)
    assert all(big[i] == gecko.ellint_f(float(phi[i]), float(m[i])) for i in idx)
