"""`python3 -m flexure_plot FILE.h5 [--out FIG.png] [--animate A.gif]` (what `flexure plot` runs)."""
import sys

from . import main

sys.exit(main())
