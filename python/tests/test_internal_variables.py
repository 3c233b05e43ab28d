"""Internal variables through the Python module: the arrays, events, exact solution and summary
carry them under the scene's names and equal what `impact run` writes, bit for bit.

The scene is a drop with COR 0.2 under a pull that decays with z (z' = -z: f = 5 - 15 e^-t), and
a second variable that follows it (bond' = -bond z): impacts, a rest and a lift-off at ln 3.
"""
import math

import numpy as np
import pytest

import impact
from test_impact import as_doubles, cli, read_csv, same_bits

SCENE = """\
[initial]
u0 = 0.2
v0 = 0.0
[floor]
cor = 0.2
[force]
expression = "5 - 15 * z"
[[internal]]
name = "z"
initial = 1.0
rate = "-z"
[[internal]]
name = "bond"
initial = 0.5
rate = "-bond * z"
[time]
T = 2.0
h = 0.001
[method]
name = "event_driven"
[output]
channels = ["u", "v", "N", "E", "z", "bond"]
"""

METHODS = ["direct", "moreau_jean", "event_driven"]


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "internal.toml"
    path.write_text(SCENE)
    return str(path)


def cli_rows(tmp_path, scene, *args):
    out = tmp_path / "rows.csv"
    done = cli("run", scene, "--quiet", "--out", str(out), *args)
    assert done.returncode == 0, done.stderr
    return read_csv(out), done


@pytest.mark.parametrize("every", [1, 7])
@pytest.mark.parametrize("method", METHODS)
def test_internal_variable_arrays_equal_the_cli_csv_bit_for_bit(tmp_path, scene, method, every):
    rows, _ = cli_rows(tmp_path, scene, "--set", f"method.name={method}", "--set",
                       f"output.every={every}")
    r = impact.run(scene, method=method, every=every)
    assert list(rows) == ["t", "u", "v", "N", "E", "z", "bond"]
    assert set(r) == set(rows) | {"method", "summary"}  # no z1, z2: the scene's names
    for name, texts in rows.items():
        assert same_bits(r[name], as_doubles(texts)), name
    # The summary's z at T is the last row's.
    for name in ("z", "bond"):
        assert same_bits(r["summary"][f"{name}_T"], r[name][-1]), name


def test_no_array_holds_memory_the_module_did_not_write(scene):
    """The arrays of internal channels used to be uninitialised (1e-315, 4e+241, new on each call):
    the same run twice gives the same bits, and every value is what the run gives."""
    first = impact.run(scene, method="direct")
    for _ in range(3):
        again = impact.run(scene, method="direct")
        for name in ("t", "u", "v", "N", "E", "z", "bond"):
            assert same_bits(again[name], first[name]), name
    # z = e^-t to first order in h (explicit Euler), far from garbage.
    assert np.max(np.abs(first["z"] - np.exp(-first["t"]))) < 1e-3


@pytest.mark.parametrize("method", METHODS)
def test_internal_variables_at_events_equal_the_cli(tmp_path, scene, method):
    events = tmp_path / "events.csv"
    done = cli("run", scene, "--quiet", "--out", "/dev/null", "--set", f"method.name={method}",
               "--events", str(events))
    assert done.returncode == 0, done.stderr
    expected = read_csv(events)
    assert list(expected) == ["t", "kind", "v_before", "v_after", "z", "bond"]
    e = impact.events(scene, method=method)
    assert set(e) == set(expected)
    assert list(e["kind"]) == expected["kind"]
    assert "lift" in expected["kind"]
    for name in ("t", "v_before", "v_after", "z", "bond"):
        assert same_bits(e[name], as_doubles(expected[name])), name


def test_exact_gives_the_internal_variables_of_the_reference(scene):
    t = np.array([2.0, 0.0, 1.0, -1.0, math.log(3)])
    e = impact.exact(scene, t)
    assert set(e) == {"t", "u", "v", "z", "bond"}
    assert same_bits(e["t"], t)
    # z = e^-t from the ODE of event_driven's track; z(0) at t <= 0.
    assert np.max(np.abs(e["z"][t > 0] - np.exp(-t[t > 0]))) < 1e-9
    assert e["z"][1] == 1.0 and e["z"][3] == 1.0 and e["bond"][3] == 0.5


@pytest.mark.parametrize("method", ["direct", "event_driven"])
def test_largest_internal_error_against_exact_is_the_arrays(tmp_path, scene, method):
    """err_internal_sup is max over the steps of |z_i - z_i(t_l)|: recomputed from the rows and
    impact.exact at their times, it is the same double; and it is what the CLI prints."""
    done = cli("run", scene, "--out", str(tmp_path / "rows.csv"), "--set", f"method.name={method}",
               "--against", "exact")
    assert done.returncode == 0, done.stderr
    r = impact.run(scene, method=method, against="exact")
    e = impact.exact(scene, r["t"])
    by_hand = max(np.max(np.abs(r[name][1:] - e[name][1:])) for name in ("z", "bond"))
    assert same_bits(r["summary"]["err_internal_sup"], by_hand)
    printed = done.stderr.split("sup|z - z_exact| = ")[1].split()[0]
    assert same_bits(r["summary"]["err_internal_sup"], float(printed))
    assert r["summary"]["err_internal_sup"] < (1e-2 if method == "direct" else 1e-9)
