"""ctest entry of the Python suite: pytest on python/tests, or exit 77 (ctest: skipped) with the
reason when pytest is missing. Usage: run_pytest.py SCRATCH_DIR (PYTHONPATH: the build's python/)."""
import os
import sys

try:
    import pytest
except ImportError:
    print("SKIPPED: pytest is not installed (Debian: apt-get install python3-pytest)")
    sys.exit(77)

here = os.path.dirname(os.path.abspath(__file__))
sys.exit(pytest.main([here, "-q", "-p", "no:cacheprovider", "--basetemp", sys.argv[1]]))
