"""``python -m birdsim ...``: the same command line as the ``birdsim`` script."""

import sys

from birdsim.cli import main

sys.exit(main())
