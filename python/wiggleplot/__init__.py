"""wiggleplot: figures for wiggle's run and sweep directories.

Python draws, C++ computes: this package only reads the files that `wiggle run`, `wiggle sweep`
and `wiggle model` write (docs/OUTPUT-FORMATS.md) and never re-derives physics. Modules:

- readers:   file readers (one function per file format), numpy arrays out
- prepare:   the arrays behind each figure (aggregation over seeds, T_rising, field grids, masks)
- style:     one matplotlib style for every figure and the saver (PNG + PDF)
- runplots:  figures of one run directory (paper figs 2, 3-4, 8, 9-11, movie)
- sweepplots: figures of a sweep directory (paper figs 2, 5, 6, 8, 14, Table 1)
- geomplots: the intruder geometry figure (paper fig 13)
- cli:       `python3 -m wiggleplot DIR` / `--geometry a.json ... --out DIR`
"""

__version__ = "0.1.0"
