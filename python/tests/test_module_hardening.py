"""The Python module under hostile input: structures that contain themselves or nest without end,
Ctrl-C during long work, a named pipe as the scene, failed runs, values --set cannot take, and
absurd thread counts. What could crash or hang the interpreter runs in a child process with a
timeout, so that a crash or a hang is a failed test, not a lost test session.
"""
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import impact
from test_impact import COR075, as_doubles, cli, read_csv, same_bits

# Figure 4's scene with a force of t that never lets the particle rest (no repeating steps to
# skip over): every step is computed.
EXPRESSION = open(COR075).read().replace("f = -9.80665", 'expression = "-9.81 + 12 * sin(3 * t)"')
assert "expression" in EXPRESSION


def child(code, timeout=60, **kwargs):
    """Runs `code` in a fresh interpreter that imports this build's module."""
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True,
                          text=True, timeout=timeout, env=dict(os.environ), **kwargs)


def interrupted(code, after=0.5):
    """Runs `code` in a child that prints 'ready' first (after its imports: NumPy's, which the
    module's first array makes, takes seconds on a loaded machine), sends it SIGINT `after`
    seconds later; returns what it printed and when (time.time()) the signal went."""
    process = subprocess.Popen([sys.executable, "-c", textwrap.dedent(code)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=dict(os.environ))
    try:
        assert process.stdout.readline().strip() == "ready"
        time.sleep(after)
        sent = time.time()
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=30)
    finally:
        process.kill()
    assert process.returncode == 0, err
    return out, sent


# --- a dict or list that contains itself, or nests deeper than any scene -----------------------

NESTED = {
    "a dict that holds itself": ("d = {}; d['x'] = d; impact.run(d)", "scene['x']: refers back"),
    "a list that holds itself": ("l = []; l.append(l); impact.run({'output': {'channels': l}})",
                                 "scene['output']['channels'][0]: refers back"),
    "a cycle through a list": ("d = {'a': []}; d['a'].append(d); impact.run({'t': d})",
                               "scene['t']['a'][0]: refers back"),
    "a list nested 1e5 deep": ("l = []\nfor _ in range(100000): l = [l]\n"
                               "impact.run({'output': {'channels': l}})",
                               "scene['output']['channels'][0][0]"),
    "a dict nested 1e5 deep": ("d = {}\nfor _ in range(100000): d = {'k': d}\nimpact.run(d)",
                               "scene['k']['k']['k']"),
    "a deep list as a set value": ("l = []\nfor _ in range(100000): l = [l]\n"
                                   "impact.run(COR075, set={'output.channels': l})",
                                   "set['output.channels'][0][0]"),
    "a list that holds itself as a set value": (
        "l = []; l.append(l); impact.run(COR075, set={'output.channels': l})",
        "set['output.channels'][0]: refers back"),
    "a deep list as a sweep's values": ("l = []\nfor _ in range(100000): l = [l]\n"
                                        "impact.sweep(COR075, vary={'floor.cor': [l]})",
                                        "vary['floor.cor'][0]"),
}


@pytest.mark.parametrize("case", list(NESTED))
def test_a_structure_that_contains_itself_or_nests_without_end_is_a_value_error(case):
    code, path = NESTED[case]
    done = child(f"""
        import impact
        COR075 = {COR075!r}
        try:
{textwrap.indent(code, ' ' * 12)}
        except ValueError as e:
            print('ValueError:', e)
    """)
    assert done.returncode == 0, done.stderr  # a crash (SIGSEGV) is -11
    assert done.stdout.startswith("ValueError: " + path), done.stdout
    assert "refers back" in done.stdout or "nested more than 32 levels" in done.stdout


# --- Ctrl-C ----------------------------------------------------------------------------------

LONG = {
    # a rest on the floor (repeating steps), 1e9 steps
    "run at rest": "impact.run(COR075, set={'time.T': 1e6, 'output.every': 10**6})",
    "run of a force of t": f"impact.run(EXPR, set={{'time.T': 1e5, 'output.every': 10**6}})",
    "run against exact": f"impact.run(EXPR, set={{'time.T': 1e5, 'output.every': 10**6}}, "
                         "against='exact')",
    "run with T/h = 1e12": "impact.run(COR075, set={'time.T': 1e9, 'time.h': 1e-3, "
                           "'output.every': 10**10})",
    "events": f"impact.events(EXPR, set={{'time.T': 1e5}})",
    "sweep point by point": f"impact.sweep(EXPR, vary={{'floor.cor': [0.1, 0.5, 0.9]}}, "
                            "set={'time.T': 1e5}, threads=2)",
    "sweep of one long point": f"impact.sweep(EXPR, vary={{'floor.cor': [0.5]}}, "
                               "set={'time.T': 1e5}, threads=1)",
    # a constant force, each point on its own grid: the summary alone steps
    "sweep of points at rest": "impact.sweep(COR075, vary={'time.h': [1e-3, 2e-3]}, "
                               "set={'time.T': 1e6}, threads=1)",
    "sweep in the ensemble": "impact.sweep(COR075, vary={'floor.cor': '0:0.9:70', "
                             "'initial.u0': [5, 6]}, set={'time.T': 1e5}, threads=2)",
}


