"""``python -m rigidsym``."""

import sys

from rigidsym.cli import main

sys.exit(main())
