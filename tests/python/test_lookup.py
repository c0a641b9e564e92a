"""Creep-force lookup tables from Python: a coarse table built by the CLI, loaded as
rollcontact.CreepLookupTable, evaluated over NumPy arrays (broadcast) and in physical units."""

import subprocess

import numpy as np

import rollcontact as rc


def test_lookup_table_from_python(cli, tmp_path):
    path = tmp_path / "coarse.h5"
    subprocess.run([cli, "lookup", "-o", str(path), "--grid", "coarse", "--mx", "9",
                    "--check", "0", "-q"], check=True)
    t = rc.CreepLookupTable(str(path))
    assert t.method == "exact" and t.mx == 9
    assert t.axes["ksi_n"][0] == -1.0 and len(t.axes["a_over_b"]) == 3
    # Broadcasting: one a/b, a row of creepages.
    ksi = np.array([-0.3, -0.1, 0.0, 0.1, 0.3])
    v = t.evaluate(1.0, ksi, 0.0, 0.0)
    assert v.shape == (5, 3)
    # Odd in ξ, opposite to it (force on the wheel), below μFN, zero at zero creepage.
    assert np.allclose(v[:, 0], -v[::-1, 0], atol=1e-6)
    assert np.all(np.sign(v[[0, 1], 0]) == 1) and np.all(np.sign(v[[3, 4], 0]) == -1)
    assert abs(v[2, 0]) < 1e-9 and np.all(np.abs(v[:, 0]) <= 1.0 + 1e-9)
    # Physical units: the normalisation of the table.
    a, b, fn, g, mu = 6.0, 4.0, 5e4, 8e4, 0.35
    c = np.sqrt(a * b)
    s = g * c * c / (mu * fn)
    fx, fy, mz = t.forces(a, b, fn, g, mu, 0.1 / s, 0.0, 0.0)
    ref = t.evaluate(a / b, 0.1, 0.0, 0.0)
    assert np.isclose(fx, ref[0] * mu * fn) and np.isclose(mz, ref[2] * mu * fn * c)
