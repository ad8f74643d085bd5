"""``python -m roboscript.cli``: the ``roboscript`` command."""

import sys

from roboscript.cli.main import main

sys.exit(main())
