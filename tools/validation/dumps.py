"""Reading LAMMPS text dumps (wiggle's dumps/dump.lammpstrj and an exported deck's dump.lammpstrj have
the same format, docs/OUTPUT-FORMATS.md) and the contact analysis the validation scripts share."""
import numpy as np
from scipy.spatial import cKDTree

GRAIN, BASE, INTRUDER = 1, 2, 3  # dump atom types


def read_dump(path):
    """Frames of a LAMMPS text dump: (step, width, array of id type x y radius)."""
    frames = []
    with open(path) as f:
        while True:
            line = f.readline()
            if not line:
                return frames
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(f.readline())
            f.readline()
            n = int(f.readline())
            f.readline()
            xlo, xhi = map(float, f.readline().split()[:2])
            f.readline()
            f.readline()
            columns = f.readline().split()[2:]
            rows = np.array([f.readline().split() for _ in range(n)], dtype=float)
            pick = [columns.index(c) for c in ("id", "type", "x", "y", "radius")]
            frames.append((step, xhi - xlo, xlo, rows[:, pick]))


def pair_overlaps(width, xlo, atoms):
    """Every pair within reach, base-base and intruder-intruder excluded: (i, j, overlap [d]),
    overlap = ri + rj - distance (positive when they touch), x periodic over the box width."""
    kind = atoms[:, 1].astype(int)
    x = np.mod(atoms[:, 2] - xlo, width)
    y = atoms[:, 3] - atoms[:, 3].min()
    r = atoms[:, 4]
    tree = cKDTree(np.column_stack([x, y]), boxsize=[width, 1e9])
    pairs = tree.query_pairs(2.0 * r.max(), output_type="ndarray")
    i, j = pairs[:, 0], pairs[:, 1]
    keep = ~((kind[i] == kind[j]) & (kind[i] != GRAIN))
    i, j = i[keep], j[keep]
    dx = x[i] - x[j]
    dx -= width * np.round(dx / width)
    return i, j, r[i] + r[j] - np.hypot(dx, y[i] - y[j])


def contacts(width, xlo, atoms):
    """Largest overlap [d] and number of touching pairs."""
    _, _, overlap = pair_overlaps(width, xlo, atoms)
    return (overlap.max() if overlap.size else 0.0), int((overlap > 0).sum())