@pytest.mark.parametrize("case", list(LONG))
def test_ctrl_c_stops_long_work_within_a_tenth_of_a_second(tmp_path, case):
    """SIGINT 0.5 s into work of minutes: KeyboardInterrupt within about 0.1 s (measured 1 to 40
    ms, once 0.12 s with 6 jobs on 2 cores: the bound here is 0.3 s for a machine shared with
    other jobs; before, the interrupt came when the work ended), nothing returned, and the module
    works on."""
    expression = tmp_path / "expression.toml"
    expression.write_text(EXPRESSION)
    out, sent = interrupted(f"""
        import time
        import numpy
        import impact
        COR075, EXPR = {COR075!r}, {str(expression)!r}
        impact.run(COR075, every=1000)
        print('ready', flush=True)
        try:
            result = {LONG[case]}
            print('finished')
        except KeyboardInterrupt:
            print('interrupted at', repr(time.time()), flush=True)
            print('works on:', len(impact.run(COR075, every=100)['t']))
    """)
    assert "interrupted at" in out, out
    delay = float(out.split("interrupted at ")[1].split()[0]) - sent
    print(f"{case}: KeyboardInterrupt {delay * 1e3:.1f} ms after SIGINT")
    assert delay < 0.3, f"{case}: KeyboardInterrupt {delay:.3f} s after SIGINT"
    assert "works on: 101" in out


# --- a named pipe as the scene ---------------------------------------------------------------

@pytest.mark.parametrize("call", ["run(FIFO)", "events(FIFO)", "exact(FIFO, [0.5])",
                                  "sweep(FIFO, vary={'floor.cor': [0.5]})"])
def test_opening_a_named_pipe_as_the_scene_does_not_hold_the_gil(tmp_path, call):
    """While impact waits for a writer, other Python threads run; then the scene comes through the
    pipe and the call returns what it gives for the file."""
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)
    done = child(f"""
        import threading, time
        import impact
        FIFO = {str(fifo)!r}
        out = {{}}
        worker = threading.Thread(target=lambda: out.update(r=impact.{call}))
        worker.start()
        start, loops = time.monotonic(), 0
        while time.monotonic() - start < 0.3:
            loops += 1
        print('loops', loops, flush=True)
        with open(FIFO, 'w') as f:
            f.write(open({COR075!r}).read())
        worker.join()
        FIFO = {COR075!r}
        expected = impact.{call}
        print('same', all(str(out['r'][k]) == str(expected[k]) for k in expected if k != 'summary'))
    """, timeout=30)
    assert done.returncode == 0, done.stderr
    assert int(done.stdout.split("loops ")[1].split()[0]) > 1000, done.stdout
    assert "same True" in done.stdout


def test_ctrl_c_while_waiting_on_a_named_pipe_is_a_keyboard_interrupt(tmp_path):
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)
    out, _ = interrupted(f"""
        import numpy
        import impact
        print('ready', flush=True)
        try:
            impact.run({str(fifo)!r})
        except KeyboardInterrupt:
            print('interrupted', flush=True)
    """)
    assert "interrupted" in out


# --- a run that fails ------------------------------------------------------------------------

FAILING = {
    "a force not finite after t = 0.5": (
        "[initial]\nu0 = 5.0\nv0 = 0.0\n[force]\nexpression = \"t < 0.5 ? -9.81 : sqrt(-1)\"\n"
        "[time]\nT = 1.0\nh = 0.001\n[method]\nname = \"direct\"\n", "time.T=0.4,1"),
    "a rate that blows up": (
        "[initial]\nu0 = 3.0\nv0 = 0.0\n[force]\nexpression = \"-9.81 + z\"\n[[internal]]\n"
        "name = \"z\"\ninitial = 1.0\nrate = \"z^2*u\"\n[time]\nT = 2.0\nh = 0.001\n"
        "[method]\nname = \"direct\"\n", "initial.u0=0.1,3"),
    "a solve that does not converge": (
        open(COR075).read().replace('name = "direct"', 'name = "fb_newton"\nmax_iterations = 1'),
        "floor.cor=0.5,0.75"),
}


