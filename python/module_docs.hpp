// The docstrings of the module `impact`: each function's first line is its signature with the
// types it takes (pybind11's own would say `scene: handle`), then what it returns and raises.
#pragma once

namespace impact::python {

inline constexpr const char* kModuleDoc =
    "impact: a particle falling onto a rigid floor (Ahn and Wolf, Dynamic impact of a particle, "
    "2013).\n\n"
    "A scene is a TOML file (str or os.PathLike), a TOML text (a str with a newline) or a dict of "
    "tables ({'time': {'T': 1.0, 'h': 1e-3}, ...}), read and checked as `impact run` reads it. "
    "set: {'table.key': value} or ['table.key=value', ...], applied as `--set` is; a value is a "
    "bool, int, float, str or a list of them (a NumPy scalar as the number it holds).\n\n"
    "Exceptions: SceneError (a ValueError) for a bad scene or argument, with the reader's "
    "message; NumericalError (an ArithmeticError) when a run fails (a value not finite, a solve "
    "that does not converge: where `impact run` exits 1); KeyboardInterrupt on Ctrl-C, within "
    "about 0.1 s, with nothing returned. The GIL is released while a scene is read and run.";

inline constexpr const char* kRunDoc =
    "run(scene: str | os.PathLike | dict, *, set: dict[str, object] | list[str] | None = None, "
    "method: str | None = None, every: int | None = None, against: str | None = None) -> dict\n\n"
    "Runs a scene as `impact run` does.\n\n"
    "method: sets method.name; every: output.every; against: 'exact' to measure the run against "
    "the reference solution, or None.\n\n"
    "Returns a dict:\n"
    "  't': numpy.ndarray[float64], the row times t_l = l h;\n"
    "  one array per output channel, named as the CSV header names it: 'u', 'v', 'N', 'E' "
    "(float64), 'iterations' (int64) and each internal variable under its name in the scene "
    "(float64); the same doubles as the CSV rows, bit for bit;\n"
    "  'method': str;\n"
    "  'summary': dict, with the names of impact run's OUT.json: steps, contact_steps, "
    "iterations, max_iterations_per_step (int), wall_s (float); NAME_T (float), each internal "
    "variable at the last grid time; with against='exact' err_u_sup, err_v_l1, err_E_T, "
    "err_first_impact, reference_s and, with internal variables (or [bonding]'s beta and D), "
    "err_internal_sup (the largest |z_i - z_i,exact| over the steps).\n\n"
    "Raises SceneError, NumericalError, KeyboardInterrupt (see the module's help).";

inline constexpr const char* kEventsDoc =
    "events(scene: str | os.PathLike | dict, *, set: dict[str, object] | list[str] | None = "
    "None, method: str | None = None) -> dict\n\n"
    "The impacts, sticks and lifts of a run (and a bonded run's debond, capture and escape), as "
    "`impact run --events` writes them. Returns a dict of numpy.ndarray: 't' (float64), 'kind' "
    "(str: 'impact', 'stick', 'lift', 'debond', 'capture' or 'escape'), 'v_before', 'v_after' "
    "(float64) and each internal variable at the event under its name (float64; a bonded run's "
    "'beta' and 'D').\n\n"
    "Raises SceneError, NumericalError, KeyboardInterrupt (see the module's help).";

inline constexpr const char* kExactDoc =
    "exact(scene: str | os.PathLike | dict, t: numpy.typing.ArrayLike, *, set: dict[str, "
    "object] | list[str] | None = None) -> dict\n\n"
    "The reference solution of the scene's problem (that of against='exact') at the times t, "
    "finite, in any order. Returns a dict of float64 numpy.ndarray: 't', 'u', 'v' and each "
    "internal variable under its name (its initial value at t <= 0).\n\n"
    "Raises SceneError, ValueError (a time not finite), NumericalError, KeyboardInterrupt.";

inline constexpr const char* kSweepDoc =
    "sweep(scene: str | os.PathLike | dict, *, vary: dict[str, str | Sequence[float]], summary: "
    "str | Sequence[str] | None = None, set: dict[str, object] | list[str] | None = None, "
    "against: str | None = None, threads: int | None = None) -> dict\n\n"
    "`impact sweep` by its own engine.\n\n"
    "vary: {'table.key': 'a:b:n' | 'a:b:n:log' | 'v1,v2,...' | a sequence of numbers}, the last "
    "key varying fastest; summary: the quantities, a list of names or one str as --summary takes "
    "it ('rest_time' or 'rest_time,E_T'); None: the default of impact sweep; against: 'exact' "
    "adds the errors err_*; threads: 1 to 4096 as --threads, None or 0 for one per core.\n\n"
    "Returns a dict: the varied keys and the quantities as float64 numpy.ndarray (NaN where a "
    "point failed), 'failure' (list of str, empty where the point did not fail) and 'points' "
    "(int).\n\n"
    "Raises SceneError (also for threads out of range), NumericalError, KeyboardInterrupt.";

}  // namespace impact::python
