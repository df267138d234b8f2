"""`python3 -m wiggleplot DIR [--format png,pdf] [--movie]`; see wiggleplot.cli."""
import sys

from wiggleplot.cli import main

sys.exit(main())
