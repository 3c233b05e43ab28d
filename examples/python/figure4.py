"""Figure 4 of the paper from Python: u, v, N and E against t under gravity (f = -9.80665), without
a coefficient of restitution (left column) and with COR = 0.75 (right), the paper's scheme (5-1) at
h = 1e-3 with the exact solution overlaid; and a work-precision plot, the errors against the exact
solution over h for direct (5-1) and moreau_jean.

    python3 examples/python/figure4.py [OUT_DIR]        # the module installed (docs/python.md)
    PYTHONPATH=build/python python3 examples/python/figure4.py [OUT_DIR]   # after make python

With matplotlib (Debian's python3-matplotlib) it draws OUT_DIR/figure4.png and
OUT_DIR/work_precision.png; without it, it writes the same data as OUT_DIR/figure4.csv and
OUT_DIR/work_precision.csv (OUT_DIR: results/python).
"""
import os
import sys

import numpy as np

import impact

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = {name: os.path.join(HERE, "..", "..", "experiments", "figure4", name + ".toml")
          for name in ("no_cor", "cor075")}
TITLES = {"no_cor": "without COR", "cor075": "COR = 0.75"}
CHANNELS = {"u": "u [m]", "v": "v [m/s]", "N": "N [m/s^2]", "E": "E [J/kg]"}
METHODS = ["direct", "moreau_jean"]
STEPS = "1e-4:1e-2:9:log"  # h from 1e-4 to 1e-2, evenly spaced in log10


def figure4():
    """Per scene, the run of direct (every channel) and the exact solution at the same times."""
    runs = {}
    for name, scene in SCENES.items():
        run = impact.run(scene)
        runs[name] = (run, impact.exact(scene, run["t"]))
    return runs


def work_precision():
    """Per method, the sup error in u and the h-weighted l1 error in v at each h (impact sweep's
    engine, against the exact event-driven solution)."""
    return {method: impact.sweep(SCENES["cor075"], vary={"time.h": STEPS},
                                 set={"method.name": method},
                                 summary=["err_u_sup", "err_v_l1"], against="exact")
            for method in METHODS}


def write_csv(path, columns):
    names = list(columns)
    np.savetxt(path, np.column_stack([columns[n] for n in names]), delimiter=",",
               header=",".join(names), comments="", fmt="%.17g")


def write_data(out, runs, curves):
    columns = {"t": runs["no_cor"][0]["t"]}
    for name, (run, _) in runs.items():
        for channel in CHANNELS:
            columns[f"{name}_{channel}"] = run[channel]
    write_csv(os.path.join(out, "figure4.csv"), columns)
    columns = {"h": curves[METHODS[0]]["time.h"]}
    for method in METHODS:
        columns[method + "_err_u_sup"] = curves[method]["err_u_sup"]
        columns[method + "_err_v_l1"] = curves[method]["err_v_l1"]
    write_csv(os.path.join(out, "work_precision.csv"), columns)
    print(f"matplotlib not installed: wrote {out}/figure4.csv and {out}/work_precision.csv")


def draw(plt, out, runs, curves):
    fig, axes = plt.subplots(len(CHANNELS), 2, figsize=(10, 9), sharex=True)
    for column, (name, (run, exact)) in enumerate(runs.items()):
        for row, (channel, label) in enumerate(CHANNELS.items()):
            ax = axes[row, column]
            ax.plot(run["t"], run[channel], lw=0.8, label="direct (5-1), h = 1e-3")
            if channel in exact:  # the exact solution's N is a sum of impulses: not drawn
                ax.plot(exact["t"], exact[channel], "k--", lw=0.6, label="exact")
            ax.set_ylabel(label)
            ax.grid(alpha=0.3)
        axes[0, column].set_title(f"Figure 4, f = -9.80665, {TITLES[name]}")
        axes[-1, column].set_xlabel("t [s]")
    axes[0, 1].legend(loc="upper right", fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "figure4.png"), dpi=120)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for method in METHODS:
        c = curves[method]
        ax.loglog(c["time.h"], c["err_u_sup"], "o-", label=f"{method}: sup |u - u_exact| [m]")
        ax.loglog(c["time.h"], c["err_v_l1"], "s--", label=f"{method}: h sum |v - v_exact| [m]")
    ax.set(xlabel="h [s]", ylabel="error", title="Figure 4 with COR = 0.75: error against h")
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "work_precision.png"), dpi=120)
    print(f"wrote {out}/figure4.png and {out}/work_precision.png")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join("results", "python")
    os.makedirs(out, exist_ok=True)
    runs, curves = figure4(), work_precision()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        write_data(out, runs, curves)
        return
    draw(plt, out, runs, curves)


if __name__ == "__main__":
    main()
