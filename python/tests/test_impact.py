"""The Python module against the command line: the same scenes give the same doubles.

Run by ctest (python_module) with PYTHONPATH at the build's module and IMPACT_CLI naming the
`impact` executable of the same build; IMPACT_SOURCE_DIR is the checkout (the paper's scenes).
"""
import csv
import glob
import json
import os
import subprocess

import numpy as np
import pytest

import impact

SOURCE = os.environ.get("IMPACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.environ.get("IMPACT_CLI", os.path.join(SOURCE, "build", "impact"))
PAPER_SCENES = sorted(glob.glob(os.path.join(SOURCE, "experiments", "figure[34]", "*.toml")))
PAPER_SCENES = [s for s in PAPER_SCENES if not s.endswith("reference.toml")]
COR075 = os.path.join(SOURCE, "experiments", "figure4", "cor075.toml")


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=False)


def read_csv(path):
    """Columns of a CSV the CLI wrote, each number read by float() (correctly rounded: the
    shortest round-trip text gives back the double that was written)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [row[k] for row in rows[1:]] for k, name in enumerate(rows[0])}


def as_doubles(texts):
    return np.array([float(x) if x != "" else np.nan for x in texts])


def same_bits(a, b):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def cli_run(tmp_path, scene, *args):
    out = tmp_path / "rows.csv"
    done = cli("run", scene, "--quiet", "--out", str(out), *args)
    assert done.returncode == 0, done.stderr
    return read_csv(out), json.loads((tmp_path / "rows.csv.json").read_text())


def test_paper_scenes_are_found():
    assert len(PAPER_SCENES) == 4, PAPER_SCENES


@pytest.mark.parametrize("scene", PAPER_SCENES, ids=os.path.basename)
def test_rows_equal_the_cli_csv_bit_for_bit(tmp_path, scene):
    rows, provenance = cli_run(tmp_path, scene)
    r = impact.run(scene)
    assert set(rows) == {"t", "u", "v", "N", "E"}
    for name, texts in rows.items():
        assert same_bits(r[name], as_doubles(texts)), name
    for key in ("steps", "contact_steps", "iterations", "max_iterations_per_step"):
        assert r["summary"][key] == provenance["summary"][key], key


@pytest.mark.parametrize("method", ["moreau_jean", "fb_newton", "exact"])
def test_other_methods_and_every_equal_the_cli(tmp_path, method):
    rows, _ = cli_run(tmp_path, COR075, "--set", f"method.name={method}", "--set",
                      "output.every=7", "--set", "time.h=0.002")
    r = impact.run(COR075, method=method, every=7, set={"time.h": 0.002})
    assert r["method"] == method
    for name, texts in rows.items():
        assert same_bits(r[name], as_doubles(texts)), name


def test_errors_against_exact_equal_the_cli(tmp_path):
    _, provenance = cli_run(tmp_path, COR075, "--against", "exact")
    r = impact.run(COR075, against="exact")
    for key in ("err_u_sup", "err_v_l1", "err_E_T", "err_first_impact"):
        assert same_bits(r["summary"][key], provenance["summary"][key]), key
    assert np.isfinite(r["summary"]["err_u_sup"]) and r["summary"]["err_u_sup"] > 0  # not exact


def test_text_and_dict_scenes_read_as_the_file():
    with open(COR075) as f:
        text = f.read()
    scene = {"initial": {"u0": 5.0, "v0": -1.0}, "floor": {"cor": 0.75},
             "force": {"f": -9.80665}, "time": {"T": 10.0, "h": 0.001},
             "method": {"name": "direct"}, "output": {"channels": ["u", "v", "N", "E"]}}
    from_file = impact.run(COR075)
    for other in (impact.run(text), impact.run(scene)):
        for name in ("t", "u", "v", "N", "E"):
            assert same_bits(other[name], from_file[name]), name


@pytest.mark.parametrize("key,value", [("time.h", -1.0), ("floor.cor", 1.5), ("time.hh", 0.1)])
def test_bad_key_raises_the_readers_message(key, value):
    with pytest.raises(ValueError) as error:
        impact.run(COR075, set={key: value})
    message = str(error.value)
    assert key.split(".")[1] in message
    done = cli("run", COR075, "--quiet", "--out", os.devnull, "--set", f"{key}={value}")
    assert done.returncode == 2
    assert message in done.stderr
    assert isinstance(error.value, impact.SceneError)


def test_bad_scene_text_names_its_source():
    with pytest.raises(ValueError, match="<string>"):
        impact.run("[time]\nT = 1.0\nh = 0.0\n")


def test_events_equal_the_cli(tmp_path):
    events = tmp_path / "events.csv"
    done = cli("run", COR075, "--quiet", "--out", os.devnull, "--events", str(events))
    assert done.returncode == 0, done.stderr
    expected = read_csv(events)
    e = impact.events(COR075)
    assert len(e["t"]) > 10
    assert list(e["kind"]) == expected["kind"]
    for name in ("t", "v_before", "v_after"):
        assert same_bits(e[name], as_doubles(expected[name])), name


@pytest.mark.parametrize("vary,summary", [
    ({"time.h": "1e-3:1e-2:5:log"}, ["rest_time", "E_T", "impacts"]),
    ({"floor.cor": "0:0.9:70"}, None),  # 70 points on one grid: stepped together (the ensemble)
])
def test_sweep_equals_the_cli(tmp_path, vary, summary):
    out = tmp_path / "sweep.csv"
    args = ["sweep", COR075, "--quiet", "--threads", "2", "--out", str(out)]
    for key, spec in vary.items():
        args += ["--vary", f"{key}={spec}"]
    if summary:
        args += ["--summary", ",".join(summary)]
    done = cli(*args)
    assert done.returncode == 0, done.stderr
    expected = read_csv(out)
    s = impact.sweep(COR075, vary=vary, summary=summary, threads=2)
    assert set(s) == set(expected) | {"points"}
    for name, texts in expected.items():
        if name == "failure":
            assert s[name] == texts
        else:
            assert same_bits(s[name], as_doubles(texts)), name


def test_sweep_of_a_list_equals_the_spec():
    by_spec = impact.sweep(COR075, vary={"floor.cor": "0.25:0.75:3"}, summary=["u_T"])
    by_list = impact.sweep(COR075, vary={"floor.cor": np.array([0.25, 0.5, 0.75])},
                           summary=["u_T"])
    assert same_bits(by_spec["u_T"], by_list["u_T"])


def test_exact_equals_the_exact_method_at_grid_times(tmp_path):
    rows, _ = cli_run(tmp_path, COR075, "--set", "method.name=exact")
    t = as_doubles(rows["t"])
    e = impact.exact(COR075, t[::-1])  # any order
    assert same_bits(e["t"], t[::-1])
    assert same_bits(e["u"][::-1], as_doubles(rows["u"]))
    assert same_bits(e["v"][::-1], as_doubles(rows["v"]))


def test_iterations_channel_is_int64_and_equals_the_cli(tmp_path):
    rows, _ = cli_run(tmp_path, COR075, "--set", "method.name=fb_newton", "--set",
                      'output.channels=["u", "iterations"]', "--set", "output.every=10")
    r = impact.run(COR075, method="fb_newton", every=10,
                   set={"output.channels": ["u", "iterations"]})
    assert r["iterations"].dtype == np.int64
    assert r["iterations"].tolist() == [int(x) for x in rows["iterations"]]
    # A row carries the iterations of the steps since the previous row: they add up to the run's.
    assert r["iterations"].sum() == r["summary"]["iterations"] > 0
    assert same_bits(r["u"], as_doubles(rows["u"]))
