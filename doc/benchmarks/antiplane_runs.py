"""What the postprocessing of the antiplane benchmarks (antiplane_bimaterial, antiplane_square_bar)
shares: reading a run's last field output and naming its model.

A PD run is a results directory named <model>_dx<dx> (model bb: bond-based; sb: state-based;
sbs<alpha>: state-based with that stabilization), an FE run fe_l<level>.
"""
import glob
import re

import h5py
import numpy as np

LABELS = {"bb": "PD bond-based", "sb": "PD state-based", "fe": "FE Q1"}


def label(model):
    """The legend of a model's short name."""
    if model.startswith("sbs"):
        return f"PD state-based, stabilization {model[3:]}"
    return LABELS[model]


def read_run(run, coarse_size):
    """(model, dx or h, nodes, w) of the results directory run: the last particle output
    (particles_*.h5) of a PD run, the last FE output (solution_*.h5) of an FE run, whose cell
    size is coarse_size / 2^level."""
    name = run.rstrip("/").split("/")[-1]
    if name.startswith("fe_"):
        level = int(re.search(r"fe_l(\d+)", name).group(1))
        model, size, prefix = "fe", coarse_size / 2**level, "solution"
    else:
        model, size = re.match(r"([\w.]+?)_dx([0-9.]+)", name).groups()
        size, prefix = float(size), "particles"
    files = sorted(glob.glob(f"{run}/{prefix}_*.h5"))
    if not files:
        raise SystemExit(f"no {prefix}_*.h5 in {run}")
    with h5py.File(files[-1], "r") as h5:
        nodes = np.asarray(h5["nodes"][:, :2], float)
        w = np.asarray(h5["w"][:, 0], float)
    return model, size, nodes, w


def convergence_plot(runs, curves, xlabel, ylabel, title, output):
    """Draw into output, for each model of runs ({model: [(size, values...), ...]}), the absolute
    values of each curve of curves [(column, line style, legend suffix)] against the size, on
    log-log axes."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for model, values in runs.items():
        values = sorted(values, key=lambda v: v[0])
        size = [v[0] for v in values]
        for column, style, suffix in curves:
            ax.loglog(size, [abs(v[column]) for v in values], style, label=f"{label(model)}: {suffix}")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    print(f"wrote {output}")
