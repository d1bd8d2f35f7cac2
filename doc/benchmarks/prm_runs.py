"""What the heat benchmarks' study scripts share: run perideal-solid on a parameter template.

solver(argv): the perideal-solid of argv[1], else build/bin/perideal-solid of the repository.
run(solver, path, fields, edits): the parameter file path with the entries marked # @KEY@ set to
fields[KEY] (contrib/prm_fill.py) and each (pattern, replacement) of edits applied (re.sub), run
in a temporary directory; returns the log (stdout) and the rows of results/statistics.csv
(dicts; empty without the file).
finish(fig, ax, path, xlabel, ylabel, title): label the axes, title and legend a plot, save it.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "contrib"))
from prm_fill import fill_text  # noqa: E402
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def solver(argv):
    return argv[1] if len(argv) > 1 else os.path.join(ROOT, "build", "bin", "perideal-solid")


def run(executable, path, fields, edits=()):
    text = fill_text(open(path).read(), fields, path)
    for pattern, replacement in edits:
        text = re.sub(pattern, replacement, text)
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "p.prm"), "w") as f:
            f.write(text)
        log = subprocess.run([executable, "p.prm"], cwd=work, env=ENV, capture_output=True,
                             text=True, check=True).stdout
        statistics = os.path.join(work, "results", "statistics.csv")
        rows = []
        if os.path.exists(statistics):
            with open(statistics) as f:
                rows = list(csv.DictReader(f))
    return log, rows


def finish(fig, ax, path, xlabel, ylabel, title):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
