"""Small synthetic run, sweep and geometry files in wiggle's output formats, with known numbers so
that the tests can check the data behind each figure. `python3 -m tests.synthetic OUT` writes them
for a look at the figures by eye."""
import csv
import json
import math
import os
import sys

import numpy as np

# Run: y(t) = 25 + SLOPE t + WIGGLE sin(2 pi t / 5); the sine vanishes at t_i = 10 and t_f = 100,
# so the paper's rate over [10, 100] is exactly SLOPE.
SLOPE = 0.02
WIGGLE = 0.05
PERIOD = 5.0
AMPLITUDE = 3.0
DT = 0.01
DUMP_TIMES = (0.0, 50.0, 100.0)
T_RISE = 2.82
MODEL_CURVE = [[2.82, 0.0], [4.0, 0.1], [6.0, 0.2], [8.0, 0.15]]
EMPTY_BIN = 7
FIELD_PHASES = (0.0, 5.0, 10.0)
FIELD_HALF = 16.0   # the grid reaches beyond r = 15 on purpose: those corners must be masked
DISK_RADIUS = 3.5   # outer radius of the synthetic intruder [d]
ATOM_R = 0.25


def traj_xy(t):
    t = np.asarray(t, dtype=float)
    return 30.0 + AMPLITUDE * np.sin(2 * np.pi * t / PERIOD), 25.0 + SLOPE * t + WIGGLE * np.sin(2 * np.pi * t / PERIOD)


def phase_rate(center):
    return 0.1 * np.sin(np.pi * center / 10.0)


def field_values(phase, x, y):
    """The known pattern: phi falls with phase and grows with x; pressure grows with depth."""
    phi = 0.8 - 0.01 * phase + 0.001 * x
    vx = 0.1 * np.ones_like(x) + 0.01 * phase
    vy = 0.05 * np.ones_like(x)
    sxx = -(10.0 - 0.5 * y)
    syy = -(10.0 - 0.5 * y)
    return phi, vx, vy, sxx, 0.0 * x, syy


def disk_atoms():
    """A ring of atoms whose outer edge is a circle of DISK_RADIUS, plus a filled centre."""
    ring = DISK_RADIUS - ATOM_R
    n = int(2 * np.pi * ring / (1.5 * ATOM_R))
    a = 2 * np.pi * np.arange(n) / n
    pts = [np.column_stack([ring * np.cos(a), ring * np.sin(a)])]
    g = np.arange(-2.5, 2.51, 0.5)
    gx, gy = np.meshgrid(g, g)
    inside = np.hypot(gx, gy) <= ring - 0.4
    pts.append(np.column_stack([gx[inside], gy[inside]]))
    return np.vstack(pts)


