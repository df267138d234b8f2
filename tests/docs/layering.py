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
    """A planted circle inside one folder (a.cpp includes b.h, b.cpp includes a.h) must be found,
    and the same tree without it must pass."""
    with tempfile.TemporaryDirectory() as root:
        folder = os.path.join(root, "src", "scenario")
        os.makedirs(folder)
        files = {"A.h": "", "B.h": "", "C.h": '#include "scenario/A.h"\n',
                 "A.cpp": '#include "scenario/A.h"\n#include "scenario/B.h"\n',
                 "B.cpp": '#include "scenario/B.h"\n#include "scenario/A.h"\n'}
        for name, text in files.items():
            with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
                f.write(text)
        caught = problems(root)
        if caught != ["units that include each other in a circle: src/scenario/A <-> src/scenario/B"]:
            return [f"self-test: a planted circle between scenario/A and scenario/B was not reported as one: {caught}"]
        with open(os.path.join(folder, "B.cpp"), "w", encoding="utf-8") as f:
            f.write('#include "scenario/B.h"\n')
        if problems(root):
            return [f"self-test: the tree without its circle was not clean: {problems(root)}"]
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
