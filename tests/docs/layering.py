#!/usr/bin/python3
"""The library's floors (ARCHITECTURE.md, "Floors"): a file may include its own folder and the
folders on floors below it, never a folder above; and no units include each other in a circle,
within a folder or across (a unit is a source with its header: Case.h and Case.cpp). Exits 1
naming each include that points up and each circle.

    layering.py [SOURCE_ROOT]

It first plants a circle in a small tree of its own and fails if that circle goes unseen, so a
check that quietly stopped looking cannot pass.
"""
import os
import re
import sys
import tempfile

# Lowest first; folders on one floor do not include each other.
FLOORS = [["core"], ["physics"], ["io"], ["analysis", "model"], ["scenario"], ["sweep"]]
FLOOR = {folder: level for level, folders in enumerate(FLOORS) for folder in folders}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z]+)/', re.M)
# Rooms inside a folder, lowest first, on the same rule: a file of one room includes its own room
# and the rooms below it. Every file of such a folder stands in one of its rooms.
ROOMS = {"scenario": [["geometry"], ["case"], ["lammps"], ["bed"], ["cost"], ["run"]]}
ROOM_INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z]+)/([a-z]+)/', re.M)
# Any include of a file of the library: "folder/Name.h" or "folder/sub/Name.h".
UNIT_INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z]+(?:/[A-Za-z]+)*/[A-Za-z0-9_]+)\.h"', re.M)


def source_files(src):
    """(path relative to src, text) of every file under src."""
    for folder, _, names in sorted(os.walk(src)):
        for name in sorted(names):
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8") as f:
                yield os.path.relpath(path, src).replace(os.sep, "/"), f.read()


def floor_problems(src):
    found = []
    for folder in sorted(os.listdir(src)):
        if folder not in FLOOR:
            found.append(f"src/{folder}: a folder ARCHITECTURE.md's floors do not name (add it to tests/docs/layering.py)")
    for rel, text in source_files(src):
        folder = rel.split("/")[0]
        if folder not in FLOOR:
            continue
        for target in INCLUDE.findall(text):
            if target == folder or target not in FLOOR:
                continue
            if FLOOR[target] >= FLOOR[folder]:
                found.append(f"src/{rel} includes {target}/: floor {FLOOR[target]} from floor {FLOOR[folder]}")
        found += room_problems(rel, text)
    return found


def room_problems(rel, text):
    """The rooms' rule for one file (src/FOLDER/ROOM/NAME)."""
    parts = rel.split("/")
    if parts[0] not in ROOMS:
        return []
    level = {room: i for i, rooms in enumerate(ROOMS[parts[0]]) for room in rooms}
    if len(parts) != 3 or parts[1] not in level:
        return [f"src/{rel}: not in one of src/{parts[0]}'s rooms (tests/docs/layering.py names them)"]
    found = []
    for folder, target in ROOM_INCLUDE.findall(text):
        if folder != parts[0] or target == parts[1]:
            continue
        if target not in level:
            found.append(f"src/{rel} includes {folder}/{target}/: a room tests/docs/layering.py does not name")
        elif level[target] >= level[parts[1]]:
            found.append(f"src/{rel} includes {folder}/{target}/: room floor {level[target]} from {level[parts[1]]}")
    return found


def unit_circles(src):
    """Every circle of units that include each other (a strongly connected set of more than one
    unit), each as its units in order, named by their paths without the extension."""
    edges = {}
    for rel, text in source_files(src):
        unit = os.path.splitext(rel)[0]
        targets = edges.setdefault(unit, set())
        for target in UNIT_INCLUDE.findall(text):
            if target != unit and os.path.exists(os.path.join(src, target + ".h")):
                targets.add(target)
    # Tarjan's strongly connected components, iterative so that a deep tree needs no deep stack.
    index, low, on_stack, stack, circles = {}, {}, set(), [], []
    for root in sorted(edges):
        if root in index:
            continue
        work = [(root, iter(sorted(edges.get(root, ()))))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            unit, targets = work[-1]
            target = next(targets, None)
            if target is not None:
                if target not in index:
                    index[target] = low[target] = len(index)
                    stack.append(target)
                    on_stack.add(target)
                    work.append((target, iter(sorted(edges.get(target, ())))))
                elif target in on_stack:
                    low[unit] = min(low[unit], index[target])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[unit])
            if low[unit] == index[unit]:
                members = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    members.append(member)
                    if member == unit:
                        break
                if len(members) > 1:
                    circles.append(sorted(members))
    return circles


def problems(root):
    src = os.path.join(root, "src")
    found = floor_problems(src)
    for circle in unit_circles(src):
        found.append("units that include each other in a circle: " + " <-> ".join(f"src/{u}" for u in circle))
    return found


def self_test():
    """A planted circle inside one folder (A.cpp includes B.h, B.cpp includes A.h) must be found,
    the same tree without it must pass, and a planted include up the scenario rooms must be found."""
    with tempfile.TemporaryDirectory() as root:
        folder = os.path.join(root, "src", "sweep")
        os.makedirs(folder)
        files = {"A.h": "", "B.h": "", "C.h": '#include "sweep/A.h"\n',
                 "A.cpp": '#include "sweep/A.h"\n#include "sweep/B.h"\n',
                 "B.cpp": '#include "sweep/B.h"\n#include "sweep/A.h"\n'}
        for name, text in files.items():
            with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
                f.write(text)
        caught = problems(root)
        if caught != ["units that include each other in a circle: src/sweep/A <-> src/sweep/B"]:
            return [f"self-test: a planted circle between sweep/A and sweep/B was not reported as one: {caught}"]
        with open(os.path.join(folder, "B.cpp"), "w", encoding="utf-8") as f:
            f.write('#include "sweep/B.h"\n')
        if problems(root):
            return [f"self-test: the tree without its circle was not clean: {problems(root)}"]
        # A room that includes one above it (geometry -> run) is named too.
        for room, name, text in (("geometry", "G.h", '#include "scenario/run/R.h"\n'), ("run", "R.h", "")):
            os.makedirs(os.path.join(root, "src", "scenario", room), exist_ok=True)
            with open(os.path.join(root, "src", "scenario", room, name), "w", encoding="utf-8") as f:
                f.write(text)
        if problems(root) != ["src/scenario/geometry/G.h includes scenario/run/: room floor 5 from 0"]:
            return [f"self-test: a planted include up the scenario rooms was not reported as one: {problems(root)}"]
    return []


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    found = self_test() + problems(root)
    for p in found:
        print(p)
    print(f"layering: {len(found)} includes against the floors or in circles")
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
