#!/usr/bin/python3
"""Runs Debian's LAMMPS on the small reference cases of tests/physics/LammpsComparisonTest.cpp and
stores the result as tests/data/lammps/<case>.json (see README.md in this folder).

Each case is written as a LAMMPS data file and deck (decks/<case>.data, decks/<case>.in, kept in the
repository so that anyone can rerun them by hand), run with `lmp`, and its dumps are parsed into one
JSON file holding: the case description the C++ test builds the wiggle World from (box, dt, contact
parameters, particles in LAMMPS id order, clump), the LAMMPS version, the exact deck and data file,
and per dumped step the per-atom state (x y vx vy omegaz fx fy tqz) and the per-contact output of
`compute pair/local` (the pair style's single(): `force` = r * ccel, the normal force, and the
shear force fs1 fs2 fs on the first atom, evaluated from the stored shear history with the
current velocities; for pairs across the periodic boundary the second atom is a ghost whose
velocity is still the half-step one).

All numbers are written with 17 significant digits by LAMMPS and stored in JSON with Python's
shortest round-trip repr, so the C++ side reads exactly the doubles LAMMPS printed.

Usage: /usr/bin/python3 tools/lammps_reference/make_reference.py [case ...]   (default: all)
"""
import json
import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DECKS = os.path.join(HERE, "decks")
OUT = os.path.join(ROOT, "tests", "data", "lammps")

DT = 1e-4
GRAVITY = 1.0
DENSITY = 1.0
KN, KT, GAMMA_N, GAMMA_T = 2e6, 2.46e6, 2500.0, 2500.0
GRAIN, BASE, CLUMP = 1, 2, 3  # LAMMPS atom types


def lammps_version():
    out = subprocess.run(["lmp", "-h"], capture_output=True, text=True).stdout
    for line in out.splitlines():
        if "Large-scale" in line:
            return line.strip()
    raise RuntimeError("cannot read the LAMMPS version from lmp -h")


def base_row(width):
    """Frozen base: diameter-1 atoms centred at y = 0, spaced 1 over the periodic width."""
    return [dict(type=BASE, x=float(i), y=0.0, r=0.5, vx=0.0, vy=0.0, omega=0.0) for i in range(width)]


# --------------------------------------------------------------------------------------------
# The cases. Each returns (particles in LAMMPS id order, settings).


def case_oblique():
    # Two grains meet off-centre (centre offset 0.2 across the line of approach, a 0.01 gap at the
    # start) while grain 1 spins (omega = 4, surface speed 2). With mu = 0.5 the contact slides at
    # first (the tangential damping force alone exceeds the cap), sticks while the tangential force
    # turns around (the spring stores the shear), and slides again in the other direction when the
    # normal force fades during restitution: slide, stick, slide. The test checks from wiggle's
    # per-pair forces that both regimes occur (README.md: how the offset and spin were chosen).
    dy = 0.2
    p = [dict(type=GRAIN, x=5.5 - math.sqrt(1.06 ** 2 - dy * dy), y=3.0, r=0.5, vx=1.0, vy=0.1,
              omega=4.0),
         dict(type=GRAIN, x=5.5, y=3.0 + dy, r=0.55, vx=-1.0, vy=0.0, omega=0.0)]
    return p, dict(width=10, ylo=-5.0, yhi=5.0, mu=0.5, steps=200, every=1, every_local=1,
                   description="oblique two-grain collision with spin, mu 0.5: sliding, sticking, sliding")


def case_bounce():
    p = [dict(type=GRAIN, x=2.45, y=0.95, r=0.5, vx=0.05, vy=0.0, omega=0.0)] + base_row(6)
    return p, dict(width=6, ylo=-1.0, yhi=10.0, mu=0.1, steps=40000, every=40, every_local=40,
                   description="grain falls, bounces and comes to rest on the frozen base")


