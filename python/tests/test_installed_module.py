"""The module as `cmake --install` puts it: in the prefix's Python site directory, where the
interpreter looks for that prefix, importable without the build tree; and its example, which draws
Figure 4 with matplotlib (and writes CSV without it).

Run by ctest (python_module): IMPACT_BUILD_DIR is the build to install from,
IMPACT_PYTHON_INSTALL_DIR where it puts the module (relative to the prefix).
"""
import os
import site
import subprocess
import sys

import pytest

import impact

SOURCE = os.environ.get("IMPACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("IMPACT_BUILD_DIR", os.path.join(SOURCE, "build"))
SITE = os.environ.get("IMPACT_PYTHON_INSTALL_DIR")
CLI = os.environ.get("IMPACT_CLI", os.path.join(BUILD, "impact"))
EXAMPLE = os.path.abspath(os.path.join(SOURCE, "examples", "python", "figure4.py"))
PNG = b"\x89PNG\r\n\x1a\n"


def python(args, env_extra, cwd):
    """sys.executable with only env_extra's PYTHONPATH: nothing of this test run's own path."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(env_extra)
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, env=env,
                          cwd=cwd, check=False)


@pytest.mark.skipif(SITE is None, reason="run by ctest, which names the install directory")
def test_the_installed_module_imports_from_the_prefix_site_directory(tmp_path):
    prefix = tmp_path / "prefix"
    done = subprocess.run(["cmake", "--install", BUILD, "--prefix", str(prefix), "--component",
                           "python"], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    site_dir = prefix / SITE
    # Where the interpreter itself looks for a prefix's modules (Debian: dist-packages).
    assert str(site_dir) in site.getsitepackages([str(prefix)])
    assert [p.name for p in site_dir.iterdir() if p.name.startswith("impact")]
    done = python(["-c", "import impact; print(impact.__version__); print(impact.__file__)"],
                  {"PYTHONPATH": str(site_dir)}, tmp_path)
    assert done.returncode == 0, done.stderr
    version, path = done.stdout.split()
    assert path.startswith(str(site_dir))
    assert version == impact.__version__
    assert subprocess.run([CLI, "--version"], capture_output=True, text=True).stdout.split()[1] \
        == version


@pytest.mark.skipif(SITE is None, reason="run by ctest, which names the install directory")
def test_the_default_prefix_site_directory_is_on_the_interpreters_path(tmp_path):
    # cmake's default prefix is /usr/local: there the module needs no PYTHONPATH at all.
    done = python(["-c", "import sys; print('\\n'.join(sys.path))"], {}, tmp_path)
    assert os.path.join("/usr/local", SITE) in done.stdout.split("\n")


def module_path():
    return os.path.dirname(impact.__file__)


def test_the_figure4_example_draws_pngs_with_matplotlib(tmp_path):
    # Not skipped where it is missing: .ci/deps.sh installs python3-matplotlib for this test.
    done = python(["-c", "import matplotlib"], {}, tmp_path)
    assert done.returncode == 0, "python3-matplotlib is not installed: " + done.stderr
    done = python([EXAMPLE, str(tmp_path)], {"PYTHONPATH": module_path(), "MPLBACKEND": "Agg"},
                  tmp_path)
    assert done.returncode == 0, done.stderr
    for name in ("figure4.png", "work_precision.png"):
        with open(tmp_path / name, "rb") as f:
            assert f.read(8) == PNG, name
    assert not list(tmp_path.glob("*.csv"))


def test_the_figure4_example_writes_csv_without_matplotlib(tmp_path):
    # matplotlib hidden: `import matplotlib` raises ImportError, as where it is not installed.
    code = ("import runpy, sys; sys.modules['matplotlib'] = None; sys.argv = sys.argv[1:]; "
            "runpy.run_path(sys.argv[0], run_name='__main__')")
    done = python(["-c", code, EXAMPLE, str(tmp_path)], {"PYTHONPATH": module_path()}, tmp_path)
    assert done.returncode == 0, done.stderr
    header = (tmp_path / "figure4.csv").read_text().split("\n")[0]
    assert header == "t," + ",".join(f"{s}_{c}" for s in ("no_cor", "cor075")
                                     for c in ("u", "v", "N", "E"))
    assert (tmp_path / "work_precision.csv").read_text().startswith("h,direct_err_u_sup,")
    assert not list(tmp_path.glob("*.png"))
