import sys
from pathlib import Path

import roboscript  # noqa: F401  (chooses MuJoCo's GL backend before a test module imports MuJoCo)

# Test helpers live next to the tests.
sys.path.insert(0, str(Path(__file__).parent))