def write_run(run_dir, with_fields=True, with_dump=True, with_model=True):
    os.makedirs(run_dir, exist_ok=True)
    with open(os.path.join(run_dir, "config.toml"), "w") as f:
        f.write("[box]\nwidth = 60.0\nbed_height = 50.0\nseed = 1\n\n"
                "[intruder]\nshape = \"disk\"\ny0 = 25.0\n\n"
                f"[drive]\namplitude = {AMPLITUDE}\nperiod = {PERIOD}\n\n"
                "[contact]\nmu = 0.1\n\n"
                f"[run]\ndt = {DT}\nduration = 100.0\n\n[fields]\nradius = 15.0\nspacing = 1.0\n")
    t = np.arange(0.0, 100.0 + 1e-9, 0.25)
    x, y = traj_xy(t)
    vx = np.gradient(x, t)
    vy = np.gradient(y, t)
    with open(os.path.join(run_dir, "trajectory.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t", "x", "y", "vx", "vy", "fy"])
        for row in zip(t, x, y, vx, vy, np.full_like(t, 25.7)):
            w.writerow([f"{v:.10g}" for v in row])
    ti, tf = 10.0, 100.0
    yi, yf = float(traj_xy(ti)[1]), float(traj_xy(tf)[1])
    summary = {"vy": (yf - yi) / (tf - ti), "vy_slope": SLOPE * 1.01, "t_i": ti, "t_f": tf,
               "y_initial": yi, "y_final": yf, "status": "ok", "n_grains": 100, "steps": 10000,
               "threads": 1, "wall_s": 1.5, "ns_per_particle_step": 50.0, "state_hash": "abc",
               "shape": "disk", "amplitude": AMPLITUDE, "period": PERIOD, "mu": 0.1}
    with open(os.path.join(run_dir, "summary.json"), "w") as f:
        json.dump(summary, f)
    with open(os.path.join(run_dir, "phase_rates.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["bin", "phase_center", "vy_mean", "samples"])
        for b in range(20):
            c = b + 0.5
            if b == EMPTY_BIN:
                w.writerow([b, c, "", 0])
            else:
                w.writerow([b, c, f"{phase_rate(c):.10g}", 40])
    if with_model:
        with open(os.path.join(run_dir, "model.json"), "w") as f:
            json.dump({"shape": "disk", "l": 3.5, "l_prime": 4.0, "T_rise": T_RISE, "h": 7.0,
                       "T_max": 7.48, "curve": MODEL_CURVE}, f)
    if with_fields:
        g = np.arange(-FIELD_HALF, FIELD_HALF + 1e-9, 1.0)
        gx, gy = np.meshgrid(g, g)
        with open(os.path.join(run_dir, "fields.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["phase", "x", "y", "phi", "vx", "vy", "sxx", "sxy", "syy", "pressure", "frames"])
            for p in FIELD_PHASES:
                phi, fvx, fvy, sxx, sxy, syy = field_values(p, gx.ravel(), gy.ravel())
                pressure = -(sxx + syy) / 2
                for k in range(gx.size):
                    w.writerow([f"{p:g}", f"{gx.ravel()[k]:g}", f"{gy.ravel()[k]:g}", f"{phi[k]:.6g}",
                                f"{fvx[k]:.6g}", f"{fvy[k]:.6g}", f"{sxx[k]:.6g}", f"{sxy[k]:.6g}",
                                f"{syy[k]:.6g}", f"{pressure[k]:.6g}", 50])
    if with_dump:
        write_dump(os.path.join(run_dir, "dumps", "dump.lammpstrj"))
    return summary


def dump_frame_atoms(t):
    """(ids, types, x, y, r) of a small system at time t: a base row, a bed of grains on a
    lattice (ids shuffled in the file) and the intruder's atoms around its trajectory centre."""
    width, height = 60, 30
    rng = np.random.default_rng(7)
    bx = np.arange(0.5, width, 1.0)
    by = np.zeros_like(bx)
    gx, gy = np.meshgrid(np.arange(0.5, width, 1.0), np.arange(1.0, height, 1.0))
    gx, gy = gx.ravel(), gy.ravel()
    cx, cy = traj_xy(t)
    atoms = disk_atoms() + [float(cx), float(cy)]
    keep = np.hypot(gx - cx, gy - cy) > DISK_RADIUS + 0.6
    gx, gy = gx[keep], gy[keep]
    # Make the frames differ: grains sink slowly, so a count change is avoided by keeping all.
    gy = gy + 0.002 * t
    x = np.concatenate([bx, gx, atoms[:, 0]])
    y = np.concatenate([by, gy, atoms[:, 1]])
    types = np.concatenate([np.full(len(bx), 2), np.full(len(gx), 1), np.full(len(atoms), 3)])
    r = np.concatenate([np.full(len(bx), 0.5), rng.uniform(0.45, 0.55, len(gx)), np.full(len(atoms), ATOM_R)])
    ids = np.arange(1, len(x) + 1)
    return ids, types, x, y, r


def write_dump(path, times=DUMP_TIMES):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        for t in times:
            ids, types, x, y, r = dump_frame_atoms(t)
            order = np.random.default_rng(int(t) + 1).permutation(len(ids))
            f.write(f"ITEM: TIMESTEP\n{int(round(t / DT))}\nITEM: NUMBER OF ATOMS\n{len(ids)}\n")
            f.write("ITEM: BOX BOUNDS pp ff pp\n0 60\n-0.5 40\n-0.5 0.5\n")
            f.write("ITEM: ATOMS id type x y z radius vx vy\n")
            for k in order:
                f.write(f"{ids[k]} {types[k]} {x[k]:.6f} {y[k]:.6f} 0 {r[k]:.4f} 0 0\n")


# Sweep: V_y of a point = BASE[shape][A][i_T] + the seed's offset (+-SEED_OFFSET), so the seed
# mean is BASE and the sample standard deviation is SEED_OFFSET * sqrt(2).
SWEEP_PERIODS = (1.0, 2.0, 4.0, 8.0)
SWEEP_AMPS = (3.0, 5.0)
SEED_OFFSET = 0.005
BASE = {
    "disk": {3.0: [-0.03, -0.02, 0.01, 0.02], 5.0: [-0.02, -0.01, 0.03, 0.05]},
    "triangle": {3.0: [-0.05, -0.04, -0.03, -0.02], 5.0: [-0.04, -0.03, -0.02, -0.01]},
}
# disk at A = 5 turns positive between T = 2 (-0.01) and T = 4 (0.03): 2 + 2 * 0.01 / 0.04 = 2.5
DISK_T_RISING = 2.5
FAILED_CASE = "case_failed"


def write_sweep(sweep_dir, with_runs=True, mus=(0.1,)):
    os.makedirs(sweep_dir, exist_ok=True)
    rows = []
    k = 0
    for mu in mus:
        for shape, amps in BASE.items():
            for a in SWEEP_AMPS:
                for j, T in enumerate(SWEEP_PERIODS):
                    for seed, off in ((1, SEED_OFFSET), (2, -SEED_OFFSET)):
                        k += 1
                        case = f"case_{k:03d}"
                        run_dir = f"runs/{case}"
                        vy = amps[a][j] + off + (mu - mus[0])
                        rows.append([case, run_dir, "ok", f"{vy:.10g}", f"{vy:.10g}", "1.0",
                                     shape, a, T, mu, seed])
                        if with_runs and shape == "disk" and mu == mus[0]:
                            write_sweep_run(os.path.join(sweep_dir, run_dir), a, T, vy)
                        # What makes a case finished (readers.case_finished): its summary says ok.
                        write_case_summary(os.path.join(sweep_dir, run_dir), vy)
    rows.append([FAILED_CASE, "runs/case_failed", "failed", "", "", "0.5", "disk", 5.0, 4.0, mus[0], 3])
    with open(os.path.join(sweep_dir, "results.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "run_dir", "status", "vy", "vy_slope", "wall_s", "intruder.shape",
                    "drive.amplitude", "drive.period", "contact.mu", "box.seed"])
        w.writerows(rows)
    return rows


def write_case_summary(run_dir, vy, warnings=()):
    os.makedirs(run_dir, exist_ok=True)
    with open(os.path.join(run_dir, "summary.json"), "w") as f:
        json.dump({"status": "ok", "vy": vy, "vy_slope": vy, "warnings": list(warnings)}, f)


def write_sweep_run(run_dir, a, T, vy):
    os.makedirs(run_dir, exist_ok=True)
    t = np.arange(0.0, 50.0 + 1e-9, 0.5)
    with open(os.path.join(run_dir, "trajectory.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t", "x", "y", "vx", "vy", "fy"])
        for ti in t:
            w.writerow([ti, 30 + a * math.sin(2 * math.pi * ti / T), 25 + vy * ti, 0, vy, 0])
    with open(os.path.join(run_dir, "phase_rates.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["bin", "phase_center", "vy_mean", "samples"])
        for b in range(20):
            w.writerow([b, b + 0.5, vy + 0.01 * math.sin(math.pi * (b + 0.5) / 10), 10])
    with open(os.path.join(run_dir, "model.json"), "w") as f:
        json.dump({"shape": "disk", "l": 3.5, "l_prime": 4.0, "T_rise": T_RISE, "h": 7.0,
                   "T_max": 7.48, "amplitude": a, "curve": MODEL_CURVE}, f)


def write_geometries(out_dir):
    """Two geometry files: a disk (outline polygon, atoms) and an apex-up triangle."""
    os.makedirs(out_dir, exist_ok=True)
    a = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    disk = {"shape": "disk", "outline": np.column_stack([3.5 * np.cos(a), 3.5 * np.sin(a)]).tolist(),
            "atoms": disk_atoms().tolist(), "atom_radius": ATOM_R, "y0": 3.5, "y_nr_left": 0.0,
            "y_nr_right": 0.0, "l_left": 3.5, "l_right": 3.5, "h": 7.0, "T_rise_left": 2.83,
            "T_rise_right": 2.83, "T_max": 7.48}
    s = 9.5
    hgt = s * math.sqrt(3) / 2
    tri = [[-s / 2, -hgt / 3], [s / 2, -hgt / 3], [0.0, 2 * hgt / 3]]
    atoms = []
    for (x0, y0), (x1, y1) in zip(tri, tri[1:] + tri[:1]):
        for u in np.linspace(0, 1, 20, endpoint=False):
            atoms.append([x0 + u * (x1 - x0), y0 + u * (y1 - y0)])
    triangle = {"shape": "triangle", "outline": tri, "atoms": atoms, "atom_radius": ATOM_R,
                "y0": 2 * hgt / 3, "y_nr_left": -hgt / 3, "y_nr_right": -hgt / 3,
                "l_left": hgt, "l_right": hgt, "h": hgt, "T_rise_left": 4.17, "T_rise_right": 4.17,
                "T_max": 8.1}
    paths = []
    for g in (disk, triangle):
        p = os.path.join(out_dir, f"{g['shape']}.json")
        with open(p, "w") as f:
            json.dump(g, f)
        paths.append(p)
    return paths


if __name__ == "__main__":
    out = sys.argv[1]
    write_run(os.path.join(out, "run"))
    write_sweep(os.path.join(out, "sweep"))
    write_sweep(os.path.join(out, "sweep_mu"), with_runs=False, mus=(0.0, 0.1, 0.3))
    write_geometries(os.path.join(out, "geometry"))