@pytest.mark.parametrize("case", list(FAILING))
def test_a_failed_run_raises_numerical_error_where_the_cli_exits_1(tmp_path, case):
    text, vary = FAILING[case]
    scene = tmp_path / "s.toml"
    scene.write_text(text)
    assert cli("run", str(scene), "-q", "-o", os.devnull).returncode == 1
    for call in (lambda: impact.run(str(scene)), lambda: impact.events(str(scene))):
        with pytest.raises(impact.NumericalError):
            call()
    # A sweep: the points the CLI writes as failure rows (exit 1 when one failed) are failures here
    # too; where it writes no file, NumericalError.
    out = tmp_path / "sweep.csv"
    done = cli("sweep", str(scene), "-q", "--vary", vary, "-o", str(out))
    assert done.returncode == 1, done.stderr
    key, values = vary.split("=")
    grid = {key: [float(x) for x in values.split(",")]}
    if not out.exists():
        with pytest.raises(impact.NumericalError):
            impact.sweep(str(scene), vary=grid)
    else:
        expected = read_csv(out)
        s = impact.sweep(str(scene), vary=grid)
        assert s["failure"] == expected["failure"] and any(s["failure"])
        for name, texts in expected.items():
            if name != "failure":
                assert same_bits(s[name], as_doubles(texts)), name


# --- values and arguments the module cannot take ---------------------------------------------

@pytest.mark.parametrize("value", [None, {"a": 1}, object(), {1, 2}, b"1e-3"])
def test_a_set_value_it_cannot_take_is_a_value_error_naming_the_key(value):
    with pytest.raises(ValueError, match=r"set\['time.h'\] = .*: a value of type"):
        impact.run(COR075, set={"time.h": value})
    with pytest.raises(ValueError, match=r"vary\['floor.cor'\] = "):
        impact.sweep(COR075, vary={"floor.cor": [0.5, value]})


def test_numpy_scalars_are_the_numbers_they_hold():
    r = impact.run(COR075, set={"time.h": np.float64(0.002), "output.every": np.int64(5)})
    expected = impact.run(COR075, set={"time.h": 0.002, "output.every": 5})
    assert same_bits(r["u"], expected["u"])


@pytest.mark.parametrize("threads", [10**6, 4097, -1, 10**30, 2.5, True, "2"])
def test_threads_out_of_the_clis_range_are_refused(threads):
    with pytest.raises(ValueError, match=r"threads = .*: 1 to 4096 as impact sweep --threads"):
        impact.sweep(COR075, vary={"floor.cor": [0.5]}, threads=threads)
    assert cli("sweep", COR075, "-q", "--vary", "floor.cor=0.5", "--threads", "4097",
               "-o", os.devnull).returncode == 2


def test_threads_at_the_limit_and_by_default_run():
    one = impact.sweep(COR075, vary={"floor.cor": [0.5]}, threads=None)
    assert same_bits(one["u_T"], impact.sweep(COR075, vary={"floor.cor": [0.5]}, threads=0)["u_T"])


def test_a_summary_given_as_one_string_is_read_as_summary_takes_it():
    by_list = impact.sweep(COR075, vary={"floor.cor": [0.5, 0.75]}, summary=["rest_time", "E_T"])
    one = impact.sweep(COR075, vary={"floor.cor": [0.5, 0.75]}, summary="rest_time")
    assert set(one) == {"floor.cor", "rest_time", "failure", "points"}  # not r, e, s, t, ...
    assert same_bits(one["rest_time"], by_list["rest_time"])
    two = impact.sweep(COR075, vary={"floor.cor": [0.5, 0.75]}, summary="rest_time,E_T")
    assert same_bits(two["E_T"], by_list["E_T"])


# --- what help() and the module say of themselves --------------------------------------------

def test_version_is_the_clis():
    done = cli("--version")
    assert done.stdout.split()[1] == impact.__version__


@pytest.mark.parametrize("function", ["run", "events", "exact", "sweep"])
def test_help_shows_the_types_each_function_takes(function):
    doc = getattr(impact, function).__doc__
    assert doc.startswith(f"{function}(scene: str | os.PathLike | dict, ")
    assert "handle" not in doc and "-> dict" in doc and "Raises" in doc
