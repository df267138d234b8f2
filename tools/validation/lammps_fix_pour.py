#!/usr/bin/python3
"""A bed poured by LAMMPS's own fix pour, the way wiggle's bed.pour = "random" pours, for comparison.

    tools/validation/lammps_fix_pour.py --out DIR [--seed 1] [--width 60] [--bed-height 50] [--y0 25]
                                        [--shape disk] [--fraction 0.3] [--speed 1] [--batch 20]
                                        [--settle 30] [--relax 20] [--level highest|row] [--surface smooth|glued]
                                        [--wiggle BIN] [--lmp lmp]

Writes DIR/in.pour and runs it with `lmp`: a 2D box periodic in x, the frozen base row and the held
intruder's atoms, the contact law of configs/small.toml, and then,
batch after batch, a `fix pour` into a band from one d_max above the highest grain up by --batch,
filled to the area fraction --fraction, grains thrown down at --speed (fix pour adds the speed of a
fall from the band's top, as wiggle's random pour does), each batch followed by --settle time
units; once the surface passes --bed-height the grains above it are deleted (as wiggle levels a
bed) and the bed relaxes for --relax time units. "Passes" is, with --level highest (the default,
the rule of the committed pour_protocol_small decks), the highest grain above --bed-height, which a
single grain thrown up can satisfy early (that study's seed 2 stopped 5 d low); with --level row,
a quarter of a row of grains (width / 4 centres) above it, which only the bulk reaches.
The intruder's atoms are wiggle's clump for --shape: with --surface smooth (the default, the
committed beds' clump) the shell of `wiggle model --geometry`; with --surface glued the touching
atoms of intruder.surface = "glued", which `wiggle model` does not write: the script exports a
bed of the base row and one grain with `wiggle export-lammps --set intruder.surface=glued` and
takes the clump's atoms (type 3) from that data file, so they are the atoms wiggle places.
DIR/dump.lammpstrj holds the bed at the end (the format wiggle's dumps have): compare it with
wiggle's beds by study/tools/bed_statistics.py --dump. DIR/data.lammps is the same bed as a
data file (write_data): `wiggle run --set bed.file=DIR/data.lammps` runs it (types 1 grains, 2 base,
3 the intruder's atoms, which wiggle replaces by its own intruder: bed.lammps_types' default).
--drive DECK continues the same LAMMPS session with the drive of DECK (an in.wiggle that
`wiggle export-lammps --set bed.file=DIR/data.lammps` wrote for this bed), so that the drive
starts with the contact history the pour built, which a data file cannot carry: DECK's lines but
those that set up the box, read the data or define the pair style (a new pair style would drop the
history), after the pour's dump, hold and gravity are removed and the clock is reset to 0. Differences from wiggle that remain: fix pour's own random numbers (not wiggle's stream),
its placement that rejects only overlaps with grains near the band, fixed settle and relax times
instead of wiggle's speed and energy thresholds, and fix pour's heights: it draws each grain's height
as top - u^2 (top - bottom), crowding the top of the band, and stops a batch when its attempts (100
per grain, pooled) run out, while wiggle draws heights uniformly.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def deck(args, atoms):
    # fix pour counts a band's grains as vol x area / (pi r_max^2); wiggle fills the area fraction with
    # the grains' real areas. So fix pour gets the vol that gives wiggle's count, and that count as
    # its total, which it then inserts in one go (its nper).
    mean_area = math.pi / 4 * (0.9 ** 2 + 0.9 * 1.1 + 1.1 ** 2) / 3
    vol = args.fraction * math.pi * 0.55 ** 2 / mean_area
    per_batch = int(vol * args.width * args.batch / (math.pi * 0.55 ** 2))
    steps = lambda t: int(round(t / 1e-4))  # noqa: E731
    top = args.bed_height + 3 * args.batch + 10  # the box's starting top; fm lets it grow
    lines = [
        f"# LAMMPS fix pour bed (tools/validation/lammps_fix_pour.py): W = {args.width}, surface {args.bed_height}, "
        f"{args.shape} at y0 = {args.y0}, seed {args.seed}" + (", glued clump" if args.surface == "glued" else ""),
        "dimension 2", "atom_style sphere", "boundary p fm p", "comm_modify vel yes", "processors * 1 1",
        f"region box block 0 {args.width} -1 {top} -0.5 0.5", "create_box 3 box",
    ]
    lines += [f"create_atoms 2 single {i + 0.5} 0 0" for i in range(int(args.width))]
    cx = 0.5 * args.width
    lines += [f"create_atoms 3 single {cx + x:.12g} {args.y0 + y:.12g} 0" for x, y in atoms]
    lines += [
        "set type 2 diameter 1.0", "set type 3 diameter 0.5", "set type 2*3 density 1.0",
        "group base type 2", "group intruder type 3", "group held union base intruder", "group grains type 1",
        "pair_style gran/hertz/history 2000000 2460000 2500 2500 0.1 1", "pair_coeff * *",
        "neighbor 0.2 bin", "neigh_modify delay 0 every 1 check yes exclude type 2 2 exclude type 3 3 exclude type 2 3",
        "timestep 0.0001", "fix hold held freeze", "fix integrate grains nve/sphere",
        "fix fall grains gravity 1.0 vector 0 -1 0", "fix flat all enforce2d",
        "compute ke grains ke", "thermo_style custom step time atoms c_ke", "thermo 100000",
        # batch loop: the band starts one d_max above the highest grain (the base's top before any)
        "variable batch loop 1000",
        *([f"region high block INF INF {args.bed_height} INF INF INF units box"] if args.level == "row" else []),
        "label pour",
        "variable n equal count(grains)",
        "if \"${n} > 0\" then \"variable ytop equal bound(grains,ymax)+0.55\" else \"variable ytop equal 0.5\"",
        "variable ylo equal ${ytop}+1.1",
        f"variable yhi equal ${{ylo}}+{args.batch}",
        "region band${batch} block 0 %g ${ylo} ${yhi} -0.5 0.5 units box" % args.width,
        f"fix ins${{batch}} grains pour {per_batch} 1 {args.seed * 1000 + 7}${{batch}} region band${{batch}} "
        f"diam range 0.9 1.1 dens 1.0 1.0 vol {vol:.12g} 100 vel 0 0 -{args.speed}",
        f"run {steps(args.settle)}",
        "unfix ins${batch}",
        "variable surface equal bound(grains,ymax)" if args.level == "highest"
        else f"variable surface equal {args.bed_height}+count(grains,high)-{args.width / 4:g}",
        f"if \"${{surface}} < {args.bed_height}\" then \"next batch\" \"jump SELF pour\"",
        f"region above block INF INF {args.bed_height} INF INF INF units box",
        "group topgrains region above", "group levelled intersect topgrains grains",
        "delete_atoms group levelled",
        f"run {steps(args.relax)}",
        "dump bed all custom 1 dump.lammpstrj id type x y z radius vx vy", "dump_modify bed sort id",
        "run 0",
        "write_data data.lammps",
    ]
    if args.drive:
        setup = ("units", "dimension", "atom_style", "boundary", "processors", "comm_modify", "read_data",
                 "pair_style", "pair_coeff")
        with open(args.drive) as f:
            drive = [line.rstrip("\n") for line in f if not line.startswith(setup + ("# Contact history",))]
        lines += ["# the drive of " + args.drive + ", with the pour's contact history",
                  "undump bed", "unfix hold", "unfix fall", "reset_timestep 0"] + drive
    return "\n".join(lines) + "\n"


def shell_atoms(args, out):
    """The smooth shell's atoms relative to the clump's centre, from `wiggle model --geometry`."""
    geometry = os.path.join(out, "geometry.json")
    subprocess.run([args.wiggle, "model", "--shape", args.shape, "--geometry", geometry], check=True,
                   stdout=subprocess.DEVNULL)
    with open(geometry) as f:
        return json.load(f)["atoms"]


def glued_atoms(args):
    """The glued clump's atoms relative to the clump's centre (W / 2, y0), as wiggle places them: read
    from the data file `wiggle export-lammps` writes for a bed of the base row and one grain."""
    with tempfile.TemporaryDirectory() as tmp:
        bed = os.path.join(tmp, "base.data")
        n = int(args.width)
        lines = ["base row and one grain, for the clump's atoms (lammps_fix_pour.py)", "", f"{n + 1} atoms",
                 "3 atom types", "", f"0 {args.width:.12g} xlo xhi", f"-1 {args.bed_height + 10:.12g} ylo yhi",
                 "-0.5 0.5 zlo zhi", "", "Atoms # sphere", ""]
        lines += [f"{i + 1} 2 1 1 {i + 0.5} 0 0" for i in range(n)]
        lines += [f"{n + 1} 1 1 1 0.5 1.5 0"]
        with open(bed, "w") as f:
            f.write("\n".join(lines) + "\n")
        export = os.path.join(tmp, "export")
        subprocess.run([args.wiggle, "export-lammps", "--set", f"box.width={args.width:.12g}",
                        "--set", f"box.bed_height={args.bed_height:.12g}", "--set", f"intruder.y0={args.y0:.12g}",
                        "--set", f"intruder.shape={args.shape}", "--set", "intruder.surface=glued",
                        "--set", f"bed.file={bed}", "--threads", "1", "--out", export],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        atoms, section = [], False
        with open(os.path.join(export, "data.lammps")) as f:
            for line in f:  # the Atoms section's lines: id type diameter density x y z ...
                if line[:1].isalpha():
                    section = line.startswith("Atoms")
                elif section and len(line.split()) >= 7 and line.split()[1] == "3":
                    x, y = map(float, line.split()[4:6])
                    atoms.append((x - 0.5 * args.width, y - args.y0))
    if not atoms:
        sys.exit("no intruder atoms in the export's data file")
    return atoms


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", required=True)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--width", type=float, default=60.0)
    p.add_argument("--bed-height", type=float, default=50.0)
    p.add_argument("--y0", type=float, default=25.0)
    p.add_argument("--shape", default="disk")
    p.add_argument("--fraction", type=float, default=0.3)
    p.add_argument("--speed", type=float, default=1.0)
    p.add_argument("--batch", type=float, default=20.0)
    p.add_argument("--settle", type=float, default=30.0, help="time units after each batch")
    p.add_argument("--relax", type=float, default=20.0, help="time units after levelling")
    p.add_argument("--level", choices=["highest", "row"], default="highest",
                   help="when the pour stops: the highest grain, or a quarter row of grains, above --bed-height")
    p.add_argument("--surface", choices=["smooth", "glued"], default="smooth",
                   help="the intruder's atoms: wiggle's smooth shell (default) or its glued clump (touching atoms)")
    p.add_argument("--drive", help="an exported in.wiggle of this bed: run its drive after the pour, history kept")
    p.add_argument("--wiggle", default=os.path.join(ROOT, "build", "release", "wiggle"))
    p.add_argument("--lmp", default="lmp")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    atoms = glued_atoms(args) if args.surface == "glued" else shell_atoms(args, args.out)
    with open(os.path.join(args.out, "in.pour"), "w") as f:
        f.write(deck(args, atoms))
    result = subprocess.run([args.lmp, "-in", "in.pour", "-log", "log.lammps", "-screen", "none"], cwd=args.out)
    if result.returncode != 0:
        sys.exit(f"lmp failed: see {os.path.join(args.out, 'log.lammps')}")
    print("bed:", os.path.join(args.out, "dump.lammpstrj"))


if __name__ == "__main__":
    main()
