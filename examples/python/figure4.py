"""Figure 4 of the paper from Python: u against t for f = -9.80665, COR = 0.75 (the right column's
first row), and a work-precision plot, the errors against the exact solution over h for direct
(5-1) and moreau_jean.

    make python && PYTHONPATH=build/python /usr/bin/python3 examples/python/figure4.py [OUT_DIR]

With matplotlib it draws OUT_DIR/figure4_u.png and OUT_DIR/work_precision.png; without it, it
writes the same data as OUT_DIR/figure4_u.csv and OUT_DIR/work_precision.csv (OUT_DIR: results/python).
"""
import os
import sys

import numpy as np

import impact

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "..", "experiments", "figure4", "cor075.toml")
METHODS = ["direct", "moreau_jean"]
STEPS = "1e-4:1e-2:9:log"  # h from 1e-4 to 1e-2, evenly spaced in log10


def work_precision():
    """Per method, the sup error in u and the h-weighted l1 error in v at each h (impact sweep's
    engine, against the exact event-driven solution)."""
    curves = {}
    for method in METHODS:
        s = impact.sweep(SCENE, vary={"time.h": STEPS}, set={"method.name": method},
                         summary=["err_u_sup", "err_v_l1"], against="exact")
        curves[method] = s
    return curves


def write_csv(path, columns):
    names = list(columns)
    np.savetxt(path, np.column_stack([columns[n] for n in names]), delimiter=",",
               header=",".join(names), comments="", fmt="%.17g")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join("results", "python")
    os.makedirs(out, exist_ok=True)
    run = impact.run(SCENE)
    curves = work_precision()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        write_csv(os.path.join(out, "figure4_u.csv"), {"t": run["t"], "u": run["u"]})
        columns = {"h": curves[METHODS[0]]["time.h"]}
        for method in METHODS:
            columns[method + "_err_u_sup"] = curves[method]["err_u_sup"]
            columns[method + "_err_v_l1"] = curves[method]["err_v_l1"]
        write_csv(os.path.join(out, "work_precision.csv"), columns)
        print(f"matplotlib not installed: wrote {out}/figure4_u.csv and {out}/work_precision.csv")
        return
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(run["t"], run["u"], lw=0.8)
    ax.set(xlabel="t [s]", ylabel="u [m]", title="Figure 4: f = -9.80665, COR = 0.75, h = 1e-3")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "figure4_u.png"), dpi=150)
    fig, ax = plt.subplots(figsize=(5, 4))
    for method in METHODS:
        c = curves[method]
        ax.loglog(c["time.h"], c["err_u_sup"], "o-", label=f"{method}: sup |u - u_exact|")
        ax.loglog(c["time.h"], c["err_v_l1"], "s--", label=f"{method}: h sum |v - v_exact|")
    ax.set(xlabel="h [s]", ylabel="error", title="against the exact solution")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "work_precision.png"), dpi=150)
    print(f"wrote {out}/figure4_u.png and {out}/work_precision.png")


if __name__ == "__main__":
    main()
