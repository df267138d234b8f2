#!/usr/bin/python3
"""The library's floors (ARCHITECTURE.md, "Floors"): a file may include its own folder and the
folders on floors below it, never a folder above. Exits 1 naming each include that points up.

    layering.py [SOURCE_ROOT]
"""
import os
import re
import sys

# Lowest first; folders on one floor do not include each other.
FLOORS = [["core"], ["physics"], ["io"], ["analysis", "model"], ["scenario"], ["sweep"]]
FLOOR = {folder: level for level, folders in enumerate(FLOORS) for folder in folders}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z]+)/', re.M)


def problems(root):
    found = []
    src = os.path.join(root, "src")
    for folder in sorted(os.listdir(src)):
        if folder not in FLOOR:
            found.append(f"src/{folder}: a folder ARCHITECTURE.md's floors do not name (add it to tests/docs/layering.py)")
            continue
        for name in sorted(os.listdir(os.path.join(src, folder))):
            with open(os.path.join(src, folder, name), encoding="utf-8") as f:
                for target in INCLUDE.findall(f.read()):
                    if target == folder or target not in FLOOR:
                        continue
                    if FLOOR[target] >= FLOOR[folder]:
                        found.append(f"src/{folder}/{name} includes {target}/: floor {FLOOR[target]} from floor {FLOOR[folder]}")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    found = problems(root)
    for p in found:
        print(p)
    print(f"layering: {len(found)} includes against the floors")
    sys.exit(1 if found else 0)


if __name__ == "__main__":
    main()
