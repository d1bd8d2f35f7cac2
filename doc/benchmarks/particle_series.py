"""What the postprocessing of the particle time series shares (kalthoff_winkler,
anisotropic_crack_path): the HDF5 files of a run's particles.xdmf in time order, and a file's
datasets in one particle order.
"""
import os
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def read_series(directory, base="particles"):
    """[(time, h5 path)] from the XDMF file, in time order."""
    tree = ET.parse(os.path.join(directory, base + ".xdmf"))
    series = []
    for grid in tree.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        time = float(grid.find("Time").get("Value"))
        item = grid.find("Geometry").find("DataItem").text.strip()
        series.append((time, os.path.join(directory, item.split(":")[0])))
    series.sort()
    return series


def read_particles(path, with_displacement=False, dim=2):
    """(nodes, damage[, displacement or None]) of one particle file, the first dim coordinates
    (2: the plane of a 2D run; 3 for a 3D run), sorted by reference position: the particle order
    depends on the MPI partition, so every file of a run (and runs on different rank counts)
    then share one order."""
    with h5py.File(path, "r") as f:
        nodes = np.array(f["nodes"])[:, :dim]
        damage = np.array(f["damage"])[:, 0]
        disp = np.array(f["displacement"])[:, :dim] if "displacement" in f else None
    order = np.lexsort(tuple(nodes[:, d] for d in reversed(range(dim))))
    if not with_displacement:
        return nodes[order], damage[order]
    return nodes[order], damage[order], (disp[order] if disp is not None else None)
