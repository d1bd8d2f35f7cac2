"""The grains of the polycrystal benchmark: Voronoi seeds by dart throwing (no two seeds closer
than 0.8 of the grain size), each with a random in-plane orientation phi in [0, 180) degrees,
written as a <Material/anisotropic bond based/Grains file> (x y phi per line). The random
generator is seeded, so every run draws the same grains.

usage: make_grains.py GRAIN_SIZE XMIN,YMIN XMAX,YMAX FILE   (lengths in m)
"""
import sys

import numpy as np


def main():
    size = float(sys.argv[1])
    lower = np.array([float(v) for v in sys.argv[2].split(",")])
    upper = np.array([float(v) for v in sys.argv[3].split(",")])
    rng = np.random.default_rng(2014)
    seeds = []
    closest = (0.8 * size) ** 2
    for _ in range(200000):
        p = lower + rng.random(2) * (upper - lower)
        if all(np.sum((p - q) ** 2) > closest for q in seeds):
            seeds.append(p)
    with open(sys.argv[4], "w") as f:
        f.write(f"# {len(seeds)} grains (make_grains.py {' '.join(sys.argv[1:4])}): "
                "seed x, y [m], orientation phi [deg]\n")
        for p in seeds:
            f.write(f"{p[0]:.6e} {p[1]:.6e} {rng.uniform(0., 180.):.3f}\n")
    print(f"{len(seeds)} grains written to {sys.argv[4]}")


if __name__ == "__main__":
    main()