def case_pile():
    # 7 x 7 grains on a square lattice with gaps of at least 0.02 (spacing 8/7 across, 1.12 up),
    # small random velocities: the lattice collapses into a disordered pile within t ~ 0.5.
    rng = random.Random(20240613)
    width, per_row, rows = 8, 7, 7
    p = []
    for row in range(rows):
        for col in range(per_row):
            r = 0.5 * rng.uniform(0.9, 1.1)
            x = (col + 0.5) * width / per_row
            y = 1.07 + 1.12 * row
            p.append(dict(type=GRAIN, x=x, y=y, r=r, vx=rng.uniform(-0.2, 0.2),
                          vy=rng.uniform(-0.5, -0.2), omega=rng.uniform(-1.0, 1.0)))
    p += base_row(width)
    return p, dict(width=width, ylo=-1.0, yhi=12.0, mu=0.1, steps=8000, every=100, every_local=100,
                   description="49 polydisperse grains (d in [0.9, 1.1]) collapsing from a loose lattice onto the frozen base")


def case_clump():
    # A disk-outline clump (rings of radius-0.25 atoms at 1.25 and 0.7 plus a centre atom, outer
    # diameter 3.0), pushed at constant vx = 2 into grains resting on the base; y free, no rotation.
    width = 20
    grains = []
    # A small hexagonal heap in front of the clump: 7, 6 and 5 grains on the base.
    for layer, n in enumerate([7, 6, 5]):
        for k in range(n):
            grains.append(dict(type=GRAIN, x=7.5 + 0.5 * layer + k, y=0.87 + 0.87 * layer,
                               r=0.495 + 0.002 * ((k + layer) % 3), vx=0.0, vy=0.0, omega=0.0))
    p = grains + base_row(width)
    xc, yc = 5.0, 2.3
    atoms = []
    for ring_r, n in [(1.25, 24), (0.7, 12)]:
        for i in range(n):
            a = 2.0 * math.pi * i / n
            atoms.append((ring_r * math.cos(a), ring_r * math.sin(a)))
    atoms.append((0.0, 0.0))
    clump_mass = 5.0
    atom_mass = clump_mass / len(atoms)
    for ox, oy in atoms:
        p.append(dict(type=CLUMP, x=xc + ox, y=yc + oy, r=0.25, vx=2.0, vy=0.0, omega=0.0,
                      mass=atom_mass))
    return p, dict(width=width, ylo=-1.0, yhi=12.0, mu=0.1, steps=10000, every=100, every_local=100,
                   clump=dict(x=xc, y=yc, vx=2.0, atom_radius=0.25),
                   description="disk clump at vx = 2 (y free, no rotation) pushing grains on the base")


def case_clump_atom_mass():
    # The clump case with the other coupling of a glued body (intruder.contact_mass = "atom"): no
    # fix rigid; fix move prescribes x and integrates y with each atom's own mass, and fix aveforce
    # gives every atom the group's mean y force (gravity included), so the clump moves as one with
    # its total mass while each contact's meff holds the atom's mass, M / 37.
    p, s = case_clump()
    return p, dict(s, coupling="atom",
                   description="disk clump at vx = 2 (y free, no rotation; fix move + fix aveforce, each atom's own "
                               "mass in meff) pushing grains on the base")


def with_law(case, law, style, keywords=""):
    """The same case under another law of wiggle (contact.law = law), with the same numbers: LAMMPS's
    pair_style gran/<style>/history with the keywords after its coefficients."""
    def law_case():
        p, s = case()
        pair_style = f"gran/{style}/history" + (f" {keywords}" if keywords else "")
        return p, dict(s, law=law, style=style, keywords=keywords,
                       description=s["description"] + "; " + pair_style)
    return law_case


CASES = {"oblique": case_oblique, "bounce": case_bounce, "pile": case_pile, "clump": case_clump,
         "clump_atom_mass": case_clump_atom_mass,
         "pile_hooke": with_law(case_pile, "hooke", "hooke"),
         "clump_hooke": with_law(case_clump, "hooke", "hooke"),
         "pile_hertz_limit_damping": with_law(case_pile, "hertz_limit_damping", "hertz", "limit_damping"),
         "clump_hertz_limit_damping": with_law(case_clump, "hertz_limit_damping", "hertz", "limit_damping")}

# --------------------------------------------------------------------------------------------


def write_data(path, particles, s):
    lines = ["wiggle LAMMPS reference case (generated by make_reference.py)", "",
             f"{len(particles)} atoms", "3 atom types", "",
             f"0 {s['width']} xlo xhi", f"{s['ylo']} {s['yhi']} ylo yhi", "-0.5 0.5 zlo zhi", "",
             "Atoms # sphere", ""]
    for i, q in enumerate(particles, start=1):
        # diameter = 2 r exactly, so LAMMPS's radius (0.5 * diameter) is r to the bit; density 1
        # gives the sphere mass 4/3 pi r^3 (clump atoms get their mass with `set` in the deck).
        lines.append(f"{i} {q['type']} {2.0 * q['r']!r} {DENSITY!r} {q['x']!r} {q['y']!r} 0.0")
    lines += ["", "Velocities", ""]
    for i, q in enumerate(particles, start=1):
        lines.append(f"{i} {q['vx']!r} {q['vy']!r} 0.0 0.0 0.0 {q['omega']!r}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_deck(path, name, particles, s):
    has_base = any(q["type"] == BASE for q in particles)
    has_clump = any(q["type"] == CLUMP for q in particles)
    d = [f"# wiggle LAMMPS reference case '{name}': {s['description']}",
         "# Generated by tools/lammps_reference/make_reference.py; run: lmp -in " + name + ".in",
         "units lj", "dimension 2", "atom_style sphere", "boundary p f p", "comm_modify vel yes",
         f"read_data {name}.data", "",
         f"group grains type {GRAIN}", f"group base type {BASE}", f"group clump type {CLUMP}"]
    if has_clump:
        clump_atoms = [q for q in particles if q["type"] == CLUMP]
        d.append(f"set group clump mass {clump_atoms[0]['mass']!r}")
        d.append(f"velocity clump set {s['clump']['vx']!r} 0 0")
    keywords = f" {s['keywords']}" if s.get("keywords") else ""
    d += ["", f"pair_style gran/{s.get('style', 'hertz')}/history {KN:g} {KT:g} {GAMMA_N:g} {GAMMA_T:g} {s['mu']!r} 1"
              f"{keywords}",
          "pair_coeff * *", "neighbor 0.2 bin", "neigh_modify delay 0 every 1 check yes"]
    excl = []
    if has_base:
        excl.append("exclude type 2 2")  # frozen-frozen pairs: no effect on motion, keep them out
    if has_clump:
        excl.append("exclude type 3 3")  # clump atoms do not interact with each other (docs/PHYSICS.md §6)
    if excl:
        d.append("neigh_modify " + " ".join(excl))
    d += [f"timestep {DT!r}", "",
          "fix integrate grains nve/sphere",
          f"fix grav all gravity {GRAVITY!r} vector 0 -1 0"]
    if has_base:
        d.append("fix hold base freeze")
    if has_clump and s.get("coupling") == "atom":
        # x prescribed, y integrated by fix move with each atom's own mass; every atom gets the
        # group's mean y force (contacts and gravity), so all move alike, as one body of mass M.
        d.append(f"fix drive clump move linear {s['clump']['vx']!r} NULL NULL")
        d.append("fix share clump aveforce NULL 0.0 NULL")
    elif has_clump:
        # x momentum held (vx stays 3), y free, no rotation; the pair style then uses the body mass
        # in meff (PairGranHertzHistory reads mass_rigid from this fix).
        d.append("fix rig clump rigid single force * off on off torque * off off off")
    d += ["fix flat all enforce2d", "",
          "compute pl all pair/local dist force p1 p2 p3 p4 cutoff radius",
          "compute pp all property/local patom1 patom2 cutoff radius",
          "write_dump all custom init.dump id type mass radius x y vx vy omegaz "
          "modify format float %.17g sort id",
          "group moving union grains clump",
          f"dump state moving custom {s['every']} state.dump id x y vx vy omegaz fx fy tqz",
          "dump_modify state format float %.17g sort id",
          f"dump contacts all local {s['every_local']} contacts.dump c_pp[1] c_pp[2] c_pl[1] c_pl[2] "
          "c_pl[3] c_pl[4] c_pl[6]",
          "dump_modify contacts format float %.17g",
          "thermo 1000", "thermo_modify lost error",
          f"run {s['steps']}"]
    with open(path, "w") as f:
        f.write("\n".join(d) + "\n")


def read_frames(path):
    """Yields (step, column names, rows) of a LAMMPS text dump (custom or local)."""
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        assert lines[i].startswith("ITEM: TIMESTEP"), lines[i]
        step = int(lines[i + 1])
        n = int(lines[i + 3])
        header = lines[i + 8].split()[2:]
        rows = [lines[i + 9 + k].split() for k in range(n)]
        yield step, header, rows
        i += 9 + n


def run_case(name, version):
    particles, s = CASES[name]()
    os.makedirs(DECKS, exist_ok=True)
    data_path = os.path.join(DECKS, name + ".data")
    deck_path = os.path.join(DECKS, name + ".in")
    write_data(data_path, particles, s)
    write_deck(deck_path, name, particles, s)
    with tempfile.TemporaryDirectory() as tmp:
        for p in (data_path, deck_path):
            with open(p) as src, open(os.path.join(tmp, os.path.basename(p)), "w") as dst:
                dst.write(src.read())
        r = subprocess.run(["lmp", "-in", name + ".in", "-log", "log.lammps", "-screen", "none"],
                           cwd=tmp, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"lmp failed on case {name}:\n{open(os.path.join(tmp, 'log.lammps')).read()[-3000:]}")
        init = list(read_frames(os.path.join(tmp, "init.dump")))[0]
        state = list(read_frames(os.path.join(tmp, "state.dump")))
        contacts = {st: (h, rows) for st, h, rows in read_frames(os.path.join(tmp, "contacts.dump"))}

    _, h, rows = init
    col = {c: k for k, c in enumerate(h)}
    out_particles = []
    for row in rows:
        t = int(row[col["type"]])
        out_particles.append(dict(id=int(row[col["id"]]),
                                  kind={GRAIN: "grain", BASE: "frozen", CLUMP: "clump"}[t],
                                  **{k: float(row[col[c]]) for k, c in
                                     [("mass", "mass"), ("radius", "radius"), ("x", "x"), ("y", "y"),
                                      ("vx", "vx"), ("vy", "vy"), ("omega", "omegaz")]}))
    frames = []
    for step, h, rows in state:
        if step == 0:
            continue  # the initial state is in "particles"; forces at step 0 are setup forces
        cols = {c: [float(r[k]) if c != "id" else int(r[k]) for r in rows] for k, c in enumerate(h)}
        frame = dict(step=step, atoms=dict(id=cols["id"], x=cols["x"], y=cols["y"], vx=cols["vx"],
                                           vy=cols["vy"], omega=cols["omegaz"], fx=cols["fx"],
                                           fy=cols["fy"], torque=cols["tqz"]))
        if step in contacts:
            ch, crow = contacts[step]
            names = ["id1", "id2", "dist", "fn", "fs1", "fs2", "fs"]
            frame["contacts"] = {n: [int(r[k]) if k < 2 else float(r[k]) for r in crow]
                                 for k, n in enumerate(names)}
        frames.append(frame)

    clump = None
    if "clump" in s:
        catoms = [q for q in out_particles if q["kind"] == "clump"]
        clump = dict(center_x=s["clump"]["x"], center_y=s["clump"]["y"], vx=s["clump"]["vx"],
                     atom_radius=s["clump"]["atom_radius"],
                     mass=math.fsum(q["mass"] for q in catoms),
                     mass_shares=len(catoms) if s.get("coupling") == "atom" else 1)
    case = dict(name=name, description=s["description"], lammps_version=version,
                box_width=float(s["width"]), dt=DT, gravity=GRAVITY, density=DENSITY,
                mass_model="sphere",
                contact=dict(kn=KN, kt=KT, gamma_n=GAMMA_N, gamma_t=GAMMA_T, mu=s["mu"], law=s.get("law", "hertz")),
                steps=s["steps"], particles=out_particles, clump=clump, frames=frames,
                deck=open(deck_path).read(), data_file=open(data_path).read())
    path = os.path.join(OUT, name + ".json")
    os.makedirs(OUT, exist_ok=True)
    with open(path, "w") as f:
        json.dump(case, f, separators=(",", ":"))
    ncont = sum(len(fr.get("contacts", {}).get("id1", [])) for fr in frames)
    print(f"{name}: {len(out_particles)} particles, {len(frames)} frames, {ncont} contact rows, "
          f"{os.path.getsize(path) / 1e6:.2f} MB -> {os.path.relpath(path, ROOT)}")


def main():
    names = sys.argv[1:] or list(CASES)
    version = lammps_version()
    for n in names:
        if n not in CASES:
            sys.exit(f"unknown case {n}; known: {', '.join(CASES)}")
        run_case(n, version)


if __name__ == "__main__":
    main()
